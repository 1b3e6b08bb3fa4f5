#pragma once
// The batch runner behind `toponav bench` and `toponav report`.  Trials are pure functions of (config, world
// kind, agent count, seed).  Each trial runs in its own forked process (up to 'workers' at once), so a trial
// that throws or crashes is recorded as failed and the batch goes on.  Finished trials are appended as JSON
// lines; a rerun skips them (resume after a kill), and --shard i/N splits a sweep across machines.
#include <cstdint>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/config.h"

namespace toponav::experiments {

struct TrialId {
  core::WorldKind kind = core::WorldKind::kLabyrinth;
  int agents = 1;
  uint64_t seed = 0;
  std::string planner;      // goal-directed navigation: the planner ("optimistic", ...); empty: a search
  std::string Key() const;  // a search "labyrinth/a1/s10000", a navigation trial "guided_maze/optimistic/s10000"
};

// Every trial of the bench config, rows in order, seeds ascending ('seed_range' overrides the config's).
std::vector<TrialId> ListTrials(const BenchOptions& bench, const std::vector<uint64_t>& seed_override = {});

struct BatchOptions {
  std::string out_dir;
  int workers = 0;              // 0: all cores
  int shard_index = 0;          // run only trials k with k % shard_count == shard_index
  int shard_count = 1;
  int max_new_trials = -1;      // stop after this many new trials (-1: all); for tests and partial runs
  bool progress = true;         // progress and ETA on stderr
  std::string fail_key;         // testing: this trial throws
  std::string crash_key;        // testing: this trial's process crashes (SIGSEGV)
  // What produced the trials (the program, the config, the trial set): written to DIR/batch-stamp.txt; a
  // directory holding results of another stamp is an error.  Empty: no check.
  std::string stamp;
  bool fresh = false;           // discard this shard's own results file first
};

struct BatchSummary {
  int total = 0;        // trials in this shard
  int already_done = 0; // found in the results file
  int ran = 0;
  int failed = 0;
  double wall_s = 0.0;
  std::string results_file;
};

BatchSummary RunBatch(const Config& config, const BatchOptions& options, const std::vector<TrialId>& trials);

// Whether a finished trial gets its final picture under bench.pictures (failures: failed trials and the
// batch's first seed of every row).
bool WantsPicture(PictureSet set, bool success, uint64_t seed, uint64_t first_seed);

// A stamp for BatchOptions::stamp: a hash of the running program's file, the config file's text and the
// batch's trial set (so an output directory holds one batch).
std::string BatchStamp(const std::string& config_path, const std::vector<TrialId>& trials);

// One line of a results file.
struct TrialRecord {
  TrialId id;
  bool ok = false;          // false: the trial threw or crashed ('error' says how)
  std::string error;
  int signal = 0;           // > 0: its process was killed by this signal (retried on resume)
  bool success = false;     // a search: explored with the IoU asked for; a navigation trial: reached the goal
  bool explored = false;
  int steps = 0;
  double iou = 0.0;
  double distance = 0.0;    // summed over agents (a navigation trial's cost)
  double shortest = 0.0;    // a navigation trial: the true world's shortest way (0: not recorded)
  double wall_time_s = 0.0;
  std::string end_reason;
  std::string sensors;      // what the agents sensed with ("" in records written before it was recorded)
  bool privileged = false;  // a navigation trial's planner was given the true world (oracle, known)
};

// All records of the batch results files in 'dirs' (one per trial key, the last one written).  Lines that
// are not complete records (a half-written last line of a killed run, a record missing a key) are skipped
// and, if 'skipped' is given, listed there as "FILE:LINE: skipped: why".
std::vector<TrialRecord> ReadResults(const std::vector<std::string>& dirs, std::vector<std::string>* skipped = nullptr);
// Throws core::DataError unless every directory's stamp is the same (merging shards of one batch is fine;
// mixing builds, configs or trial sets would make one table of trials that do not belong together).
void CheckOneBatch(const std::vector<std::string>& dirs);

struct ReportRow {
  core::WorldKind kind = core::WorldKind::kLabyrinth;
  int agents = 1;
  int trials = 0, successes = 0, failed = 0;
  double mean_steps = 0.0, mean_iou = 0.0;
  double mean_wall_s = 0.0;   // per trial
  double ms_per_step = 0.0;   // all trials' wall time over all their steps
};
// Rows for the search trials (records without a planner).
std::vector<ReportRow> Summarize(const std::vector<TrialRecord>& records);
std::string MarkdownTable(const std::vector<ReportRow>& rows);
std::string CsvTable(const std::vector<ReportRow>& rows);
// Steps per trial, single agent against the team, per world kind (PNG).
void WriteStepsPlot(const std::vector<TrialRecord>& records, const std::string& png_path);

}  // namespace toponav::experiments
