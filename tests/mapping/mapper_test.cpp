#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "core/error.h"
#include "core/rng.h"
#include "mapping/mapping.h"
#include "mapping/polygon_set.h"
#include "tests/testing/square_room.h"
#include "tests/testing/worlds.h"

namespace toponav::mapping {
namespace {

using core::Detection;
using core::Observation;
using core::Vec2;

using testing::Det;
using testing::Obs;
using testing::SquareCorners;
using testing::SquareFromInside;
using testing::SquareOptions;

TEST(Mapper, SquareSeenFromInsideYieldsFourVerticesAndFourWalls) {
  Mapper m(SquareOptions());
  core::Rng rng(1);
  for (int i = 0; i < 30; ++i) m.AddObservation(SquareFromInside({5, 5, 0.1 * i}));
  m.SampleMostLikelyMap(rng);
  const MapView view = m.View();
  EXPECT_EQ(view.vertices.size(), 4u);
  EXPECT_EQ(view.walls.size(), 4u);
  EXPECT_EQ(m.PotentialVertices().size(), 4u);
  EXPECT_NEAR(view.known_area(), 100.0, 1e-6);
  EXPECT_TRUE(view.frontiers.empty()) << "a closed room has no frontier";
  EXPECT_LT(m.LogPosterior(), 0.0);
}

// The square room seen from inside, each observation with one false detection somewhere on the wall y = 0
// (a new place every time, so none gathers enough detections to become a map vertex).
// 30 observations from poses drifting through the room (detections from 'seen'), MCMC every 5 and at the end.
MapView DriveThroughSquare(const MapperOptions& o, uint64_t seed,
                           const std::function<std::vector<Detection>(int, const core::Pose2&)>& seen) {
  Mapper m(o);
  core::Rng rng(seed);
  for (int i = 0; i < 30; ++i) {
    const core::Pose2 pose{5 + 0.03 * i, 5, 0.05 * i};
    m.AddObservation(Obs(pose, seen(i, pose)));
    if (i % 5 == 4) m.SampleMostLikelyMap(rng);
  }
  m.SampleMostLikelyMap(rng);
  return m.View();
}

TEST(Mapper, ContactEvidenceMakesTheWallAnAgentPressedAgainstCertain) {
  Mapper m(SquareOptions());
  core::Rng rng(1);
  for (int i = 0; i < 30; ++i) m.AddObservation(SquareFromInside({5, 5, 0.1 * i}));
  m.SampleMostLikelyMap(rng);
  const MapView before = m.View();
  ASSERT_EQ(before.walls.size(), 4u);
  for (const auto& w : before.walls) EXPECT_FALSE(w.certain) << "sight alone never makes a wall certain";
  EXPECT_FALSE(m.AddContact({{5, 5}, {6, 5}, 2.0})) << "no wall within reach toward (6, 5)";
  EXPECT_FALSE(m.AddContact({{5, 5}, {5, 5}, 2.0})) << "no way: no contact";
  // Pressed east from (9, 5): the wall x = 10 lies 1 ahead.
  EXPECT_TRUE(m.AddContact({{9, 5}, {12, 5}, 2.0}));
  const MapView after = m.View();
  ASSERT_EQ(after.walls.size(), 4u);
  int certain = 0;
  for (const auto& w : after.walls) {
    if (!w.certain) continue;
    ++certain;
    EXPECT_EQ(w.probability, 1.0);
    EXPECT_NEAR(w.pa.x, 10.0, 0.5) << "the east wall";
    EXPECT_NEAR(w.pb.x, 10.0, 0.5);
  }
  EXPECT_EQ(certain, 1);
}

MapView SquareWithFalseDetectionsOnAWall(double on_segment_tolerance) {
  MapperOptions o = SquareOptions();
  o.wall_on_segment_tolerance = on_segment_tolerance;
  return DriveThroughSquare(o, 5, [](int i, const core::Pose2& pose) {
    std::vector<Detection> d = SquareCorners(pose);
    d.push_back(Det(pose, {1.0 + 0.27 * i, 0.0}, core::VertexLabel::kPoint));
    return d;
  });
}

bool HasWall(const MapView& view, Vec2 a, Vec2 b) {
  for (const auto& w : view.walls)
    if ((core::Distance(w.pa, a) < 0.5 && core::Distance(w.pb, b) < 0.5) ||
        (core::Distance(w.pa, b) < 0.5 && core::Distance(w.pb, a) < 0.5))
      return true;
  return false;
}

// A wall's end B = (2, 20) seen edge-on from (0, 0), with a vertex C detected just past it: from there C comes
// before B in bearing, so the evidence joins A = (2, -20) and C straight past B; from (-10, 0) B comes first.
MapView WallAndAVertexPastItsEnd(double past_vertex_tolerance) {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-20, -30}, {20, 40}};
  o.defer_to_mcmc = false;
  o.wall_past_vertex_tolerance = past_vertex_tolerance;
  Mapper m(o);
  for (int i = 0; i < 8; ++i) {
    const core::Pose2 pose{i % 2 ? -10.0 : 0.0, 0.0, 0.0};
    std::vector<Detection> d;
    for (Vec2 p : {Vec2{2, -20}, Vec2{2, 20}, Vec2{3, 26}}) d.push_back(Det(pose, p, core::VertexLabel::kCorner));
    m.AddObservation(Obs(pose, d));
  }
  return m.View();
}

