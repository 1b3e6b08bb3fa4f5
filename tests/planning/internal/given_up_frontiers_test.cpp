#include "planning/internal/given_up_frontiers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace toponav::planning {
namespace {

mapping::Frontier MakeFrontier(int id, std::vector<core::Vec2> points) {
  mapping::Frontier f;
  f.id = id;
  f.points = std::move(points);
  f.midpoint = (f.points.front() + f.points.back()) * 0.5;
  return f;
}

TEST(GivenUpFrontiers, TheSamePlaceUnderANewIdStaysGivenUp) {
  GivenUpFrontiers g(3.0);
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 10}}), MakeFrontier(5, {{20, 0}, {20, 10}})});
  EXPECT_TRUE(g.Contains(4));
  EXPECT_FALSE(g.Contains(5)) << "only the frontier named is given up";
  // The map re-creates the wall piece under id 9 (shifted by a unit); an opening 10 units away is new, and
  // so is a frontier that runs on past the given-up piece (an opening beside it) though its middle is close.
  g.Update({MakeFrontier(9, {{1, 2}, {1, 12}}), MakeFrontier(10, {{10, 0}, {10, 10}}),
            MakeFrontier(11, {{0, -8}, {0, 18}})});
  EXPECT_TRUE(g.Contains(9));
  EXPECT_FALSE(g.Contains(10));
  EXPECT_FALSE(g.Contains(11));
  GivenUpFrontiers by_id(0.0);
  by_id.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 10}})});
  by_id.Update({MakeFrontier(9, {{1, 2}, {1, 12}})});
  EXPECT_FALSE(by_id.Contains(9)) << "reach 0: by id only";
}

TEST(GivenUpFrontiers, OnlyThePartProbedOfALongFrontierStaysGivenUpByPlace) {
  // A 100-unit frontier along an unmapped wall, probed near its lower end (the agent stood at (1, 10)).
  GivenUpFrontiers g(3.0, 20.0);
  const core::Vec2 probed{1, 10};
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &probed);
  EXPECT_TRUE(g.Contains(4));
  // Later the map splits it: the piece where the agent stood stays given up, an opening at the far end
  // (never looked through) is a frontier again.
  g.Update({MakeFrontier(7, {{0, 5}, {0, 25}}), MakeFrontier(8, {{0, 70}, {0, 90}})});
  EXPECT_TRUE(g.Contains(7));
  EXPECT_FALSE(g.Contains(8));
  // Probed at its middle: only the middle stays given up; openings towards either end are frontiers again.
  GivenUpFrontiers middle(3.0, 20.0);
  const core::Vec2 at_middle{1, 50};
  middle.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &at_middle);
  middle.Update({MakeFrontier(7, {{0, 35}, {0, 65}}), MakeFrontier(8, {{0, 5}, {0, 25}}),
                 MakeFrontier(9, {{0, 75}, {0, 95}})});
  EXPECT_TRUE(middle.Contains(7));
  EXPECT_FALSE(middle.Contains(8));
  EXPECT_FALSE(middle.Contains(9));
  // Without a probe radius the whole polyline counts.
  GivenUpFrontiers whole(3.0, 0.0);
  whole.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &probed);
  whole.Update({MakeFrontier(8, {{0, 70}, {0, 90}})});
  EXPECT_TRUE(whole.Contains(8));
}

TEST(GivenUpFrontiers, AFrontierGivenUpWhereAgentsStoodRecordsOnlyThePartNearThatPoint) {
  GivenUpFrontiers g(3.0, 20.0);
  const core::Vec2 at{1, 50};
  g.GiveUp(5, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &at);  // no frontier 5 there: nothing recorded
  EXPECT_TRUE(g.probed().empty());
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &at);
  EXPECT_TRUE(g.Contains(4));
  EXPECT_EQ(g.given_up(), 2);
  ASSERT_EQ(g.probed().size(), 1u);
  EXPECT_NEAR(g.probed()[0].a.y, 50.0 - std::sqrt(399.0), 1e-9);  // the part within 20 of (1, 50)
  EXPECT_NEAR(g.probed()[0].b.y, 50.0 + std::sqrt(399.0), 1e-9);
}

TEST(GivenUpFrontiers, AFrontierProbedInPartKeepsItsLongestOtherPiece) {
  // Given up where the agent stood at (1, 40): the part of the long frontier within 20 of it was probed, and
  // the frontier keeps its longer other piece (from 3 past the probed part, y 63, to its end at y 100); a
  // frontier lying wholly near the probed part is dropped, one far from it is as it was.
  GivenUpFrontiers g(3.0, 20.0);
  const core::Vec2 at{1, 40};
  mapping::Frontier along = MakeFrontier(4, {{0, 0}, {0, 100}});
  along.front_turn = along.back_turn = 0.3;  // both ends where the chain was cut at a gentle turn
  g.GiveUp(4, {along}, &at);
  const mapping::Frontier far = MakeFrontier(7, {{20, 0}, {20, 100}});
  const std::vector<mapping::Frontier> cut = g.Unprobed({along, MakeFrontier(6, {{1, 25}, {1, 55}}), far});
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_EQ(cut[0].id, 4);
  ASSERT_EQ(cut[0].points.size(), 2u);
  EXPECT_NEAR(cut[0].points.front().y, 40.0 + std::sqrt(399.0) + 3.0, GivenUpFrontiers::kUnprobedSpacing);
  EXPECT_NEAR(cut[0].points.back().y, 100.0, 1e-9);
  EXPECT_NEAR(cut[0].length, cut[0].points.back().y - cut[0].points.front().y, 1e-9);
  EXPECT_NEAR(cut[0].midpoint.y, 0.5 * (cut[0].points.front().y + 100.0), 1e-9);
  EXPECT_EQ(cut[0].front_turn, 0.0) << "the cut end is a true end";
  EXPECT_EQ(cut[0].back_turn, 0.3) << "the other end is as it was";
  EXPECT_EQ(cut[1].id, 7);
  EXPECT_EQ(cut[1].points.size(), far.points.size());
  EXPECT_EQ(cut[1].midpoint.y, far.midpoint.y);
}

