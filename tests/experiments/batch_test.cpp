#include "experiments/batch.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "experiments/results_io.h"

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <vector>

namespace toponav::experiments {
namespace {

namespace fs = std::filesystem;

Config TinyBench() {
  return ParseConfig(
      "bench:\n  name: tiny\n  rows:\n    - {kind: labyrinth, agents: 1}\n    - {kind: guided_maze, agents: 3}\n"
      "  first_seed: 20\n  num_seeds: 3\n  max_steps: 8\n  pictures: false\n",
      "tiny.yaml");
}

std::string DirPrefix() { return "toponav_batch_" + std::to_string(::getpid()) + "_"; }

std::string FreshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / (DirPrefix() + name);
  fs::remove_all(d);
  return d.string();
}

// This process's batch directories go when its tests are done.
class RemoveBatchDirs : public ::testing::Environment {
 public:
  void TearDown() override {
    std::vector<fs::path> mine;
    for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
      if (e.path().filename().string().rfind(DirPrefix(), 0) == 0) mine.push_back(e.path());
    for (const auto& p : mine) fs::remove_all(p);
  }
};
::testing::Environment* const kRemoveBatchDirs = ::testing::AddGlobalTestEnvironment(new RemoveBatchDirs);

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

TEST(Batch, PicturesOfFailuresAreFailedTrialsAndEachRowsFirstSeed) {
  EXPECT_TRUE(WantsPicture(PictureSet::kAll, true, 12, 10));
  EXPECT_FALSE(WantsPicture(PictureSet::kNone, false, 10, 10));
  EXPECT_TRUE(WantsPicture(PictureSet::kFailures, false, 12, 10));
  EXPECT_TRUE(WantsPicture(PictureSet::kFailures, true, 10, 10)) << "a representative success";
  EXPECT_FALSE(WantsPicture(PictureSet::kFailures, true, 12, 10));
  // The YAML key takes true, false or failures, and names itself on anything else.
  EXPECT_EQ(ParseConfig("bench:\n  pictures: failures\n", "p.yaml").bench.pictures, PictureSet::kFailures);
  EXPECT_EQ(ParseConfig("bench:\n  pictures: false\n", "p.yaml").bench.pictures, PictureSet::kNone);
  EXPECT_EQ(ParseConfig("bench:\n  pictures: true\n", "p.yaml").bench.pictures, PictureSet::kAll);
  try {
    ParseConfig("bench:\n  pictures: some\n", "p.yaml");
    FAIL() << "accepted pictures: some";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("bench.pictures"), std::string::npos) << e.what();
  }
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

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const core::DataError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BatchReliability, FreshRemovesOnlyThisShardsOwnResultsFile) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions o = QuietBatch("fresh_own");
  o.stamp = "stamp-a";
  o.shard_count = 2;
  o.max_new_trials = 1;
  RunBatch(cfg, o, trials);  // shard 0
  o.shard_index = 1;
  RunBatch(cfg, o, trials);  // shard 1
  std::ofstream(fs::path(o.out_dir) / "my_notes.jsonl") << "{\"mine\": true}\n";
  o.shard_index = 0;
  o.fresh = true;
  o.max_new_trials = 0;
  RunBatch(cfg, o, trials);
  EXPECT_FALSE(fs::exists(fs::path(o.out_dir) / "trials-0-of-2.jsonl") &&
               fs::file_size(fs::path(o.out_dir) / "trials-0-of-2.jsonl") > 0);
  EXPECT_TRUE(fs::exists(fs::path(o.out_dir) / "trials-1-of-2.jsonl")) << "the other shard's trials stay";
  EXPECT_TRUE(fs::exists(fs::path(o.out_dir) / "my_notes.jsonl")) << "a file the user put there stays";
  EXPECT_EQ(ReadResults({o.out_dir}).size(), 1u) << "and is never read as results";
  // Another build's stamp: --fresh cannot discard the other shard's file, so the run is refused.
  o.stamp = "stamp-b";
  EXPECT_NE(ErrorOf([&] { RunBatch(cfg, o, trials); }).find("trials-1-of-2.jsonl"), std::string::npos);
}

