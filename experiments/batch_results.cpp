// The reading half of batch.h: a batch's results files back as records, and its search trials as table rows
// (`toponav report`).
#include "experiments/batch.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "experiments/results_io.h"

namespace toponav::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A record with every key a report needs, of the right type; nullopt (and 'why') otherwise.
std::optional<TrialRecord> ParseRecord(const std::string& line, std::string* why) {
  try {
    const json j = json::parse(line);
    TrialRecord r;
    const auto kind = core::ParseWorldKind(j.at("kind").get<std::string>());
    if (!kind) {
      *why = "unknown kind";
      return std::nullopt;
    }
    r.id = {*kind, j.at("agents").get<int>(), j.at("seed").get<uint64_t>(), j.value("planner", std::string())};
    if (j.at("id").get<std::string>() != r.id.Key()) {
      *why = "its id does not match its kind, agents and seed";
      return std::nullopt;
    }
    r.ok = j.at("ok").get<bool>();
    if (!r.ok) {
      r.error = j.at("error").get<std::string>();
      r.signal = j.value("signal", 0);
      return r;
    }
    r.success = j.at("success").get<bool>();
    r.explored = j.at("explored").get<bool>();
    r.steps = j.at("steps").get<int>();
    r.iou = j.at("iou").get<double>();
    r.distance = j.at("distance").get<double>();
    r.shortest = j.value("shortest", 0.0);
    r.wall_time_s = j.at("wall_time_s").get<double>();
    r.end_reason = j.at("end_reason").get<std::string>();
    r.sensors = j.value("sensors", "");
    r.privileged = j.value("privileged", "none") != "none";
    return r;
  } catch (const json::exception& e) {
    *why = line.empty() || line.back() != '}' ? "a partial line (a run killed while writing it?)" : e.what();
    return std::nullopt;
  }
}

}  // namespace

std::vector<TrialRecord> ReadResults(const std::vector<std::string>& dirs, std::vector<std::string>* skipped) {
  std::map<std::string, TrialRecord> by_key;  // the last record of a trial wins (a retry after a signal)
  for (const auto& dir : dirs) {
    if (!fs::is_directory(dir)) throw core::DataError(dir, "not a directory");
    for (const auto& f : BatchResultsFiles(dir)) {
      std::ifstream in(f);
      std::string line, why;
      for (int n = 1; std::getline(in, line); ++n) {
        if (line.empty()) continue;
        if (auto r = ParseRecord(line, &why)) by_key[r->id.Key()] = *r;
        else if (skipped) skipped->push_back(f.string() + ":" + std::to_string(n) + ": skipped: " + why);
      }
    }
  }
  std::vector<TrialRecord> out;
  for (auto& [k, r] : by_key) out.push_back(r);
  return out;
}

void CheckOneBatch(const std::vector<std::string>& dirs) {
  for (size_t i = 1; i < dirs.size(); ++i) {
    const std::string a = ReadStamp(dirs[0]), b = ReadStamp(dirs[i]);
    if (a != b)
      throw core::DataError(dirs[i], "its trials come from another build, config or trial set than " + dirs[0] +
                                         "'s (stamp " + (b.empty() ? "none" : b) + " against " +
                                         (a.empty() ? "none" : a) + "): report them separately");
  }
}

std::vector<ReportRow> Summarize(const std::vector<TrialRecord>& records) {
  std::map<std::pair<int, int>, ReportRow> rows;
  for (const auto& r : records) {
    if (!r.id.planner.empty()) continue;  // navigation trials: navigation_report.h
    ReportRow& row = rows[{int(r.id.kind), r.id.agents}];
    row.kind = r.id.kind;
    row.agents = r.id.agents;
    ++row.trials;
    if (!r.ok) {
      ++row.failed;
      continue;
    }
    row.successes += r.success;
    row.mean_steps += r.steps;
    row.mean_iou += r.iou;
    row.mean_wall_s += r.wall_time_s;
    row.ms_per_step += r.wall_time_s;  // divided by the steps below
  }
  std::vector<ReportRow> out;
  for (auto& [k, row] : rows) {
    const int ok = row.trials - row.failed;
    if (ok > 0) {
      if (row.mean_steps > 0) row.ms_per_step = 1000.0 * row.ms_per_step / row.mean_steps;
      row.mean_steps /= ok;
      row.mean_iou /= ok;
      row.mean_wall_s /= ok;
    }
    out.push_back(row);
  }
  return out;
}

std::string MarkdownTable(const std::vector<ReportRow>& rows) {
  std::ostringstream os;
  os << "| environment | agents | success | mean steps | mean IoU | failed runs | s/trial | ms/step |\n";
  os << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "| %s | %d | %d/%d | %.1f | %.4f | %d | %.1f | %.1f |\n", core::ToString(r.kind),
                  r.agents, r.successes, r.trials, r.mean_steps, r.mean_iou, r.failed, r.mean_wall_s, r.ms_per_step);
    os << buf;
  }
  return os.str();
}

std::string CsvTable(const std::vector<ReportRow>& rows) {
  std::ostringstream os;
  os << "environment,agents,trials,successes,mean_steps,mean_iou,failed,mean_wall_s,ms_per_step\n";
  for (const auto& r : rows)
    os << core::ToString(r.kind) << "," << r.agents << "," << r.trials << "," << r.successes << "," << r.mean_steps
       << "," << r.mean_iou << "," << r.failed << "," << r.mean_wall_s << "," << r.ms_per_step << "\n";
  return os.str();
}

}  // namespace toponav::experiments
