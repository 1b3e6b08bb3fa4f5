#pragma once
// The goal navigator (paper Sec. V): one agent from its start to a goal, every step a goal-directed planner --
// the optimistic baseline, Learned Subgoal Planning with the sensor's subgoal estimates ("lsp"), LSP with the
// true frontier properties ("oracle") or the optimistic planner on the true walls ("known") -- choosing the way
// on the map built so far.  The task ends when the agent is within navigation.goal_radius of the goal ("goal"),
// is held in place NavigationOptions::stuck_window steps ("stuck"), or finds the goal cut off for
// NavigationOptions::cut_off_steps steps ("cut_off"); the harness's step cap ends it otherwise.
//
// Each step, in order: the goal test; the subgoal estimates of this step's observations to the LSP estimator;
// the stuck test; the blocked frontiers brought up to date; the range ring's scans once the agent is held
// (navigation.scan_when_held); the view the planner gets (the map, the region's edges as walls, the blocked
// frontier parts, motion blocks and scan walls as free-standing walls); the planner's way; where it finds none,
// the recovery (planning/internal/doorway_recovery.h).  After the agent steps, an agent that made no headway
// (no motion, pacing, held in place, the third lap of a loop) is due for a nudge once
// NavigationOptions::stuck_steps such steps added up: the frontier it stands at is blocked where it stood, or a
// motion block goes across its way.
// Where it made no headway along its way (a motion block's count, or a nudge), the map wall that way crosses
// close ahead is reported as contact evidence: the map makes it certain, and no way crosses it again.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/world.h"
#include "planning/lsp_planner.h"
#include "planning/navigator.h"
#include "planning/navigator_options.h"

namespace toponav::planning {

// The goal-directed planners (a bench row's `planner:`): "optimistic" (unknown space is free), "oracle" (LSP with
// the true frontier properties: the bound a perfect network reaches), "lsp" (LSP with the sensor's subgoal
// estimates averaged per frontier, planning::CellAveragingEstimator; a sensor that gives none leaves every
// frontier at the optimistic default), "known" (the optimistic planner on the true walls: the floor).
enum class GoalPlanner { kOptimistic, kOracle, kLsp, kKnown };
const char* ToString(GoalPlanner planner);
std::optional<GoalPlanner> ParseGoalPlanner(const std::string& name);
// Whether the planner is defined by knowing the true world (oracle, known): it needs GoalNavigatorSetup::truth.
bool NeedsTrueWorld(GoalPlanner planner);

// What the planner decided at a step, before the agent moves.
struct NavigationDecision {
  // The frontier pieces a learned-subgoal planner estimated, with their Ps (empty for the optimistic planner,
  // or when it planned optimistically).
  std::vector<FrontierEstimate> estimates;
  // The way the agent follows this step (the planner's, or the recovery's), from where it stands to its end
  // (world units); empty where it has none and stays.
  std::vector<core::Vec2> way;
};

// Planner "lsp": each estimate of the learned estimator, with the grid and distance tables it was made on and,
// per frontier piece, whether some observation's subgoal cells covered it.
using EstimateHook = std::function<void(const SubgoalGrid& grid, const OrderingProblem& distances,
                                        const std::vector<SubgoalProperties>& estimates,
                                        const std::vector<char>& seen)>;

struct GoalNavigatorSetup {
  GoalPlanner planner = GoalPlanner::kOptimistic;
  core::Vec2 goal;
  core::Aabb2 region;        // the extent the world lies in, known to the agent: its edges are walls to the planner
  double step_length = 1.8;  // the agent's step (world units)
  NavigationOptions navigation;
  PlannerOptions planning;
  LspOptions lsp;
  // Privileged information: the true world, for the planners defined by knowing it (oracle, known) and for
  // nothing else.  The harness sets it, and the trial record says so; the others refuse it.
  const core::World* truth = nullptr;
};

// The most consecutive entries of 'trail' that all lie within 'span' of each other (HeldInPlace's test over the
// whole trail: a goal-directed trial ends "stuck" where this reaches NavigationOptions::stuck_window; 0 for an empty
// trail).  How near a trial that reached its goal came to that end.
int LongestHold(const std::vector<core::Vec2>& trail, double span);

class GoalNavigator : public Navigator {
 public:
  // Throws core::ConfigError where the planner needs the true world and 'truth' is not set, or does not and it is.
  explicit GoalNavigator(const GoalNavigatorSetup& setup);
  ~GoalNavigator() override;

  bool Plan(const NavigatorInput& input, std::vector<std::vector<core::Vec2>>* ways) override;
  StepResponse AfterStep(const NavigatorInput& input, int agent, const MotionOutcome& step, core::Rng& rng) override;
  std::string end_reason() const override { return end_reason_; }

  // Hooks the harness may set: every step before the planner, with the frontier targets on offer (training
  // data); every step that does not end the task, with the decision; planner "lsp", every estimate.
  std::function<void(const NavigatorInput&, const std::vector<FrontierTarget>&)> on_plan;
  std::function<void(const NavigationDecision&)> on_decision;
  void set_on_estimate(EstimateHook hook);

  struct Counts {
    int nudges = 0;
    int recovery_steps = 0;  // steps on which the planner found no way to the goal (so the recovery ran)
    int repeated_steps = 0;  // steps of a third or later lap of the same loop, with a path (RepeatedStep)
    int scan_steps = 0;      // steps planned with the range ring's scans, after a hold
  };
  const Counts& counts() const { return counts_; }
  const std::vector<FrontierEstimate>& estimates() const { return estimates_; }  // the last step's
  const std::vector<core::Segment2>& scan_walls() const;  // every scan's walls, merged
  std::vector<core::Segment2> added_blocks() const;       // every motion block added, those taken back too

 private:
  struct Parts;
  bool End(const char* reason);
  void Scan(const NavigatorInput& input, const core::Vec2& at);
  mapping::MapView PlannerView(const mapping::MapView& map) const;
  std::vector<FrontierTarget> UnprobedTargets(const mapping::MapView& map) const;
  void Decide(const NavigatorInput& input, const mapping::MapView& view, const VisibilityGraph& graph,
              const std::vector<FrontierTarget>& targets, const core::Vec2& at);

  GoalNavigatorSetup setup_;
  std::unique_ptr<Parts> parts_;
  FrontierChoice choice_;
  std::vector<std::pair<int, int>> crossed_;  // the map walls the last way crossed (vertex ids)
  std::vector<FrontierEstimate> estimates_;
  Counts counts_;
  bool scanning_ = false;
  int cut_off_ = 0;
  std::string end_reason_ = "step_cap";
};

}  // namespace toponav::planning