TEST(Mapper, OfTwoWallsFromACornerTheOnePassingTheOthersEndIsNotDrawnWhenAsked) {
  const MapView both = WallAndAVertexPastItsEnd(0.0);
  ASSERT_EQ(both.vertices.size(), 3u);
  EXPECT_TRUE(HasWall(both, {2, -20}, {3, 26}));
  const MapView drawn = WallAndAVertexPastItsEnd(2.0);
  EXPECT_FALSE(HasWall(drawn, {2, -20}, {3, 26})) << "it runs within 0.9 of the wall's end (2, 20)";
  EXPECT_TRUE(HasWall(drawn, {2, -20}, {2, 20}));
  EXPECT_TRUE(HasWall(drawn, {2, 20}, {3, 26}));
  EXPECT_EQ(drawn.walls.size(), both.walls.size() - 1);
}

// A corner B = (18, -70) between a wall to A = (48, -70) and a wall to C = (18, -18).  From (6, -78) the
// sensor sees all three; from (6, -70.6), looking along B-A edge-on, A shows just past B (B lies 0.3 from the
// sight line to A) and the sensor misses B -- or, 'b_out_of_order', detects it at (18, -70.6), on A's far side
// in bearing -- so A and C come next to each other in bearing.
MapView CornerMissedEdgeOn(double front_tolerance, bool b_out_of_order = false) {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-10, -90}, {60, -10}};
  o.defer_to_mcmc = false;
  o.wall_front_vertex_tolerance = front_tolerance;
  Mapper m(o);
  const Vec2 a{48, -70}, b{18, -70}, c{18, -18};
  for (int i = 0; i < 3; ++i) {
    const core::Pose2 pose{6, -78, 0};
    m.AddObservation(Obs(pose, {Det(pose, a, core::VertexLabel::kCorner), Det(pose, b, core::VertexLabel::kCorner),
                                Det(pose, c, core::VertexLabel::kCorner)}));
  }
  for (int i = 0; i < 5; ++i) {
    const core::Pose2 pose{6, -70.6, 0};
    std::vector<core::Detection> d{Det(pose, a, core::VertexLabel::kCorner), Det(pose, c, core::VertexLabel::kCorner)};
    if (b_out_of_order) d.push_back(Det(pose, {18, -70.6}, core::VertexLabel::kCorner));
    m.AddObservation(Obs(pose, d));
  }
  return m.View();
}

