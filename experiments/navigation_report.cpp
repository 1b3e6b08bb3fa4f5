#include "experiments/navigation_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "core/error.h"
#include "experiments/internal/picture_io.h"

namespace toponav::experiments {

namespace {

constexpr const char* kBaseline = "optimistic";
const double kNaN = std::numeric_limits<double>::quiet_NaN();

using Key = std::pair<int, std::string>;  // kind, planner; the baseline sorts first
Key RowKey(const TrialRecord& r) { return {int(r.id.kind), r.id.planner == kBaseline ? "" : r.id.planner}; }

// Seed -> cost of the finished trials of (kind, planner).
std::map<uint64_t, double> Costs(const std::vector<TrialRecord>& records, int kind, const std::string& planner) {
  std::map<uint64_t, double> out;
  for (const auto& r : records)
    if (r.ok && int(r.id.kind) == kind && r.id.planner == planner) out[r.id.seed] = r.distance;
  return out;
}

void SetReduction(const std::vector<TrialRecord>& records, NavigationReportRow* row) {
  row->reduction = row->median_ratio = kNaN;
  if (row->planner == kBaseline) return;
  const auto base = Costs(records, int(row->kind), kBaseline), mine = Costs(records, int(row->kind), row->planner);
  double b = 0, m = 0;
  std::vector<double> ratios;
  for (const auto& [seed, cost] : mine) {
    const auto it = base.find(seed);
    if (it == base.end()) continue;
    b += it->second;
    m += cost;
    ++row->paired;
    if (it->second > 0) ratios.push_back(cost / it->second);
  }
  if (row->paired > 0 && b > 0) row->reduction = (b - m) / b;
  if (!ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    const size_t h = ratios.size() / 2;
    row->median_ratio = ratios.size() % 2 ? ratios[h] : 0.5 * (ratios[h - 1] + ratios[h]);
  }
}

// Adds what trial 'r' had to go on to its row's inputs, once.
void AddInputs(const TrialRecord& r, NavigationReportRow* row) {
  if (!r.ok) return;
  const std::string inputs = (r.sensors.empty() ? "?" : r.sensors) + (r.privileged ? " + true world" : "");
  if (row->inputs.empty()) row->inputs = inputs;
  else if (("; " + row->inputs + "; ").find("; " + inputs + "; ") == std::string::npos) row->inputs += "; " + inputs;
}

}  // namespace

std::vector<NavigationReportRow> SummarizeNavigation(const std::vector<TrialRecord>& records) {
  std::map<Key, NavigationReportRow> rows;
  std::map<Key, std::pair<double, double>> detours;  // reached trials with a shortest way: cost, shortest
  for (const auto& r : records) {
    if (r.id.planner.empty()) continue;
    NavigationReportRow& row = rows[RowKey(r)];
    row.kind = r.id.kind;
    row.planner = r.id.planner;
    AddInputs(r, &row);
    ++row.trials;
    if (!r.ok) {
      ++row.failed;
      continue;
    }
    row.reached += r.success;
    row.total_cost += r.distance;
    row.mean_steps += r.steps;
    row.mean_iou += r.iou;
    row.mean_wall_s += r.wall_time_s;
    if (r.success && r.shortest > 0) {
      detours[RowKey(r)].first += r.distance;
      detours[RowKey(r)].second += r.shortest;
    }
  }
  std::vector<NavigationReportRow> out;
  for (auto& [k, row] : rows) {
    const int ok = row.trials - row.failed;
    if (ok > 0) {
      row.mean_cost = row.total_cost / ok;
      row.mean_steps /= ok;
      row.mean_iou /= ok;
      row.mean_wall_s /= ok;
    }
    SetReduction(records, &row);
    const auto d = detours.find(k);
    row.over_shortest = d == detours.end() ? kNaN : d->second.first / d->second.second;
    out.push_back(row);
  }
  return out;
}

std::string NavigationMarkdown(const std::vector<NavigationReportRow>& rows, const std::vector<TrialRecord>& records) {
  std::ostringstream os;
  os << "| environment | planner | reached goal | mean cost | total cost | reduction vs optimistic | median cost ratio "
        "| cost / shortest | mean steps | mean IoU | failed runs | s/trial | inputs |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    char reduction[64] = "-", ratio[32] = "-", detour[32] = "-";
    if (!std::isnan(r.reduction))
      std::snprintf(reduction, sizeof reduction, "%.1f %% (%d seeds)", 100 * r.reduction, r.paired);
    if (!std::isnan(r.median_ratio)) std::snprintf(ratio, sizeof ratio, "%.3f", r.median_ratio);
    if (!std::isnan(r.over_shortest)) std::snprintf(detour, sizeof detour, "%.3f", r.over_shortest);
    char buf[400];
    std::snprintf(buf, sizeof buf, "| %s | %s | %d/%d | %.1f | %.0f | %s | %s | %s | %.1f | %.4f | %d | %.1f | ",
                  core::ToString(r.kind), r.planner.c_str(), r.reached, r.trials, r.mean_cost, r.total_cost, reduction,
                  ratio, detour, r.mean_steps, r.mean_iou, r.failed, r.mean_wall_s);
    os << buf << r.inputs << " |\n";  // the inputs may be long: not through the fixed buffer
  }
  std::vector<std::string> short_of_goal;
  for (const auto& r : records)
    if (!r.id.planner.empty() && (!r.ok || !r.success))
      short_of_goal.push_back(
          "- " + r.id.Key() + ": " +
          (r.ok ? r.end_reason + " after " + std::to_string(r.steps) + " steps" : "failed: " + r.error));
  if (!short_of_goal.empty()) {
    os << "\nShort of the goal (" << short_of_goal.size() << "):\n";
    for (const auto& line : short_of_goal) os << line << "\n";
  }
  return os.str();
}

