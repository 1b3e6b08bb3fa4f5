#pragma once
// The error policy of toponav (every layer follows it):
//  - assert(): programmer-only invariants inside hot loops (compiled out in Release).
//  - TOPONAV_CHECK(cond, msg): always on; throws InternalError naming file and line.
//  - ConfigError: a bad configuration (YAML or command line); names the file, the key path and the value.
//  - DataError: bad input data (world file, model file, dataset); names the file and the problem.
//  - Expected outcomes (no path, nothing left to explore) are values, never exceptions or NaN sentinels.
// A batch runner catches these per trial, records the message and carries on; nothing aborts the process.
#include <sstream>
#include <stdexcept>
#include <string>

namespace toponav::core {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ConfigError : public Error {
 public:
  // 'file' is the config file (or "<command line>"), 'key' the dotted key path, 'value' the offending value.
  ConfigError(const std::string& file, const std::string& key, const std::string& value, const std::string& problem);
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& value() const { return value_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, key_, value_, problem_;
};

class DataError : public Error {
 public:
  DataError(const std::string& file, const std::string& problem);
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

class InternalError : public Error {
 public:
  using Error::Error;
};

[[noreturn]] void ThrowInternal(const char* file, int line, const std::string& message);

}  // namespace toponav::core

#define TOPONAV_CHECK(cond, msg)                                                         \
  do {                                                                                   \
    if (!(cond)) {                                                                       \
      std::ostringstream toponav_check_os_;                                              \
      toponav_check_os_ << "check failed: " #cond ": " << msg;                         \
      ::toponav::core::ThrowInternal(__FILE__, __LINE__, toponav_check_os_.str());       \
    }                                                                                    \
  } while (false)