TEST(Mapper, ASightingThatMissedAMapVertexInFrontOfTwoDetectionsCountsForNoWallWhenAsked) {
  for (const bool out_of_order : {false, true}) {
    SCOPED_TRACE(out_of_order ? "B detected on A's far side in bearing" : "B missed");
    const MapView reference = CornerMissedEdgeOn(0.0, out_of_order);
    ASSERT_EQ(reference.vertices.size(), 3u);
    EXPECT_TRUE(HasWall(reference, {48, -70}, {18, -18})) << "the wall across the solid corner";
    const MapView damped = CornerMissedEdgeOn(1.0, out_of_order);
    EXPECT_FALSE(HasWall(damped, {48, -70}, {18, -18}));
    EXPECT_TRUE(HasWall(damped, {48, -70}, {18, -70}));
    if (out_of_order) continue;  // B-C: A lies between them in bearing in the edge-on views (damped either way)
    EXPECT_TRUE(HasWall(damped, {18, -70}, {18, -18}));
    EXPECT_EQ(damped.walls.size(), 2u);
  }
}

TEST(Mapper, FalseDetectionsOnAWallDoNotHideIt) {
  const MapView view = SquareWithFalseDetectionsOnAWall(2.0);
  EXPECT_EQ(view.vertices.size(), 4u);
  EXPECT_TRUE(HasWall(view, {0, 0}, {10, 0}));
  EXPECT_EQ(view.walls.size(), 4u);
  EXPECT_TRUE(view.frontiers.empty());
}

TEST(Mapper, CountingEveryDetectionBetweenCornersLosesTheWall) {
  // The reference's rule (tolerance 0): each detection between two corners damps their wall's evidence.
  const MapView view = SquareWithFalseDetectionsOnAWall(0.0);
  EXPECT_FALSE(HasWall(view, {0, 0}, {10, 0}));
  EXPECT_EQ(view.walls.size(), 3u);
}

TEST(Mapper, MappedDoorwayJambsOnTheWallLineKeepTheDoorwayOpen) {
  // The square room with a doorway from (4,0) to (6,0): the jambs lie on the line between the corners
  // (0,0) and (10,0), whose labels say a wall runs on; once the jambs are mapped they still damp that
  // pair's evidence, so no wall closes the doorway.
  const MapView view = DriveThroughSquare(SquareOptions(), 6, [](int, const core::Pose2& pose) {
    std::vector<Detection> d = SquareCorners(pose);
    d.push_back(Det(pose, {4, 0}, core::VertexLabel::kLeftGap));   // no wall counter-clockwise (the doorway)
    d.push_back(Det(pose, {6, 0}, core::VertexLabel::kRightGap));  // no wall clockwise
    return d;
  });
  EXPECT_EQ(view.vertices.size(), 6u);
  EXPECT_TRUE(HasWall(view, {0, 0}, {4, 0}));
  EXPECT_TRUE(HasWall(view, {6, 0}, {10, 0}));
  EXPECT_FALSE(HasWall(view, {0, 0}, {10, 0})) << "a wall across the doorway";
  EXPECT_FALSE(HasWall(view, {4, 0}, {6, 0}));
  EXPECT_EQ(view.frontiers.size(), 1u) << "the doorway";
}

// The doorway from (4,0) to (6,0) again, but the far jamb's detections scatter along the doorway and the wall
// beyond it (never twice within the gate of one place, so it never gathers enough detections to be mapped),
// and the near jamb's label leans only 60 % towards "no wall counter-clockwise" (a jamb seen edge-on).
MapView DoorwayWithAnUnmappedFarJamb(bool both_ends, bool open_world = false) {
  MapperOptions o = SquareOptions();
  o.wall_past_detection_min = both_ends;
  if (open_world) o.open_region = core::Aabb2{{-20, -20}, {30, 30}};
  return DriveThroughSquare(o, 7, [](int i, const core::Pose2& pose) {
    std::vector<Detection> d = SquareCorners(pose);
    Detection near_jamb = Det(pose, {4, 0}, core::VertexLabel::kLeftGap);
    near_jamb.labels = {0.0, 0.4, 0.6, 0.0};  // P(no wall ccw) = 0.6
    d.push_back(near_jamb);
    d.push_back(Det(pose, {6.0 + 0.27 * (i % 15), 0.0}, core::VertexLabel::kRightGap));
    return d;
  });
}