std::string NavigationCsv(const std::vector<NavigationReportRow>& rows) {
  std::ostringstream os;
  os << "environment,planner,trials,reached,failed,mean_cost,total_cost,reduction,paired,median_ratio,over_shortest,"
        "mean_steps,mean_iou,mean_wall_s,inputs\n";
  for (const auto& r : rows)
    os << core::ToString(r.kind) << "," << r.planner << "," << r.trials << "," << r.reached << "," << r.failed << ","
       << r.mean_cost << "," << r.total_cost << "," << r.reduction << "," << r.paired << "," << r.median_ratio << ","
       << r.over_shortest << "," << r.mean_steps << "," << r.mean_iou << "," << r.mean_wall_s << ",\"" << r.inputs
       << "\"\n";
  return os.str();
}

namespace {

void DrawPanel(cv::Mat& img, int left, const std::string& title, const std::vector<std::pair<double, double>>& points,
               double max_cost) {
  const int size = 420, margin = 45;
  const auto px = [&](double x, double y) {
    return cv::Point(left + margin + int((size - margin - 10) * x / max_cost),
                     size - margin - int((size - margin - 30) * y / max_cost));
  };
  const cv::Scalar grey(170, 170, 170), black(0, 0, 0);
  cv::rectangle(img, px(0, max_cost), px(max_cost, 0), grey, 1);
  cv::line(img, px(0, 0), px(max_cost, max_cost), cv::Scalar(60, 160, 60), 1, cv::LINE_AA);
  for (const auto& [x, y] : points) cv::circle(img, px(x, y), 3, cv::Scalar(200, 100, 20), cv::FILLED, cv::LINE_AA);
  cv::putText(img, title, {left + 8, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.42, black, 1, cv::LINE_AA);
  cv::putText(img, "optimistic cost ->", {left + margin + 10, size - 12}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1,
              cv::LINE_AA);
  char top[32];
  std::snprintf(top, sizeof top, "%.0f", max_cost);
  cv::putText(img, top, {left + 4, px(0, max_cost).y + 10}, cv::FONT_HERSHEY_SIMPLEX, 0.35, black, 1, cv::LINE_AA);
  cv::putText(img, "0", {left + margin - 14, size - margin}, cv::FONT_HERSHEY_SIMPLEX, 0.35, black, 1, cv::LINE_AA);
}

}  // namespace

void WriteCostScatter(const std::vector<TrialRecord>& records, const std::string& png_path) {
  std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> panels;
  double max_cost = 1.0;
  for (const auto& row : SummarizeNavigation(records)) {
    if (row.planner == kBaseline) continue;
    const auto base = Costs(records, int(row.kind), kBaseline), mine = Costs(records, int(row.kind), row.planner);
    std::vector<std::pair<double, double>> points;
    for (const auto& [seed, cost] : mine)
      if (base.count(seed)) {
        points.push_back({base.at(seed), cost});
        max_cost = std::max({max_cost, base.at(seed), cost});
      }
    char title[160];
    const double reduction = std::isnan(row.reduction) ? 0.0 : row.reduction;
    std::snprintf(title, sizeof title, "%s: %s cost (y) vs optimistic (x), %.1f %% %s", core::ToString(row.kind),
                  row.planner.c_str(), 100 * std::abs(reduction), reduction < 0 ? "more" : "less");
    panels.push_back({title, points});
  }
  if (panels.empty()) return;
  cv::Mat img(420, 420 * int(panels.size()), CV_8UC3, cv::Scalar(255, 255, 255));
  for (size_t i = 0; i < panels.size(); ++i)
    DrawPanel(img, 420 * int(i), panels[i].first, panels[i].second, 1.05 * max_cost);
  internal::SavePicture(img, png_path);
}

}  // namespace toponav::experiments
