#pragma once
// Learned Subgoal Planning (paper Sec. V; lsp.md §1): every step each frontier on offer gets its properties
// (Ps, success and exploration cost) from an estimator, the distance tables come from a raster of the map
// (planning/subgoal_grid.h), and the frontier that begins the order of least expected cost is the subgoal;
// the agent heads for the goal through it (the other frontiers block its optimistic path, as the reference
// masks them).  When the goal is in known space, or no frontier is worth ordering, it plans as the
// optimistic planner does.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/option_fields.h"
#include "core/world.h"
#include "planning/planner.h"
#include "planning/subgoal_calibration.h"
#include "planning/subgoal_ordering.h"

namespace toponav::planning {

class SubgoalGrid;

// Where the properties come from: the oracle (the true world), or a network through the sensor.
class SubgoalEstimator {
 public:
  virtual ~SubgoalEstimator() = default;
  // One estimate per frontier of 'grid' (in its order); 'distances' are its tables.
  virtual std::vector<SubgoalProperties> Estimate(const SubgoalGrid& grid, const OrderingProblem& distances) = 0;
};

// The true properties (TrueSubgoalProperties): what LSP reaches with a perfect network.
std::unique_ptr<SubgoalEstimator> CreateOracleEstimator(const core::World& world, double cell, double clearance);

// YAML section `lsp:`.
struct LspOptions {
  int max_frontiers = 12;     // frontiers ordered exactly; more are cut by SelectFrontiers (at most 16)
  double cell = 1.0;          // raster cell, world units
  double clearance = 1.0;     // the oracle's true free space keeps this far from walls
  // Frontiers longer than this are cut into pieces of equal length, each ordered as a subgoal of its own, so
  // the agent crosses a long frontier where the estimates say the way goes on (world units; 0: never cut).
  double piece_length = 35.0;
  // What the learned estimator's Ps means (YAML key lsp.calibration: a file that
  // experiments/subgoal_calibration.h reads and writes); empty: as the network gives it.  The oracle's
  // true properties are never mapped.
  SubgoalCalibration calibration;
  static const core::OptionFields<LspOptions>& Fields();  // YAML keys (under lsp:) and their ranges
  void Validate() const;  // throws core::ConfigError ("lsp.piece_length", ...)
};

// 'frontier' cut into the fewest pieces of equal length at most 'length' (0, or a frontier no longer than it:
// the frontier itself); each keeps its id, and a cut end has turn 0.
std::vector<mapping::Frontier> FrontierPieces(const mapping::Frontier& frontier, double length);

// What the last Plan call decided, for pictures and tests: every frontier piece estimated (each with its
// frontier's id), its (clamped) properties, and the order chosen over the ones worth ordering (indices into
// them, the subgoal first).
struct LspDecision {
  std::vector<mapping::Frontier> pieces;
  std::vector<SubgoalProperties> properties;
  std::vector<int> order;
};

// The planner.  The estimator is shared: its owner may feed it (the learned one takes the sensor's outputs).
class LspPlanner : public Planner {
 public:
  // 'region': the area the world lies in (the raster's extent); 'planning': for the masked path's graph.
  LspPlanner(std::shared_ptr<SubgoalEstimator> estimator, const LspOptions& options, const PlannerOptions& planning,
             std::optional<core::Aabb2> region, std::string name);
  std::vector<FrontierChoice> Plan(const PlanningProblem& problem) override;
  std::string name() const override { return name_; }
  const LspDecision& decision() const { return decision_; }  // the last Plan call's

 private:
  // The piece (index into pieces_) that begins the best order, or -1 (the goal is known, or nothing to order).
  int ChooseSubgoal(const PlanningProblem& p);

  std::shared_ptr<SubgoalEstimator> estimator_;
  LspOptions o_;
  PlannerOptions planning_;  // for the way through the subgoal: map walls never crossed
  std::optional<core::Aabb2> region_;
  std::string name_;
  LspDecision decision_;
  std::vector<mapping::Frontier> pieces_;
};

std::unique_ptr<LspPlanner> CreateLspPlanner(std::shared_ptr<SubgoalEstimator> estimator, const LspOptions& options,
                                             const PlannerOptions& planning, std::optional<core::Aabb2> region,
                                             std::string name);

// A frontier piece and its estimated Ps (pictures and traces of LSP trials).
struct FrontierEstimate {
  int frontier_id = 0;
  std::vector<core::Vec2> points;
  double ps = 0.0;
  bool subgoal = false;  // the piece that begins the chosen order
};
std::vector<FrontierEstimate> Estimates(const LspDecision& decision);

}  // namespace toponav::planning