TEST(Mapper, AWallPastAnUnmappedJambNeedsBothEndsToSayWall) {
  // Averaged, the near jamb (0.4 wall) and the far corner (1.0 wall) make 0.7: a wall across the doorway.
  const MapView averaged = DoorwayWithAnUnmappedFarJamb(false);
  EXPECT_TRUE(HasWall(averaged, {4, 0}, {10, 0}));
  // Both ends must say wall (the smaller, 0.4): the doorway stays open, and the wall up to the near jamb stays.
  const MapView view = DoorwayWithAnUnmappedFarJamb(true);
  EXPECT_EQ(view.vertices.size(), 5u);
  EXPECT_FALSE(HasWall(view, {4, 0}, {10, 0})) << "a wall across the doorway";
  EXPECT_TRUE(HasWall(view, {0, 0}, {4, 0}));
  EXPECT_FALSE(view.frontiers.empty()) << "the doorway";
  // Open worlds (buildings without doorways) keep the average.
  EXPECT_TRUE(HasWall(DoorwayWithAnUnmappedFarJamb(true, true), {4, 0}, {10, 0}));
}

// Doorway jambs (4,0) and (6,0) seen side by side with confident wrong labels: the near one says a wall runs on
// counter-clockwise (0.8), the far one leans only 55 % to "no wall clockwise".
MapView DoorwayWithWrongLabels(bool evidence_min, bool open_world) {
  MapperOptions o = SquareOptions();
  o.wall_evidence_min = evidence_min;
  if (open_world) o.open_region = core::Aabb2{{-20, -20}, {30, 30}};
  return DriveThroughSquare(o, 6, [](int, const core::Pose2& pose) {
    std::vector<Detection> d = SquareCorners(pose);
    Detection near_jamb = Det(pose, {4, 0}, core::VertexLabel::kLeftGap),
              far_jamb = Det(pose, {6, 0}, core::VertexLabel::kRightGap);
    near_jamb.labels = {0.0, 0.8, 0.2, 0.0};
    far_jamb.labels = {0.55, 0.45, 0.0, 0.0};
    d.push_back(near_jamb);
    d.push_back(far_jamb);
    return d;
  });
}

TEST(Mapper, WithWallEvidenceMinOneEndSayingGapKeepsADoorwayOpenInClosedWorlds) {
  EXPECT_TRUE(HasWall(DoorwayWithWrongLabels(false, false), {4, 0}, {6, 0}))
      << "averaged: 1 - (0.2 + 0.55) / 2 = 0.625";
  const MapView view = DoorwayWithWrongLabels(true, false);
  EXPECT_FALSE(HasWall(view, {4, 0}, {6, 0})) << "the smaller end: 0.45";
  EXPECT_TRUE(HasWall(view, {0, 0}, {4, 0}));
  EXPECT_TRUE(HasWall(DoorwayWithWrongLabels(true, true), {4, 0}, {6, 0})) << "open worlds keep the average";
}

// Detections of the corner (10,10) scattered around it, the first observation with a second (false) one
// 1.2 units away: how many detections the vertex born from the false one collects.
int DuplicateDetections(double count_bias) {
  MapperOptions o = SquareOptions();
  o.association_count_bias = count_bias;
  Mapper m(o);
  core::Rng rng(8);
  for (int i = 0; i < 40; ++i) {
    const core::Pose2 pose{5, 5, 0.0};
    std::vector<Detection> d{
        Det(pose, {10 + rng.Normal(0, 0.6), 10 + rng.Normal(0, 0.6)}, core::VertexLabel::kCorner, 1.0, 0.1)};
    if (i == 0) d.push_back(Det(pose, {10.0, 8.8}, core::VertexLabel::kPoint, 1.0, 0.1));
    m.AddObservation(Obs(pose, d));
  }
  const auto vs = m.PotentialVertices();
  EXPECT_EQ(vs.size(), 2u);
  return vs.size() == 2 ? std::min(vs[0].num_detections, vs[1].num_detections) : -1;
}

