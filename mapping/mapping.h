#pragma once
// Front door of the mapping layer: the probabilistic polygonal vertex map of the paper (Sec. III).
// Detections are associated to vertices (Mahalanobis gate on the innovation, one-to-one per observation),
// fused by Kalman updates, joined by walls whose probability averages the sensor's edge likelihoods, and
// MCMC over vertex inclusion picks the most likely map under the posterior; known space is the union of
// conservative per-observation star polygons.  Planners read an immutable MapView, never the Mapper.
#include <memory>
#include <optional>
#include <vector>

#include "core/geometry.h"
#include "core/observation.h"
#include "core/option_fields.h"
#include "core/rng.h"
#include "mapping/polygon_set.h"

namespace toponav::mapping {

struct MapperOptions {
  double association_gate_chi2 = 9.21;    // chi-square(2 dof) 99 % gate on the innovation (P + R)
  double association_count_bias = 1.0;    // gated vertices with fewer detections cost this * ln(ratio) more
  double false_positive_rate = 0.2;       // R_fp of the posterior
  double false_negative_rate = 0.2;       // R_fn of the posterior
  double vertex_log_prior = -3.22;        // per vertex in the map (2 log R_fp, the reference's bias)
  double wall_log_prior = -0.5;           // per wall in the map
  int min_detections = 3;                 // a vertex needs this many detections to enter a map
  double wall_threshold = 0.5;            // a wall exists when its averaged likelihood exceeds this
  double wall_skip_damping = 0.2;         // evidence for detections k apart is scaled by this^(k-1)
  // Two detections less than this apart in bearing (radians) give no wall evidence, and two map vertices
  // less than this apart seen from an observation's pose no edge term in its likelihood: seen edge-on, a wall
  // between them and a doorway in it look the same, and which of their jambs falls between them in bearing
  // order is noise.  0: every pair counts (the reference).
  double wall_min_view_angle = 0.0;
  double wall_on_segment_tolerance = 2.0;  // ... not counting detections within this distance of the segment
                                          // between them whose vertex is not in the map (a false detection on
                                          // the wall); 0: count all (the reference)
  // An observation that missed a vertex with enough detections lying between its pose and the segment
  // between two of its detections (or within this distance, world units, of the two sight lines, and farther
  // than it from the segment and its ends) gives that pair no wall evidence while the vertex is in the map:
  // seen along a wall edge-on, its far end shows just past the near corner, and where the sensor misses that
  // corner, the far end and the corner's other neighbour make a pair whose wall cuts across the solid corner.
  // A vertex counts as missed if it had enough detections (min_detections) when the observation was added
  // and is not one of the pair's detections or those between them in bearing (one detected outside the
  // pair's bearing interval, its map position in front of the segment, was missed where it stands).
  // Leaving a sample out moves the pair's average either way.  0: every observation counts (the reference).
  double wall_front_vertex_tolerance = 0.0;
  // Of a map wall a-b and a map wall a-c passing within this distance (world units) of b and ending more than
  // twice this past it, the planners and known space get a-b only (mapping/internal/walls_past_vertices.h);
  // 0: both.
  double wall_past_vertex_tolerance = 0.0;
  // Closed worlds: the evidence such a pair (a detection on the segment between them) gives for a wall
  // straight past the detection is the smaller of its ends' wall likelihoods (both ends must say a wall runs
  // on) if true, their average (the reference) if false.  (README, "The map", says why.)
  bool wall_past_detection_min = true;
  // Closed worlds: every pair's evidence is the smaller of its ends' wall likelihoods, not their average: for
  // a sensor whose wrong labels are confident (the learned one), one end saying "gap" keeps a doorway open.
  bool wall_evidence_min = false;
  double edge_log_floor = -1.386;         // log 0.25: an edge term never costs more than this
  int mcmc_samples = 50;                  // proposals per SampleMostLikelyMap call (the paper's 50)
  int mcmc_window = 45;                   // proposals flip vertices seen in this many latest observations
  bool defer_to_mcmc = true;              // new vertices and walls enter the map only through MCMC; set false
                                          // to build without MCMC (every vertex with enough detections kept)
  double max_range = 100.0;               // range of hypothetical observations
  // Closed worlds: known space keeps what an observation saw up to its detected vertices that have enough
  // detections even where the posterior leaves them out of the map (the sensor's false positives lie on
  // walls, so the space in front of them was seen).
  bool known_space_candidates = true;
  double star_rebuild_tolerance = 1.0;    // recompute known space around a map vertex once it drifted this far
  double frontier_wall_tolerance = 1.5;   // known-space boundary this close to a map wall is wall, not frontier
  double frontier_split_angle = 0.3;      // a frontier turning by more than this (radians) is split there ...
  double frontier_split_min_length = 8.0; // ... if both pieces are at least this long; 0 angle: never split
                                          // (closed worlds only: see mapping/internal/frontiers.cpp)
  std::optional<core::Aabb2> world_bounds;  // if set, observations from outside are rejected
  // Open worlds (the office park): the search region.  Where the sensor's labels say no wall continues on
  // either side of a gap between two detected vertices, the agent sees through it out to this region's edge
  // (within max_range), so open ground becomes known; the region's edge is never a frontier.
  std::optional<core::Aabb2> open_region;
  // Open worlds: the search is for buildings, so known-space boundary farther than this from every vertex
  // with enough detections (mapped or not) is where the search ends, like the region's edge: open ground
  // far from all structure is no frontier.  0: every piece of boundary in the region is frontier.
  double open_frontier_reach = 60.0;
  static const core::OptionFields<MapperOptions>& Fields();  // YAML keys (under mapping:) and their ranges
  void Validate() const;                  // throws core::ConfigError ("mapping.association_gate_chi2", ...)
};

struct MapVertex {
  int id = 0;
  core::Vec2 position;
  core::Cov2 covariance;
  int num_detections = 0;
};

struct MapWall {
  int a = 0, b = 0;          // vertex ids
  core::Vec2 pa, pb;
  double probability = 0.0;  // averaged edge likelihood
  // Known for certain to be there (the region's edge, a wall the planner adds, a true map): a way never
  // crosses it.  The map's own walls are not (planning::PlannerOptions::wall_crossing_cost prices them).
  bool certain = false;
};

// A piece of the known-space boundary that is not a map wall: where unknown space begins.
struct Frontier {
  int id = 0;                       // stable across steps while the frontier stays put
  std::vector<core::Vec2> points;   // polyline along the known-space boundary
  core::Vec2 midpoint;              // the point halfway along it
  double length = 0.0;
  // Where a longer chain was cut at a turn (MapperOptions::frontier_split_angle) rather than ending at a corner
  // of known space: how sharply it turns at that end (radians between the two pieces' chords); 0: a true end.
  double front_turn = 0.0, back_turn = 0.0;
};

struct MapView {
  std::vector<MapVertex> vertices;   // the map's vertices
  std::vector<MapVertex> rejected;   // vertices with enough detections that the posterior leaves out
  std::vector<MapWall> walls;        // walls between map vertices
  std::vector<core::Polygon> known_space;             // double-precision copy of known_set
  std::shared_ptr<const PolygonSet> known_set;         // the exact known space (metrics use this, not a copy)
  std::vector<Frontier> frontiers;
  int num_observations = 0;
  double known_area() const;
};

struct MapperStats {
  int num_potential_vertices = 0;
  int num_walls_with_evidence = 0;
  int last_mcmc_accepted = 0;
  int last_mcmc_evaluated_observations = 0;
};

class Mapper {
 public:
  explicit Mapper(const MapperOptions& options);
  ~Mapper();
  Mapper(const Mapper&) = delete;
  Mapper& operator=(const Mapper&) = delete;

