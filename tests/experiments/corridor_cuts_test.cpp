#include "experiments/corridor_cuts.h"

#include <gtest/gtest.h>

namespace toponav::experiments {
namespace {

// A corridor 100 long and 14 wide (a guided maze's width).
core::World Corridor() {
  core::World w;
  w.boundary = {{0, 0}, {100, 0}, {100, 14}, {0, 14}};
  w.bounds = {{0, 0}, {100, 14}};
  return w;
}

TEST(FreeSpaceRegions, AWallAcrossTheCorridorCutsIt) {
  const FreeSpaceRegions regions(Corridor(), 1.0, 100.0);
  EXPECT_EQ(regions.Count({}), 1);
  EXPECT_EQ(regions.Count({{{50, 0}, {50, 14}}}), 2);
  EXPECT_TRUE(regions.Cuts({{50, 0}, {50, 14}}));
  EXPECT_TRUE(regions.Cuts({{50, -3}, {52, 17}})) << "slanted, ends inside the walls";
}

TEST(FreeSpaceRegions, AGapNarrowerThanTheAgentIsClosed) {
  const FreeSpaceRegions regions(Corridor(), 1.0, 100.0);
  EXPECT_TRUE(regions.Cuts({{50, 0}, {50, 12.5}})) << "1.5 left for a disc of diameter 2";
  EXPECT_FALSE(regions.Cuts({{50, 0}, {50, 10}})) << "4 left";
}

TEST(FreeSpaceRegions, AWallJuttingIntoTheCorridorDoesNotCutIt) {
  const FreeSpaceRegions regions(Corridor(), 1.0, 100.0);
  EXPECT_FALSE(regions.Cuts({{40, 0}, {46, 5.5}}));
  EXPECT_FALSE(regions.Cuts({{30, 7}, {70, 7}})) << "along the middle: round either end";
}

TEST(FreeSpaceRegions, ASmallPocketCutOffDoesNotCount) {
  const FreeSpaceRegions regions(Corridor(), 1.0, 100.0);
  EXPECT_FALSE(regions.Cuts({{4, 0}, {4, 14}})) << "the pocket behind it is 4 x 14";
  EXPECT_TRUE(FreeSpaceRegions(Corridor(), 1.0, 20.0).Cuts({{4, 0}, {4, 14}}));
}

}  // namespace
}  // namespace toponav::experiments