TEST(Mapper, DuplicateBornBesideAVertexStarves) {
  EXPECT_LE(DuplicateDetections(1.0), 3);
  EXPECT_GT(DuplicateDetections(0.0), 5) << "without the bias the duplicate takes a share (the failure it fixes)";
}

TEST(Mapper, TwoDetectionsOfOneObservationNeverJoinOneVertex) {
  Mapper m(SquareOptions());
  const core::Pose2 pose{0, 0, 0};
  m.AddObservation(Obs(pose, {Det(pose, {5, 0}, core::VertexLabel::kPoint, 1.0, 0.1)}));
  // Both new detections fall inside the gate of the one vertex: only one may join it.
  m.AddObservation(Obs(pose, {Det(pose, {5, 0.2}, core::VertexLabel::kPoint, 1.0, 0.1),
                              Det(pose, {5, -0.2}, core::VertexLabel::kPoint, 1.0, 0.1)}));
  const auto vs = m.PotentialVertices();
  ASSERT_EQ(vs.size(), 2u);
  EXPECT_EQ(vs[0].num_detections + vs[1].num_detections, 3);
}

TEST(Mapper, KalmanCovarianceShrinksWithRepeatedSightings) {
  Mapper m(SquareOptions());
  double last = 1e9;
  for (int i = 0; i < 10; ++i) {
    const core::Pose2 pose{2.0 + 0.3 * i, 1.0, 0.0};
    m.AddObservation(Obs(pose, {Det(pose, {9, 9}, core::VertexLabel::kCorner, 0.5, 0.05)}));
    const auto vs = m.PotentialVertices();
    ASSERT_EQ(vs.size(), 1u);
    const double trace = vs[0].covariance.xx + vs[0].covariance.yy;
    EXPECT_LT(trace, last);
    last = trace;
  }
}

TEST(Mapper, DistantDetectionStartsANewVertex) {
  Mapper m(SquareOptions());
  const core::Pose2 pose{0, 0, 0};
  m.AddObservation(Obs(pose, {Det(pose, {5, 0}, core::VertexLabel::kPoint)}));
  m.AddObservation(Obs(pose, {Det(pose, {5, 3}, core::VertexLabel::kPoint)}));  // far outside a 0.3/0.02 gate
  EXPECT_EQ(m.PotentialVertices().size(), 2u);
}

TEST(Mapper, BadInputIsRejectedAndLeavesTheMapUnchanged) {
  Mapper m(SquareOptions());
  const core::Pose2 pose{5, 5, 0};
  m.AddObservation(SquareFromInside(pose));
  const size_t before = m.PotentialVertices().size();
  Observation nan_range = SquareFromInside(pose);
  nan_range.detections[1].range = std::nan("");
  Observation bad_cov = SquareFromInside(pose);
  bad_cov.detections[2].polar = {1.0, 2.0, 1.0};  // determinant < 0
  Observation outside = SquareFromInside({50, 5, 0});
  for (const Observation& z : {nan_range, bad_cov, outside}) {
    EXPECT_THROW(m.AddObservation(z), core::DataError);
    EXPECT_EQ(m.PotentialVertices().size(), before);
  }
  EXPECT_EQ(m.View().num_observations, 1);
}

