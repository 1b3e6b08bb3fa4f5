#include "experiments/results_io.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <regex>

#include "core/error.h"

namespace toponav::experiments {

namespace fs = std::filesystem;

bool IsBatchResultsFile(const std::string& name) {
  static const std::regex kShard("trials-([0-9]{1,6})-of-([0-9]{1,6})\\.jsonl");
  std::smatch m;
  if (name == "trials.jsonl") return true;
  return std::regex_match(name, m, kShard) && std::stoi(m[1]) < std::stoi(m[2]);
}

std::vector<fs::path> BatchResultsFiles(const std::string& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (IsBatchResultsFile(e.path().filename().string()) && fs::is_regular_file(e.path())) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

void WriteTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.flush();
  if (!out) throw core::DataError(path, "cannot write the file (disk full?)");
}

std::string ReadStamp(const std::string& dir) {
  std::string stamp;
  if (std::ifstream in(fs::path(dir) / "batch-stamp.txt"); in) std::getline(in, stamp);
  return stamp;
}

void WriteStamp(const std::string& dir, const std::string& stamp) {
  const fs::path file = fs::path(dir) / "batch-stamp.txt", tmp = fs::path(dir) / ".batch-stamp.txt.tmp";
  {
    std::ofstream out(tmp);
    out << stamp << "\n";
    out.flush();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw core::DataError(file.string(), "cannot write the batch stamp (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) throw core::DataError(file.string(), "cannot write the batch stamp: " + ec.message());
}

BatchLock::BatchLock(const std::string& dir, const std::string& results_name) {
  const std::string path = (fs::path(dir) / ("." + results_name + ".lock")).string();
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw core::DataError(path, std::string("cannot open the lock file: ") + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw core::DataError(dir, "another toponav bench is writing " + results_name +
                                   " in this directory (lock " + path + "): wait for it, or use another --out");
  }
}

BatchLock::~BatchLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

ResultsAppender::ResultsAppender(const std::string& file) : file_(file) {
  bool ends_cleanly = true;
  {
    std::ifstream prev(file, std::ios::binary | std::ios::ate);
    if (prev && prev.tellg() > 0) {
      prev.seekg(-1, std::ios::end);
      ends_cleanly = prev.get() == '\n';
    }
  }
  fd_ = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw core::DataError(file, std::string("cannot open for appending: ") + std::strerror(errno));
  if (!ends_cleanly) Write("\n");
}

ResultsAppender::~ResultsAppender() {
  if (fd_ >= 0) ::close(fd_);
}

void ResultsAppender::Write(const std::string& bytes) {
  for (size_t off = 0; off < bytes.size();) {
    const ssize_t n = ::write(fd_, bytes.data() + off, bytes.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw core::DataError(file_, std::string("cannot write a result: ") + std::strerror(errno));
    off += size_t(n);
  }
  if (::fdatasync(fd_) != 0 && errno != EINVAL && errno != EROFS)
    throw core::DataError(file_, std::string("cannot write a result: ") + std::strerror(errno));
}

void ResultsAppender::Append(const std::string& line) { Write(line + "\n"); }

}  // namespace toponav::experiments
