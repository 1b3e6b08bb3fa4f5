#include "core/error.h"

namespace toponav::core {

ConfigError::ConfigError(const std::string& file, const std::string& key, const std::string& value,
                         const std::string& problem)
    : Error(file + ": " + key + " = '" + value + "': " + problem),
      file_(file),
      key_(key),
      value_(value),
      problem_(problem) {}

DataError::DataError(const std::string& file, const std::string& problem)
    : Error(file + ": " + problem), file_(file) {}

void ThrowInternal(const char* file, int line, const std::string& message) {
  throw InternalError(std::string(file) + ":" + std::to_string(line) + ": " + message);
}

}  // namespace toponav::core