TEST(Mapper, FrontierIsSplitWhereItTurnsSharply) {
  auto frontiers = [](double split_angle) {
    MapperOptions o;
    o.frontier_split_angle = split_angle;
    Mapper m(o);
    core::Rng rng(5);
    for (int i = 0; i < 6; ++i) {
      const core::Pose2 pose{0.0, 0.0, 0.0};
      m.AddObservation(
          Obs(pose, {Det(pose, {10, 0}, core::VertexLabel::kPoint), Det(pose, {0, 10}, core::VertexLabel::kPoint),
                     Det(pose, {-10, 0}, core::VertexLabel::kPoint)}));
    }
    m.SampleMostLikelyMap(rng);
    return m.View().frontiers;
  };
  const auto whole = frontiers(0.0);
  ASSERT_EQ(whole.size(), 1u);
  const auto split = frontiers(1.0);
  ASSERT_EQ(split.size(), 3u);
  double total = 0;
  for (const auto& f : split) {
    EXPECT_GE(f.length, 8.0);
    total += f.length;
  }
  EXPECT_NEAR(total, whole[0].length, 1e-9);
  // The piece across the opening between A and B has its middle there, not at a corner.
  bool between_a_b = false;
  for (const auto& f : split) between_a_b = between_a_b || core::Distance(f.midpoint, {5, 5}) < 0.5;
  EXPECT_TRUE(between_a_b);
  // Every end of a piece is a cut, and records how sharply the ring turns there (90 degrees at B, 135 at A and C);
  // the unsplit ring's ends are not cuts.
  for (const auto& f : split) {
    EXPECT_GT(f.front_turn, 1.5);
    EXPECT_GT(f.back_turn, 1.5);
  }
  EXPECT_EQ(whole[0].front_turn, 0.0);
  EXPECT_EQ(whole[0].back_turn, 0.0);
}

// The closed end of a long corridor (walls y = 0 and y = 20, far end out of range): only the end's two corners
// are ever mapped; a spot on the wall y = 20 is detected in a third of the observations (the sensor's false
// positives on walls gather into such candidates), so the posterior leaves it out.
// With 'every_step', the view (known space, computed incrementally) is taken after every observation too.
MapView CorridorEndWithACandidateOnAWall(bool candidates, std::vector<MapVertex>* potential, bool every_step = false) {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-10, -10}, {300, 30}};
  o.known_space_candidates = candidates;
  Mapper m(o);
  core::Rng rng(7);
  for (int i = 0; i < 30; ++i) {
    const core::Pose2 pose{10 + 0.2 * i, 10, 0.0};
    std::vector<Detection> d{Det(pose, {0, 0}, core::VertexLabel::kCorner),
                             Det(pose, {0, 20}, core::VertexLabel::kCorner)};
    if (i % 3 == 0) d.push_back(Det(pose, {60, 20}, core::VertexLabel::kPoint));
    m.AddObservation(Obs(pose, d));
    if (i % 5 == 4) m.SampleMostLikelyMap(rng);
    if (every_step) m.View();
  }
  m.SampleMostLikelyMap(rng);
  *potential = m.PotentialVertices();
  return m.View();
}

TEST(Mapper, KnownSpaceReachesAWallCandidateThePosteriorLeavesOut) {
  std::vector<MapVertex> potential;
  const MapView with = CorridorEndWithACandidateOnAWall(true, &potential);
  ASSERT_EQ(with.vertices.size(), 2u) << "only the corridor end's corners are mapped";
  bool candidate = false;
  for (const auto& v : potential)
    candidate = candidate || (core::Distance(v.position, {60, 20}) < 1.0 && v.num_detections >= 3);
  ASSERT_TRUE(candidate) << "the spot on the wall has enough detections to be a candidate";
  const Vec2 in_front{50, 17};  // seen free: between the agent and the candidate on the wall
  auto known = [](const MapView& v, Vec2 p) { return v.known_set && v.known_set->Contains(p); };
  EXPECT_TRUE(known(with, in_front));
  const MapView without = CorridorEndWithACandidateOnAWall(false, &potential);
  EXPECT_FALSE(known(without, in_front)) << "the mapped corners alone bound known space by a chord";
  EXPECT_GT(with.known_area(), without.known_area() + 200.0);
  // Computed step by step (a vertex becomes a candidate after some observations saw it), the same known space.
  const MapView stepwise = CorridorEndWithACandidateOnAWall(true, &potential, true);
  EXPECT_TRUE(known(stepwise, in_front));
  EXPECT_NEAR(stepwise.known_area(), with.known_area(), 1e-6 * with.known_area());
}

