#include "experiments/batch.h"

#include <gtest/gtest.h>

#include "core/error.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace toponav::experiments {
namespace {

namespace fs = std::filesystem;

Config TinyBench() {
  return ParseConfig(
      "bench:\n  name: tiny\n  rows:\n    - {kind: labyrinth, agents: 1}\n    - {kind: guided_maze, agents: 3}\n"
      "  first_seed: 20\n  num_seeds: 3\n  max_steps: 8\n  pictures: false\n",
      "tiny.yaml");
}

std::string FreshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("toponav_batch_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  return d.string();
}

// A quiet batch writing to a fresh directory.
BatchOptions QuietBatch(const std::string& name) {
  BatchOptions o;
  o.out_dir = FreshDir(name);
  o.progress = false;
  return o;
}

int CountLines(const std::string& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".jsonl") {
      std::ifstream in(e.path());
      std::string line;
      while (std::getline(in, line)) ++n;
    }
  return n;
}

TEST(Batch, ResumesWithoutRedoingOrLosingTrials) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  ASSERT_EQ(trials.size(), 6u);
  BatchOptions o = QuietBatch("resume");
  o.workers = 2;
  o.max_new_trials = 2;  // "killed" after two trials
  EXPECT_EQ(RunBatch(cfg, o, trials).ran, 2);
  // A kill mid-write leaves half a line: it must be ignored and that trial redone.
  std::ofstream(fs::path(o.out_dir) / "trials.jsonl", std::ios::app) << "{\"id\": \"labyrinth/a1/s2";
  o.max_new_trials = -1;
  const BatchSummary s = RunBatch(cfg, o, trials);
  EXPECT_EQ(s.already_done, 2);
  EXPECT_EQ(s.ran, 4);
  const auto records = ReadResults({o.out_dir});
  std::set<std::string> keys;
  for (const auto& r : records) keys.insert(r.id.Key());
  EXPECT_EQ(keys.size(), 6u);
  EXPECT_EQ(RunBatch(cfg, o, trials).ran, 0) << "a finished batch has nothing left to do";
}

TEST(Batch, ResumesOnlyTrialsOfTheSameStampAndFreshDiscardsTheRest) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench, {});
  BatchOptions o = QuietBatch("stamp");
  o.stamp = "program-a-config-a";
  o.max_new_trials = 2;
  EXPECT_EQ(RunBatch(cfg, o, trials).ran, 2);
  o.max_new_trials = 1;
  EXPECT_EQ(RunBatch(cfg, o, trials).already_done, 2) << "the same stamp resumes";
  o.stamp = "program-b-config-a";
  EXPECT_THROW(RunBatch(cfg, o, trials), core::DataError) << "another build's trials are not taken as done";
  EXPECT_EQ(CountLines(o.out_dir), 3) << "and are left as they were";
  o.fresh = true;
  const BatchSummary s = RunBatch(cfg, o, trials);
  EXPECT_EQ(s.already_done, 0);
  EXPECT_EQ(s.ran, 1);
  EXPECT_EQ(CountLines(o.out_dir), 1);
}

TEST(Batch, TwoShardsMergeIntoTheSameTableAsOneRun) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions whole = QuietBatch("whole");
  RunBatch(cfg, whole, trials);
  BatchOptions a = whole, b = whole;
  a.out_dir = FreshDir("shard0");
  b.out_dir = FreshDir("shard1");
  a.shard_count = b.shard_count = 2;
  a.shard_index = 0;
  b.shard_index = 1;
  EXPECT_EQ(RunBatch(cfg, a, trials).total + RunBatch(cfg, b, trials).total, 6);
  // Everything but the timing columns (wall time differs from run to run).
  auto untimed = [](std::vector<ReportRow> rows) {
    for (auto& r : rows) r.mean_wall_s = r.ms_per_step = 0;
    return MarkdownTable(rows);
  };
  EXPECT_EQ(untimed(Summarize(ReadResults({a.out_dir, b.out_dir}))), untimed(Summarize(ReadResults({whole.out_dir}))));
}

TEST(Batch, AThrowingAndACrashingTrialAreRecordedAndTheRestFinish) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions o = QuietBatch("failures");
  o.fail_key = trials[1].Key();
  o.crash_key = trials[4].Key();
  const BatchSummary s = RunBatch(cfg, o, trials);
  EXPECT_EQ(s.ran, 6);
  EXPECT_EQ(s.failed, 2);
  EXPECT_EQ(CountLines(o.out_dir), 6);
  for (const auto& r : ReadResults({o.out_dir})) {
    if (r.id.Key() == o.fail_key) {
      EXPECT_FALSE(r.ok);
      EXPECT_NE(r.error.find("injected"), std::string::npos);
    } else if (r.id.Key() == o.crash_key) {
      EXPECT_FALSE(r.ok);
      EXPECT_NE(r.error.find("signal"), std::string::npos);
    } else {
      EXPECT_TRUE(r.ok) << r.id.Key() << ": " << r.error;
      EXPECT_GT(r.steps, 0);
    }
  }
  const auto rows = Summarize(ReadResults({o.out_dir}));
  int failed = 0;
  for (const auto& row : rows) failed += row.failed;
  EXPECT_EQ(failed, 2);
}

TEST(Batch, SeedOverrideReplacesTheConfigSeeds) {
  const auto trials = ListTrials(TinyBench().bench, {500, 501});
  ASSERT_EQ(trials.size(), 4u);
  EXPECT_EQ(trials[0].Key(), "labyrinth/a1/s500");
  EXPECT_EQ(trials[3].Key(), "guided_maze/a3/s501");
}

}  // namespace
}  // namespace toponav::experiments