TEST(BatchReliability, AFullDiskStopsTheRunWithAnErrorAndKeepsWhatWasWritten) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions o = QuietBatch("disk_full");
  o.stamp = "stamp-a";
  fs::create_directories(o.out_dir);
  // The stamp cannot be written: an error, and no empty stamp is left behind to block the next run.
  fs::create_symlink("/dev/full", fs::path(o.out_dir) / ".batch-stamp.txt.tmp");
  EXPECT_NE(ErrorOf([&] { RunBatch(cfg, o, trials); }).find("batch-stamp.txt"), std::string::npos);
  EXPECT_EQ(ReadStamp(o.out_dir), "");
  fs::remove(fs::path(o.out_dir) / ".batch-stamp.txt.tmp");
  o.max_new_trials = 2;
  EXPECT_EQ(RunBatch(cfg, o, trials).ran, 2);
  // The results file cannot grow (a file-size limit stands in for a full disk: writes fail the same way):
  // the write error stops the run, naming the file.
  const fs::path results = fs::path(o.out_dir) / "trials.jsonl";
  const auto size = fs::file_size(results);
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = old;
  limited.rlim_cur = rlim_t(size + 40);  // room for part of one more record
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  o.max_new_trials = -1;
  const std::string e = ErrorOf([&] { RunBatch(cfg, o, trials); });
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(e.find("trials.jsonl"), std::string::npos) << e;
  EXPECT_NE(e.find("cannot write a result"), std::string::npos) << e;
  // With space again, the two trials written before are intact (the partial line is skipped) and the rest
  // is run.
  const BatchSummary s = RunBatch(cfg, o, trials);
  EXPECT_EQ(s.already_done, 2);
  EXPECT_EQ(s.ran, 4);
}

TEST(BatchReliability, ATrialKilledByASignalIsRetriedOnResumeAndAThrowingOneIsNot) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions o = QuietBatch("signal");
  o.fail_key = trials[1].Key();
  o.crash_key = trials[4].Key();
  EXPECT_EQ(RunBatch(cfg, o, trials).failed, 2);
  o.fail_key.clear();
  o.crash_key.clear();
  const BatchSummary s = RunBatch(cfg, o, trials);
  EXPECT_EQ(s.ran, 1) << "only the killed trial runs again";
  EXPECT_EQ(s.already_done, 5);
  for (const auto& r : ReadResults({o.out_dir})) {
    if (r.id.Key() == trials[4].Key()) {
      EXPECT_TRUE(r.ok) << "the retry's record replaces the kill's";
    }
    if (r.id.Key() == trials[1].Key()) {
      EXPECT_FALSE(r.ok) << "a deterministic throw stays recorded as failed";
    }
  }
}

TEST(BatchReliability, ASecondWriterOfTheSameResultsIsRefused) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions o = QuietBatch("lock");
  fs::create_directories(o.out_dir);
  const BatchLock held(o.out_dir, "trials.jsonl");
  EXPECT_NE(ErrorOf([&] { RunBatch(cfg, o, trials); }).find("another toponav bench"), std::string::npos);
  BatchOptions shard = o;
  shard.shard_count = 2;
  shard.max_new_trials = 1;
  EXPECT_EQ(RunBatch(cfg, shard, trials).ran, 1) << "another shard's file has its own lock";
}

TEST(BatchReliability, IncompleteRecordsAreReportedSkippedAndRedone) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions o = QuietBatch("incomplete");
  o.max_new_trials = 1;
  RunBatch(cfg, o, trials);
  std::ofstream(fs::path(o.out_dir) / "trials.jsonl", std::ios::app)
      << R"({"id": "labyrinth/a1/s21", "kind": "labyrinth", "agents": 1, "seed": 21, "ok": true, "success": true})"
      << "\n";
  std::vector<std::string> skipped;
  EXPECT_EQ(ReadResults({o.out_dir}, &skipped).size(), 1u);
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_NE(skipped[0].find("trials.jsonl:2"), std::string::npos) << skipped[0];
  o.max_new_trials = -1;
  EXPECT_EQ(RunBatch(cfg, o, trials).ran, 5) << "the incomplete trial is run properly";
}

TEST(BatchReliability, ReportsRefuseDirectoriesOfDifferentBatchesAndAcceptShardsOfOne) {
  const Config cfg = TinyBench();
  const auto trials = ListTrials(cfg.bench);
  BatchOptions a = QuietBatch("mix_a"), b = QuietBatch("mix_b"), c = QuietBatch("mix_c");
  a.stamp = b.stamp = "stamp-a";
  c.stamp = "stamp-c";
  a.max_new_trials = b.max_new_trials = c.max_new_trials = 1;
  a.shard_count = b.shard_count = 2;
  b.shard_index = 1;
  for (const auto* o : {&a, &b, &c}) RunBatch(cfg, *o, trials);
  EXPECT_NO_THROW(CheckOneBatch({a.out_dir, b.out_dir}));
  EXPECT_NE(ErrorOf([&] { CheckOneBatch({a.out_dir, c.out_dir}); }).find("report them separately"), std::string::npos);
  EXPECT_NE(BatchStamp("tests/../CMakeLists.txt", trials),
            BatchStamp("tests/../CMakeLists.txt", ListTrials(cfg.bench, {1})))
      << "another trial set is another batch";
}

}  // namespace
}  // namespace toponav::experiments
