#pragma once
// Strict parsing of the command line's values: no wrap-around, no trailing junk; errors are
// core::ConfigError("<command line>", option, value, what is accepted).
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "core/rng.h"

namespace toponav::experiments {

using core::kMaxSeed;

// A seed: decimal digits only, at most kMaxSeed.
uint64_t ParseSeed(const std::string& text, const std::string& option = "--seed");
// "N" or "A-B" (inclusive, at most a million seeds).
std::vector<uint64_t> ParseSeeds(const std::string& text, const std::string& option = "--seeds");
// "i/N": shard i of N, 0 <= i < N <= 100000.
void ParseShard(const std::string& text, int* index, int* count);
// "x,y,yaw": finite numbers (world units, radians).
core::Pose2 ParsePose(const std::string& text);

}  // namespace toponav::experiments