TEST(GivenUpFrontiers, APieceOfABentFrontierKeepsItsCorner) {
  // Probed near its start at (1, 10): the part up to 20 from there is cut, 3 more, and the piece runs from
  // (0, 33) round the corner at (0, 50) to the end at (50, 50).
  GivenUpFrontiers g(3.0, 20.0);
  const core::Vec2 at{1, 10};
  const mapping::Frontier bent = MakeFrontier(4, {{0, 0}, {0, 50}, {0, 50}, {50, 50}});  // a repeated point
  g.GiveUp(4, {bent}, &at);
  const std::vector<mapping::Frontier> cut = g.Unprobed({bent});
  ASSERT_EQ(cut.size(), 1u);
  ASSERT_EQ(cut[0].points.size(), 3u);
  EXPECT_NEAR(cut[0].points[0].y, 10.0 + std::sqrt(399.0) + 3.0, GivenUpFrontiers::kUnprobedSpacing);
  EXPECT_EQ(cut[0].points[1].y, 50.0);
  EXPECT_EQ(cut[0].points[2].x, 50.0);
  EXPECT_NEAR(cut[0].length, 50.0 - cut[0].points[0].y + 50.0, 1e-9);
  EXPECT_EQ(cut[0].midpoint.y, 50.0) << "halfway along the piece: past its corner";
  EXPECT_NEAR(cut[0].midpoint.x, cut[0].length / 2 - (50.0 - cut[0].points[0].y), 1e-9);
}

TEST(GivenUpFrontiers, AFrontierThatGrowsWellPastWhereItWasGivenUpIsTakenBackOnce) {
  GivenUpFrontiers g(3.0, 20.0);
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 20}})});
  // Wobbling by a few units: still given up.
  EXPECT_TRUE(g.Update({MakeFrontier(4, {{2, -4}, {2, 24}})}).empty());
  EXPECT_TRUE(g.Contains(4));
  // Grown into a long opening under the same id: taken back.
  EXPECT_EQ(g.Update({MakeFrontier(4, {{0, 0}, {0, 75}})}), std::vector<int>{4});
  EXPECT_FALSE(g.Contains(4));
  // One given up by place (a new id where the probed part lay) is taken back when it grows, too.
  g.Update({MakeFrontier(6, {{1, 2}, {1, 18}})});
  EXPECT_TRUE(g.Contains(6));
  EXPECT_EQ(g.Update({MakeFrontier(6, {{1, 2}, {1, 60}})}), std::vector<int>{6});
  EXPECT_FALSE(g.Contains(6));
  // Given up again and grown again: it stays given up (no back and forth).
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 20}})});
  EXPECT_TRUE(g.Update({MakeFrontier(4, {{0, 0}, {0, 75}})}).empty());
  EXPECT_TRUE(g.Contains(4));
}

TEST(GivenUpFrontiers, GivingAFrontierUpAgainWhereTheAgentStoodElsewhereRecordsThatPartToo) {
  GivenUpFrontiers g(3.0, 10.0);
  const mapping::Frontier along = MakeFrontier(4, {{0, 0}, {0, 100}});
  const core::Vec2 first{1, 20}, second{1, 80};
  g.GiveUp(4, {along}, &first);
  g.GiveUp(4, {along}, &second);
  EXPECT_EQ(g.given_up(), 1) << "one frontier";
  ASSERT_EQ(g.probed().size(), 2u);
  const std::vector<mapping::Frontier> cut =
      g.Unprobed({MakeFrontier(6, {{1, 75}, {1, 85}}), MakeFrontier(7, {{1, 45}, {1, 55}})});
  ASSERT_EQ(cut.size(), 1u) << "the second place is probed as well";
  EXPECT_EQ(cut[0].id, 7) << "not the stretch between them";
  EXPECT_EQ(cut[0].points.front().y, 45.0) << "as it was";
}

TEST(GivenUpFrontiers, ClearTakesEveryFrontierBack) {
  GivenUpFrontiers g(3.0);
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 10}})});
  g.Clear();
  EXPECT_FALSE(g.Contains(4));
  EXPECT_EQ(g.given_up(), 0);
  g.Update({MakeFrontier(9, {{1, 2}, {1, 12}})});
  EXPECT_FALSE(g.Contains(9)) << "the place is forgotten too";
}

}  // namespace
}  // namespace toponav::planning