  // Contact evidence: the map wall that crosses the way from contact.at toward contact.toward within
  // contact.reach (the one nearest to 'at') is real -- from now on, whenever it is in the map, its view says so
  // (probability 1, MapWall::certain).  Returns false (and changes nothing) where no map wall crosses the way.
  bool AddContact(const core::Contact& contact);

  // Associates the detections, updates vertices and walls.  Observations of several agents may be added in
  // turn.  Throws core::DataError (and leaves the map unchanged) for NaN or infinite values, a covariance
  // that is not positive definite, or a pose outside options.world_bounds.
  void AddObservation(const core::Observation& observation);

  // MCMC over vertex inclusion: 'samples' (negative: options.mcmc_samples) single-vertex flips of the recently
  // seen candidates (random-order systematic scan), Metropolis acceptance; leaves the map at the most likely
  // state seen and returns how much that raised the log posterior (>= 0).
  double SampleMostLikelyMap(core::Rng& rng, int samples = -1);

  // The log posterior of the current map (all observations).
  double LogPosterior() const;
  // ... with the listed potential vertices in or out of the map as given (diagnostics and tests: which map
  // the posterior prefers; the map itself is not changed).
  double LogPosteriorIf(const std::vector<std::pair<int, bool>>& inclusion) const;

  // The map of the last MCMC call (or the live one without defer_to_mcmc) with its known space and frontiers,
  // brought up to date incrementally (not const: known space and frontier ids advance with each call, so
  // call it once per map update).
  MapView View();
  // The same map with its known space rebuilt exactly from the vertices' current positions (View lets a
  // vertex drift up to options.star_rebuild_tolerance before rebuilding around it, and the union of star
  // polygons built from older positions reaches into obstacles).  Slower: for scoring a final map.
  MapView ExactView();

  // All potential vertices and their inclusion flags (for tests and pictures).
  std::vector<MapVertex> PotentialVertices() const;
  MapperStats Stats() const;
  const MapperOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Splits a polyline (a ring if its first and last points are equal) where it turns by more than max_turn
// radians, keeping every piece at least min_length long; consecutive pieces share their end points.
std::vector<std::vector<core::Vec2>> SplitAtTurns(const std::vector<core::Vec2>& chain, double max_turn,
                                                  double min_length);

// Builds the star-shaped polygon of points seen from 'center' (vertexnav.md §2.7): points sorted by bearing,
// the center inserted wherever consecutive bearings are pi or more apart.  Points at the center or at the
// same bearing as a nearer point are dropped.  Fewer than 2 usable points give an empty ring.
core::Ring StarPolygon(const core::Vec2& center, const std::vector<core::Vec2>& points);

// A point of an open star polygon: whether no wall continues from it counter-clockwise / clockwise (as seen
// from the center), i.e. whether the sight line may pass it on that side.
struct StarPoint {
  core::Vec2 p;
  bool open_ccw = false;
  bool open_cw = false;
};

// What an open gap sees: the region (convex), a range limit, and walls that stop sight lines.
struct OpenSpace {
  core::Aabb2 region;
  double max_range = 100.0;
  double sample_step = 0.1;    // radians between rays
  std::vector<core::Segment2> blockers;
};

// StarPolygon where a window between consecutive points A, B (by bearing) with A.open_ccw and B.open_cw is not
// closed by the chord A-B but by rays out to the nearest of the region's edge, max_range and the blockers
// (sampled every sample_step radians).  Bearings strictly increase along the ring, so it is simple.  If
// 'hit' is given, it receives the indices of the blockers that stopped some ray (sorted, unique).
core::Ring OpenStarPolygon(const core::Vec2& center, const std::vector<StarPoint>& points, const OpenSpace& space,
                           std::vector<int>* hit = nullptr);

}  // namespace toponav::mapping
