#include "experiments/batch.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "core/error.h"
#include "experiments/draw.h"
#include "experiments/results_io.h"
#include "experiments/navigation_trial.h"
#include "experiments/trial.h"
#include "sim/worlds.h"

namespace toponav::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

std::string TrialId::Key() const {
  const std::string middle = planner.empty() ? "a" + std::to_string(agents) : planner;
  return std::string(core::ToString(kind)) + "/" + middle + "/s" + std::to_string(seed);
}

std::vector<TrialId> ListTrials(const BenchOptions& bench, const std::vector<uint64_t>& seed_override) {
  std::vector<uint64_t> seeds = seed_override;
  if (seeds.empty())
    for (int i = 0; i < bench.num_seeds; ++i) seeds.push_back(bench.first_seed + uint64_t(i));
  std::vector<TrialId> out;
  for (const auto& row : bench.rows)
    for (uint64_t s : seeds) out.push_back({row.kind, row.agents, s, row.planner});
  return out;
}

namespace {

// A trial's record without results: a failed one says why, and 'signal' (> 0) if its process was killed by one.
json RecordJson(const TrialId& id, const std::string& error, int signal = 0) {
  json j;
  j["id"] = id.Key();
  j["kind"] = core::ToString(id.kind);
  j["agents"] = id.agents;
  j["seed"] = id.seed;
  if (!id.planner.empty()) j["planner"] = id.planner;
  j["ok"] = error.empty();
  if (!error.empty()) j["error"] = error;
  if (signal > 0) j["signal"] = signal;
  return j;
}

json SearchJson(const TrialId& id, const TrialResult& r) {
  json j = RecordJson(id, "");
  j["sensors"] = r.sensors;
  j["success"] = r.success;
  j["explored"] = r.explored;
  j["steps"] = r.steps;
  j["iou"] = r.iou;
  double d = 0;
  for (double x : r.distance) d += x;
  j["distance"] = d;
  j["distance_per_agent"] = r.distance;
  j["nudges"] = r.nudges;
  j["give_ups"] = r.give_ups;
  j["inspections"] = r.inspections;
  j["sealed_steps"] = r.sealed_steps;
  j["blocks"] = r.blocks.size();
  j["end_reason"] = r.end_reason;
  j["wall_time_s"] = r.wall_time_s;
  j["time_s"] = {{"observe_and_map", r.time_map_s}, {"mcmc", r.time_mcmc_s}, {"known_space", r.time_known_s},
                 {"plan_and_move", r.time_plan_s}};
  return j;
}

json NavigationJson(const TrialId& id, const NavigationResult& r) {
  json j = RecordJson(id, "");
  j["sensors"] = r.sensors;
  j["privileged"] = r.privileged ? "true_world" : "none";
  j["success"] = r.reached;
  j["explored"] = false;
  j["steps"] = r.steps;
  j["iou"] = r.iou;
  j["distance"] = r.distance;
  j["shortest"] = r.shortest;
  j["nudges"] = r.nudges;
  j["recovery_steps"] = r.recovery_steps;
  j["repeated_steps"] = r.repeated_steps;
  j["scan_steps"] = r.scan_steps;
  j["longest_hold"] = r.longest_hold;
  j["blocks"] = r.blocks.size();
  j["end_reason"] = r.end_reason;
  j["wall_time_s"] = r.wall_time_s;
  return j;
}

using StepHook = std::function<void(const mapping::MapView&, const std::vector<std::vector<core::Vec2>>&)>;

// Runs the trial 'id' names (a search, or goal-directed navigation with its planner): its record, and the final
// map and paths for the picture.
json RunTrial(const Config& config, const TrialId& id, const core::World& w, const StepHook& on_step,
              mapping::MapView* view, std::vector<std::vector<core::Vec2>>* paths, MapPictureExtras* extras) {
  if (id.planner.empty()) {
    TrialOptions t;
    t.num_agents = id.agents;
    t.max_steps = config.bench.max_steps;
    t.mcmc_every = config.bench.mcmc_every;
    t.open_world_mcmc_every = config.open_world.mcmc_every;
    t.on_step = on_step;
    const TrialResult r = RunSearchTrial(w, config, t, id.seed, view);
    *paths = r.paths;
    extras->blocks = r.blocks;
    return SearchJson(id, r);
  }
  NavigationTrialOptions n;
  const auto planner = ParseGoalPlanner(id.planner);
  TOPONAV_CHECK(planner, "trial " << id.Key() << " names no goal-directed planner");
  n.planner = *planner;
  n.max_steps = config.bench.max_steps;
  n.mcmc_every = config.bench.mcmc_every;
  n.on_step = on_step;
  const NavigationResult r = RunNavigationTrial(w, config, n, id.seed, view);
  *paths = {r.path};
  *extras = {w.goal, r.frontier_ps, r.blocks, r.scan_walls, {}};
  return NavigationJson(id, r);
}

// Runs in the forked child: the trial, its picture, and one JSON line on 'fd'.
[[noreturn]] void ChildMain(const Config& config, const BatchOptions& o, const TrialId& id, int fd) {
  std::string line;
  try {
    if (id.Key() == o.crash_key) std::raise(SIGSEGV);
    if (id.Key() == o.fail_key) throw core::InternalError("injected failure for " + id.Key());
    const core::World w = sim::GenerateWorld(id.kind, config.worlds, id.seed);
    std::string name = id.Key();
    std::replace(name.begin(), name.end(), '/', '_');
    std::unique_ptr<TrialVideo> video;
    StepHook on_step;
    if (config.bench.videos) {
      const fs::path dir = fs::path(o.out_dir) / "videos";
      fs::create_directories(dir);
      video = std::make_unique<TrialVideo>(w, config.picture, (dir / (name + ".mp4")).string());
      on_step = [&](const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) {
        video->AddFrame(v, paths);
      };
    }
    mapping::MapView view;
    std::vector<std::vector<core::Vec2>> paths;
    MapPictureExtras extras;
    const json record = RunTrial(config, id, w, on_step, &view, &paths, &extras);
    line = record.dump();
    if (WantsPicture(config.bench.pictures, record.at("success").get<bool>(), id.seed, config.bench.first_seed)) {
      const fs::path dir = fs::path(o.out_dir) / "pictures";
      fs::create_directories(dir);
      DrawMapPicture(w, view, paths, config.picture, (dir / (name + ".png")).string(), extras);
    }
  } catch (const std::exception& e) {
    line = RecordJson(id, e.what()).dump();
  }
  line += "\n";
  for (size_t off = 0; off < line.size();) {
    const ssize_t n = ::write(fd, line.data() + off, line.size() - off);
    if (n <= 0) break;
    off += size_t(n);
  }
  ::close(fd);
  std::_Exit(0);
}

std::string FormatDuration(double s) {
  const int t = int(s + 0.5);
  std::ostringstream os;
  if (t >= 3600) os << t / 3600 << "h";
  if (t >= 60) os << (t / 60) % 60 << "m";
  os << t % 60 << "s";
  return os.str();
}

}  // namespace