// The square room; from observation 5 on, a vertex X at (9, 5) inside it is detected too, so it becomes a
// candidate and MCMC takes it into the map.  The first observations saw X's place without detecting it: once
// X is in the map, their hypothetical observations hold it.  The known space must not depend on whether the
// view was taken on the way (incrementally) or only at the end.
double RoomWithALateVertexKnownArea(bool every_step) {
  Mapper m(SquareOptions());
  core::Rng rng(9);
  for (int i = 0; i < 30; ++i) {
    const core::Pose2 pose{5, 5 + 0.02 * i, 0.0};
    std::vector<Detection> d;  // labels without walls: only the vertices matter here
    for (Vec2 c : {Vec2{0, 0}, Vec2{10, 0}, Vec2{10, 10}, Vec2{0, 10}})
      d.push_back(Det(pose, c, core::VertexLabel::kPoint));
    if (i >= 5) d.push_back(Det(pose, {9, 5}, core::VertexLabel::kPoint));
    m.AddObservation(Obs(pose, d));
    if (i % 5 == 4) m.SampleMostLikelyMap(rng);
    if (every_step) m.View();
  }
  const MapView view = m.View();
  bool mapped = false;
  for (const auto& v : view.vertices) mapped = mapped || core::Distance(v.position, {9, 5}) < 0.5;
  EXPECT_TRUE(mapped) << "the late vertex is in the map";
  return view.known_area();
}

TEST(Mapper, KnownSpaceIsTheSameComputedStepByStepOrAtTheEnd) {
  const double at_end = RoomWithALateVertexKnownArea(false);
  EXPECT_LT(at_end, 100.0 - 1.0) << "the vertex inside the room dents what the observations saw";
  EXPECT_NEAR(RoomWithALateVertexKnownArea(true), at_end, 1e-6 * at_end);
}

// The square room; the first 10 observations see every corner 0.6 further out on both axes, the last 20 see
// them exactly, so the corners drift back by less than star_rebuild_tolerance (1.0) after MCMC maps them.
struct DriftingRoom {
  Mapper m{SquareOptions()};
  explicit DriftingRoom(bool every_step) {
    core::Rng rng(3);
    for (int i = 0; i < 30; ++i) {
      const core::Pose2 pose{5, 5, 0.1 * i};
      const double out = i < 10 ? 0.6 : 0.0;
      std::vector<Detection> d;
      for (Vec2 c : {Vec2{0, 0}, Vec2{10, 0}, Vec2{10, 10}, Vec2{0, 10}})
        d.push_back(Det(pose, c + Vec2{c.x > 5 ? out : -out, c.y > 5 ? out : -out}, core::VertexLabel::kCorner));
      m.AddObservation(Obs(pose, d));
      if (i % 5 == 4) m.SampleMostLikelyMap(rng);
      if (every_step) m.View();
    }
    m.SampleMostLikelyMap(rng);
  }
};

TEST(Mapper, ExactViewRebuildsKnownSpaceAroundVerticesThatDriftedLessThanTheTolerance) {
  DriftingRoom stepwise(true), at_end(false);
  const double cached = stepwise.m.View().known_area();
  const double exact = stepwise.m.ExactView().known_area();
  const double fresh = at_end.m.View().known_area();  // every star polygon built from the final positions
  ASSERT_EQ(stepwise.m.View().vertices.size(), 4u);
  EXPECT_GT(cached, exact + 5.0) << "the step-by-step view keeps star polygons built from the outer positions";
  EXPECT_NEAR(exact, fresh, 1e-6 * fresh);
  EXPECT_LT(exact, 10.6 * 10.6) << "the corners ended within 0.3 of the room's";
  EXPECT_NEAR(stepwise.m.View().known_area(), exact, 1e-6 * exact) << "the cache follows the exact view";
  EXPECT_NEAR(at_end.m.ExactView().known_area(), fresh, 1e-6 * fresh) << "nothing to rebuild: the same";
}

