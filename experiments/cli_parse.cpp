#include "experiments/cli_parse.h"

#include <cmath>
#include <sstream>

#include "core/error.h"

namespace toponav::experiments {

namespace {

// Decimal digits only, at most 'max'.
bool ParseUnsigned(const std::string& text, uint64_t max, uint64_t* out) {
  if (text.empty() || text.size() > 20) return false;
  uint64_t v = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return false;
    const uint64_t d = uint64_t(c - '0');
    if (v > (max - d) / 10) return false;  // v * 10 + d > max
    v = v * 10 + d;
  }
  *out = v;
  return true;
}

std::string SeedRange() { return "[0, " + std::to_string(kMaxSeed) + "]"; }

}  // namespace

uint64_t ParseSeed(const std::string& text, const std::string& option) {
  uint64_t v = 0;
  if (!ParseUnsigned(text, kMaxSeed, &v))
    throw core::ConfigError("<command line>", option, text, "expected a whole number in " + SeedRange());
  return v;
}

std::vector<uint64_t> ParseSeeds(const std::string& text, const std::string& option) {
  const auto dash = text.find('-');
  uint64_t a = 0, b = 0;
  const bool ok = dash == std::string::npos ? ParseUnsigned(text, kMaxSeed, &a) && (b = a, true)
                                            : ParseUnsigned(text.substr(0, dash), kMaxSeed, &a) &&
                                                  ParseUnsigned(text.substr(dash + 1), kMaxSeed, &b);
  if (!ok || b < a || b - a >= 1000000)
    throw core::ConfigError("<command line>", option, text,
                            "expected N or A-B with A <= B, at most a million seeds, each in " + SeedRange());
  std::vector<uint64_t> seeds;
  for (uint64_t s = a; s <= b; ++s) seeds.push_back(s);
  return seeds;
}

void ParseShard(const std::string& text, int* index, int* count) {
  const auto slash = text.find('/');
  uint64_t i = 0, n = 0;
  if (slash == std::string::npos || !ParseUnsigned(text.substr(0, slash), 100000, &i) ||
      !ParseUnsigned(text.substr(slash + 1), 100000, &n) || n < 1 || i >= n)
    throw core::ConfigError("<command line>", "--shard", text, "expected i/N with 0 <= i < N <= 100000");
  *index = int(i);
  *count = int(n);
}

core::Pose2 ParsePose(const std::string& text) {
  core::Pose2 p;
  char c1 = 0, c2 = 0;
  std::istringstream is(text);
  if (!(is >> p.x >> c1 >> p.y >> c2 >> p.yaw) || c1 != ',' || c2 != ',' || !is.eof() || !std::isfinite(p.x) ||
      !std::isfinite(p.y) || !std::isfinite(p.yaw))
    throw core::ConfigError("<command line>", "--pose", text, "expected x,y,yaw (finite numbers, yaw in radians)");
  return p;
}

}  // namespace toponav::experiments