std::string BatchStamp(const std::string& config_path, const std::vector<TrialId>& trials) {
  auto fnv = [](std::istream& in) {
    uint64_t h = 1469598103934665603ull;
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
      for (std::streamsize i = 0; i < in.gcount(); ++i) h = (h ^ uint8_t(buf[i])) * 1099511628211ull;
      if (!in) break;
    }
    return h;
  };
  std::ifstream program("/proc/self/exe", std::ios::binary);
  std::ifstream config(config_path, std::ios::binary);
  if (!config) throw core::DataError(config_path, "cannot read the config");
  std::ostringstream os;
  std::string keys;
  for (const auto& t : trials) keys += t.Key() + "\n";
  std::istringstream trial_set(keys);
  os << std::hex << "program-" << (program ? fnv(program) : 0) << "-config-" << fnv(config) << "-trials-"
     << fnv(trial_set);
  return os.str();
}

namespace {

std::string ResultsFile(const BatchOptions& o) {
  const std::string name = o.shard_count == 1 ? std::string("trials.jsonl")
                                              : "trials-" + std::to_string(o.shard_index) + "-of-" +
                                                    std::to_string(o.shard_count) + ".jsonl";
  return (fs::path(o.out_dir) / name).string();
}

// --fresh discards this shard's own results file; otherwise only trials of the same program, config and
// trial set may be resumed (they are pure functions of them), and a directory holding another batch's
// results is refused.
void PrepareOutput(const BatchOptions& o, const std::string& own_file) {
  if (o.fresh) fs::remove(own_file);
  if (o.stamp.empty()) return;
  const std::string old = ReadStamp(o.out_dir);
  if (old == o.stamp) return;
  std::vector<std::string> held;  // results files with trials in them
  for (const auto& f : BatchResultsFiles(o.out_dir))
    if (fs::file_size(f) > 0) held.push_back(f.filename().string());
  if (!held.empty()) {
    const std::string what =
        old.empty() ? "trials of an unknown build, config or trial set (no stamp)"
                    : "trials of another build, config or trial set (stamp " + old + ", now " + o.stamp + ")";
    const bool only_own = held.size() == 1 && held[0] == fs::path(own_file).filename().string();
    std::string files;
    for (const auto& h : held) files += (files.empty() ? "" : ", ") + h;
    throw core::DataError((fs::path(o.out_dir) / "batch-stamp.txt").string(),
                          "the directory holds " + what + " in " + files +
                              (only_own ? ": use another --out, or --fresh to discard them"
                                        : ": use another --out (--fresh discards only this shard's own file)"));
  }
  WriteStamp(o.out_dir, o.stamp);
}

// This shard's trials that the directory does not hold yet (at most max_new_trials).
std::vector<TrialId> PendingTrials(const BatchOptions& o, const std::vector<TrialId>& all, BatchSummary* summary) {
  std::set<std::string> done;  // a trial whose process was killed by a signal is run again
  for (const auto& r : ReadResults({o.out_dir}))
    if (r.signal == 0) done.insert(r.id.Key());
  std::vector<TrialId> todo;
  for (size_t k = 0; k < all.size(); ++k) {
    if (int(k % size_t(o.shard_count)) != o.shard_index) continue;
    ++summary->total;
    if (done.count(all[k].Key())) ++summary->already_done;
    else todo.push_back(all[k]);
  }
  if (o.max_new_trials >= 0 && int(todo.size()) > o.max_new_trials) todo.resize(size_t(o.max_new_trials));
  return todo;
}

struct Child {
  pid_t pid;
  int fd;
  TrialId id;
  std::string buffer;
};

Child Spawn(const Config& config, const BatchOptions& o, const TrialId& id) {
  int fds[2];
  if (::pipe(fds) != 0) throw core::InternalError("pipe() failed");
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) throw core::InternalError("fork() failed");
  if (pid == 0) {
    ::close(fds[0]);
    ChildMain(config, o, id, fds[1]);
  }
  ::close(fds[1]);
  return {pid, fds[0], id, ""};
}

