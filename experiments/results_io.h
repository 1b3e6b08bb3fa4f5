#pragma once
// What a batch keeps on disk, and the promises around it (docs/reliability.md): a results directory holds
// one batch -- its results files (trials.jsonl, or trials-I-of-N.jsonl per shard), batch-stamp.txt naming
// the program, config and trial set that made them, and one lock file per shard.  Other files are never
// read as results and never removed.
#include <filesystem>
#include <string>
#include <vector>

namespace toponav::experiments {

// trials.jsonl or trials-I-of-N.jsonl (I < N).
bool IsBatchResultsFile(const std::string& filename);
std::vector<std::filesystem::path> BatchResultsFiles(const std::string& dir);  // sorted

// Writes 'text' to 'path', checked: a full disk is a core::DataError naming the file, not an empty file.
void WriteTextFile(const std::string& path, const std::string& text);

// The directory's stamp ("" if none).  WriteStamp replaces it atomically (a full disk leaves the old one).
std::string ReadStamp(const std::string& dir);
void WriteStamp(const std::string& dir, const std::string& stamp);

// An exclusive lock on 'dir' for one results file (flock on DIR/.<name>.lock), held while the object lives:
// a second writer of the same results file is refused with a message instead of duplicating its trials.
class BatchLock {
 public:
  BatchLock(const std::string& dir, const std::string& results_name);
  ~BatchLock();
  BatchLock(const BatchLock&) = delete;
  BatchLock& operator=(const BatchLock&) = delete;

 private:
  int fd_ = -1;
};

// Appends whole lines to a results file.  Opening closes a partial last line (a run killed mid-write); every
// Append writes, flushes and syncs one line, and throws core::DataError naming the file if any of that fails
// (a full disk): what was written before stays valid, and a partial line is skipped by readers.
class ResultsAppender {
 public:
  explicit ResultsAppender(const std::string& file);
  ~ResultsAppender();
  ResultsAppender(const ResultsAppender&) = delete;
  ResultsAppender& operator=(const ResultsAppender&) = delete;
  void Append(const std::string& line);

 private:
  void Write(const std::string& bytes);
  std::string file_;
  int fd_ = -1;
};

}  // namespace toponav::experiments
