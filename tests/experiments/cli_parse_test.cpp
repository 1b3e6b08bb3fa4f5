#include "experiments/cli_parse.h"

#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"

namespace toponav::experiments {
namespace {

std::string KeyOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const core::ConfigError& e) {
    return e.key();
  }
  return "accepted";
}

TEST(CliParse, SeedsAreWholeNumbersThatNeverWrap) {
  EXPECT_EQ(ParseSeed("0"), 0u);
  EXPECT_EQ(ParseSeed("10042"), 10042u);
  EXPECT_EQ(ParseSeed(std::to_string(kMaxSeed)), kMaxSeed);
  for (const std::string& bad :
       std::vector<std::string>{"-1", "+1", " 1", "1 ", "12abc", "", "18446744073709551616", "18446744073709551615",
                                std::to_string(kMaxSeed + 1), "1e3", "0x10"})
    EXPECT_EQ(KeyOf([&] { ParseSeed(bad); }), "--seed") << bad;
  EXPECT_EQ(ParseSeeds("5-7"), (std::vector<uint64_t>{5, 6, 7}));
  EXPECT_EQ(ParseSeeds("9"), std::vector<uint64_t>{9});
  for (const std::string bad : {"7-5", "3-4abc", "-3", "3-", "1-2000000", "1--2"})
    EXPECT_EQ(KeyOf([&] { ParseSeeds(bad); }), "--seeds") << bad;
}

TEST(CliParse, ShardsAreIOfNWithIBelowN) {
  int i = -1, n = -1;
  ParseShard("1/4", &i, &n);
  EXPECT_EQ(i, 1);
  EXPECT_EQ(n, 4);
  for (const std::string bad : {"1/2/3", "2/2", "-1/2", "1/0", "1", "a/b", "1/ 2", "0/100001"})
    EXPECT_EQ(KeyOf([&] { ParseShard(bad, &i, &n); }), "--shard") << bad;
}

TEST(CliParse, PosesAreThreeFiniteNumbers) {
  const core::Pose2 p = ParsePose("1.5,-2,0.3");
  EXPECT_EQ(p.x, 1.5);
  EXPECT_EQ(p.y, -2.0);
  EXPECT_EQ(p.yaw, 0.3);
  for (const std::string bad : {"1,2", "1,2,3,4", "nan,1,2", "1,inf,0", "1,2,3x", "garbage"})
    EXPECT_EQ(KeyOf([&] { ParsePose(bad); }), "--pose") << bad;
}

}  // namespace
}  // namespace toponav::experiments