// The record of a finished child: the line it wrote, or a failure saying how it ended.
json Collect(Child& c, int status) {
  char buf[4096];
  ssize_t n;
  while ((n = ::read(c.fd, buf, sizeof buf)) > 0) c.buffer.append(buf, size_t(n));
  ::close(c.fd);
  try {
    if (!c.buffer.empty() && c.buffer.back() == '\n') return json::parse(c.buffer);
  } catch (const json::exception&) {
  }
  if (WIFSIGNALED(status))  // killed (out of memory, pre-empted) or crashed: retried on resume
    return RecordJson(c.id, "killed by signal " + std::to_string(WTERMSIG(status)), WTERMSIG(status));
  return RecordJson(c.id, "exited with status " + std::to_string(WEXITSTATUS(status)) + " and no result");
}

class Progress {
 public:
  Progress(const BatchOptions& o, size_t todo) : on_(o.progress), tty_(o.progress && ::isatty(2)), todo_(todo) {}
  ~Progress() {
    if (tty_) std::cerr << "\n";
  }
  void Report(const BatchSummary& s) const {
    if (!on_) return;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const int finished = s.ran;
    const double eta = finished > 0 ? el / finished * double(todo_ - size_t(finished)) : 0.0;
    std::cerr << (tty_ ? "\r" : "") << "[bench] " << s.already_done + finished << "/" << s.total << " trials done ("
              << s.failed << " failed), elapsed " << FormatDuration(el)
              << (finished > 0 ? ", ETA " + FormatDuration(eta) : std::string()) << (tty_ ? "   " : "\n") << std::flush;
  }

