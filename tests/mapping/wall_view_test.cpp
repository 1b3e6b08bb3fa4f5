#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/rng.h"
#include "mapping/mapping.h"

namespace toponav::mapping {
namespace {

using core::Detection;
using core::Vec2;

Detection Det(const core::Pose2& pose, Vec2 p, core::VertexLabel label) {
  Detection d;
  d.range = core::Distance(pose.position(), p);
  d.bearing = core::WrapAngle(std::atan2(p.y - pose.y, p.x - pose.x) - pose.yaw);
  d.polar = {0.3 * 0.3, 0, 0.02 * 0.02};
  d.labels = core::OneHot(label);
  return d;
}

// Two corners (0, 0) and (10, 0) seen only edge-on, from points on the line through them: a wall between
// them and a doorway in it look the same from there.
// Both detected with 'label' each time.
std::unique_ptr<Mapper> EdgeOnPairMapper(double min_view_angle, core::VertexLabel label) {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-30, -10}, {20, 10}};
  o.defer_to_mcmc = false;
  o.wall_min_view_angle = min_view_angle;
  auto m = std::make_unique<Mapper>(o);
  for (int i = 0; i < 12; ++i) {
    const core::Pose2 pose{-20.0 + i, 0.1 * (i % 3), 0.0};
    core::Observation z;
    z.pose = pose;
    z.detections = {Det(pose, {0, 0}, label), Det(pose, {10, 0}, label)};
    std::sort(z.detections.begin(), z.detections.end(), [](auto& a, auto& b) { return a.bearing < b.bearing; });
    m->AddObservation(z);
  }
  return m;
}

MapView EdgeOnPair(double min_view_angle) {
  return EdgeOnPairMapper(min_view_angle, core::VertexLabel::kCorner)->View();
}

TEST(WallEvidence, PairsSeenEdgeOnGiveNoEvidenceAboveTheMinimumViewAngle) {
  const MapView reference = EdgeOnPair(0.0);
  ASSERT_EQ(reference.vertices.size(), 2u);
  EXPECT_EQ(reference.walls.size(), 1u) << "the reference counts every pair";
  const MapView view = EdgeOnPair(0.06);
  ASSERT_EQ(view.vertices.size(), 2u);
  EXPECT_TRUE(view.walls.empty()) << "bearings less than 0.06 apart say nothing about a wall";
}

TEST(Posterior, PairsSeenEdgeOnAddNoEdgeTermAboveTheMinimumViewAngle) {
  // Labels saying "a wall runs on" or "nothing runs on", and no wall between them (no evidence from pairs
  // seen edge-on): the edge terms would charge the first for the missing wall in every observation; what
  // the wall evidence ignores, the posterior must not count either.
  EXPECT_DOUBLE_EQ(EdgeOnPairMapper(0.06, core::VertexLabel::kCorner)->LogPosterior(),
                   EdgeOnPairMapper(0.06, core::VertexLabel::kPoint)->LogPosterior());
}

TEST(Mapper, LogPosteriorIfScoresOtherInclusionsWithoutChangingTheMap) {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-1, -1}, {11, 11}};
  Mapper m(o);
  core::Rng rng(3);
  for (int i = 0; i < 20; ++i) {
    const core::Pose2 pose{5, 5, 0.1 * i};
    core::Observation z;
    z.pose = pose;
    for (Vec2 c : {Vec2{0, 0}, Vec2{10, 0}, Vec2{10, 10}, Vec2{0, 10}})
      z.detections.push_back(Det(pose, c, core::VertexLabel::kCorner));
    std::sort(z.detections.begin(), z.detections.end(), [](auto& a, auto& b) { return a.bearing < b.bearing; });
    m.AddObservation(z);
  }
  m.SampleMostLikelyMap(rng);
  const double now = m.LogPosterior();
  EXPECT_DOUBLE_EQ(m.LogPosteriorIf({}), now);
  EXPECT_LT(m.LogPosteriorIf({{0, false}}), now) << "leaving a seen corner out costs";
  EXPECT_DOUBLE_EQ(m.LogPosterior(), now) << "the map itself is unchanged";
  EXPECT_EQ(m.View().vertices.size(), 4u);
}

}  // namespace
}  // namespace toponav::mapping