TEST(DetectionCovariance, EigenvaluesAreRangeAndCrossRangeVariances) {
  Detection d;
  d.range = 7.0;
  d.bearing = 0.6;
  d.polar = {0.25, 0.0, 0.01};
  const core::Cov2 c = core::DetectionCovariance({1, 2, 0.3}, d);
  Eigen::Matrix2d m;
  m << c.xx, c.xy, c.xy, c.yy;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(m);
  EXPECT_NEAR(es.eigenvalues()(0), 0.25, 1e-12);
  EXPECT_NEAR(es.eigenvalues()(1), 49 * 0.01, 1e-12);
}

TEST(MapperOptions, ValidateNamesTheKey) {
  MapperOptions o;
  o.false_positive_rate = 1.5;
  try {
    o.Validate();
    FAIL();
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "mapping.false_positive_rate");
  }
}

}  // namespace
}  // namespace toponav::mapping

namespace toponav::mapping {
namespace {

TEST(Mapper, ObservationsOfSeveralAgentsBuildOneMap) {
  Mapper m(SquareOptions());
  core::Rng rng(4);
  for (int i = 0; i < 20; ++i) {
    Observation a = SquareFromInside({3, 3 + 0.1 * i, 0.0});
    Observation b = SquareFromInside({7, 7 - 0.1 * i, 2.0});
    a.agent = 0;
    b.agent = 1;
    m.AddObservation(a);
    m.AddObservation(b);
  }
  m.SampleMostLikelyMap(rng);
  EXPECT_EQ(m.View().vertices.size(), 4u);
  EXPECT_EQ(m.PotentialVertices().size(), 4u) << "both agents' detections of a corner join one vertex";
}

// A room [0,10]^2 whose east wall is missing between (10,0) and (10,10) as far as the sensor can tell:
// the corners at x = 10 are seen as gaps, so the east side of known space is a frontier.
Observation RoomWithOpening(const core::Pose2& pose) {
  std::vector<Detection> d;
  d.push_back(Det(pose, {0, 0}, core::VertexLabel::kCorner));
  d.push_back(Det(pose, {10, 0}, core::VertexLabel::kLeftGap));    // wall only on its clockwise side, to (0,0)
  d.push_back(Det(pose, {10, 10}, core::VertexLabel::kRightGap));  // wall only counter-clockwise, to (0,10)
  d.push_back(Det(pose, {0, 10}, core::VertexLabel::kCorner));
  return Obs(pose, d);
}

TEST(Mapper, FrontierAcrossAnOpeningKeepsItsId) {
  Mapper m(SquareOptions());
  core::Rng rng(5);
  for (int i = 0; i < 10; ++i) m.AddObservation(RoomWithOpening({4, 5, 0}));
  m.SampleMostLikelyMap(rng);
  const MapView first = m.View();
  EXPECT_EQ(first.walls.size(), 3u);
  ASSERT_EQ(first.frontiers.size(), 1u);
  EXPECT_NEAR(first.frontiers[0].midpoint.x, 10.0, 1e-6);
  EXPECT_NEAR(first.frontiers[0].length, 10.0, 1e-6);
  for (int i = 0; i < 5; ++i) m.AddObservation(RoomWithOpening({4.2, 5, 0}));
  m.SampleMostLikelyMap(rng);
  const MapView second = m.View();
  ASSERT_EQ(second.frontiers.size(), 1u);
  EXPECT_EQ(second.frontiers[0].id, first.frontiers[0].id);
}

}  // namespace
}  // namespace toponav::mapping