 private:
  bool on_, tty_;
  size_t todo_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

// Runs 'todo' in forked workers, appending one whole line per finished trial (a kill loses at most the
// running ones).
void RunWorkers(const Config& config, const BatchOptions& o, const std::vector<TrialId>& todo, ResultsAppender& out,
                BatchSummary* summary) {
  const int workers = o.workers > 0 ? o.workers : std::max(1u, std::thread::hardware_concurrency());
  const Progress progress(o, todo.size());
  std::vector<Child> running;  // pid -1: finished, removed after each sweep
  // A failed write stops the batch: the running trials are stopped too (they are redone on resume).
  struct StopOnThrow {
    std::vector<Child>& running;
    ~StopOnThrow() {
      for (const auto& c : running) {
        if (c.pid < 0) continue;
        ::kill(c.pid, SIGKILL);
        ::waitpid(c.pid, nullptr, 0);
        ::close(c.fd);
      }
    }
  } stop{running};
  size_t next = 0;
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && int(running.size()) < workers) running.push_back(Spawn(config, o, todo[next++]));
    // Read whatever the children wrote, then reap those that finished.
    std::vector<pollfd> pfds;
    for (const auto& c : running) pfds.push_back({c.fd, POLLIN, 0});
    ::poll(pfds.data(), nfds_t(pfds.size()), 200);
    for (size_t i = 0; i < running.size(); ++i) {
      Child& c = running[i];
      char buf[4096];
      ssize_t n;
      while ((pfds[i].revents & (POLLIN | POLLHUP)) && (n = ::read(c.fd, buf, sizeof buf)) > 0)
        c.buffer.append(buf, size_t(n));
      int status = 0;
      const pid_t w = ::waitpid(c.pid, &status, WNOHANG);
      if (w == 0) continue;        // still running
      if (w < 0) status = 0x7f00;  // cannot be waited for (e.g. SIGCHLD ignored): give up on it, read what it wrote
      const json j = Collect(c, status);  // (closes its pipe)
      c.pid = -1;
      out.Append(j.dump());
      if (!j.value("ok", false)) ++summary->failed;
      ++summary->ran;
      progress.Report(*summary);
    }
    running.erase(std::remove_if(running.begin(), running.end(), [](const Child& c) { return c.pid < 0; }),
                  running.end());
  }
}

}  // namespace

bool WantsPicture(PictureSet set, bool success, uint64_t seed, uint64_t first_seed) {
  return set == PictureSet::kAll || (set == PictureSet::kFailures && (!success || seed == first_seed));
}

BatchSummary RunBatch(const Config& config, const BatchOptions& o, const std::vector<TrialId>& all) {
  const auto t0 = std::chrono::steady_clock::now();
  TOPONAV_CHECK(o.shard_count >= 1 && o.shard_index >= 0 && o.shard_index < o.shard_count,
                "shard " << o.shard_index << "/" << o.shard_count);
  fs::create_directories(o.out_dir);
  BatchSummary summary;
  summary.results_file = ResultsFile(o);
  const BatchLock lock(o.out_dir, fs::path(summary.results_file).filename().string());
  PrepareOutput(o, summary.results_file);
  const std::vector<TrialId> todo = PendingTrials(o, all, &summary);
  ResultsAppender out(summary.results_file);
  RunWorkers(config, o, todo, out, &summary);
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace toponav::experiments
