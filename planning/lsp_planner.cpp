#include "planning/lsp_planner.h"

#include <cmath>

#include "core/error.h"
#include "planning/subgoal_grid.h"

namespace toponav::planning {

const core::OptionFields<LspOptions>& LspOptions::Fields() {
  using O = LspOptions;
  static const core::OptionFields<O> fields{
      {"max_frontiers", &O::max_frontiers, 1, kMaxExactFrontiers},
      {"cell", &O::cell, 0.05, 20.0},
      {"clearance", &O::clearance, 0.0, 50.0},
  };
  return fields;
}

namespace {

class OracleEstimator : public SubgoalEstimator {
 public:
  OracleEstimator(const core::World& world, double cell, double clearance) : truth_(world, cell, clearance) {}
  std::vector<SubgoalProperties> Estimate(const SubgoalGrid& grid, const OrderingProblem& distances) override {
    return TrueSubgoalProperties(grid, truth_, distances);
  }

 private:
  TrueFreeSpace truth_;
};

// The view with every frontier but 'keep' as a wall: the optimistic path then leads through 'keep'.
mapping::MapView MaskOtherFrontiers(const mapping::MapView& view, int keep) {
  mapping::MapView v = view;
  for (const auto& f : view.frontiers)
    if (f.id != keep) AddWalls(&v, f.points);
  return v;
}

class LspPlanner : public Planner {
 public:
  LspPlanner(std::unique_ptr<SubgoalEstimator> estimator, const LspOptions& o, const PlannerOptions& planning,
             std::optional<core::Aabb2> region, std::string name)
      : estimator_(std::move(estimator)), o_(o), planning_(planning), region_(region), name_(std::move(name)) {
    TOPONAV_CHECK(estimator_ && o.max_frontiers >= 1 && o.max_frontiers <= kMaxExactFrontiers && o.cell > 0,
                  "LSP planner options: max_frontiers " << o.max_frontiers << ", cell " << o.cell);
  }

  std::vector<FrontierChoice> Plan(const PlanningProblem& p) override {
    TOPONAV_CHECK(p.view && p.graph && p.targets && p.goal && p.agents.size() == 1,
                  "LSP plans for one agent with a goal");
    decision_ = {};
    FrontierChoice c;
    const int subgoal = ChooseSubgoal(p);
    if (subgoal >= 0) {
      const mapping::MapView masked = MaskOtherFrontiers(*p.view, subgoal);
      c.path = VisibilityGraph(masked, planning_, false).Plan(p.agents[0], *p.goal);
      if (!c.path)
        for (const auto& t : *p.targets)
          if (t.frontier_id == subgoal) c.path = p.graph->Plan(p.agents[0], t.point);
      c.frontier_id = subgoal;
    }
    if (!c.path) {
      c.path = p.graph->Plan(p.agents[0], *p.goal);  // the optimistic way
      c.frontier_id = -1;
    }
    c.status = c.path.status;
    return {c};
  }

  std::string name() const override { return name_; }
  const LspDecision& decision() const { return decision_; }

 private:
  // The frontier id that begins the best order, or -1 (the goal is known, or nothing to order).
  int ChooseSubgoal(const PlanningProblem& p) {
    const std::vector<const mapping::Frontier*> frontiers = TargetFrontiers(*p.view, *p.targets);
    if (frontiers.empty()) return -1;
    const SubgoalGrid grid(*p.view, frontiers, p.agents[0], *p.goal, o_.cell, region_);
    if (grid.goal_known()) return -1;
    OrderingProblem problem = grid.Distances();
    const std::vector<SubgoalProperties> estimates = estimator_->Estimate(grid, problem);
    TOPONAV_CHECK(estimates.size() == frontiers.size(), estimates.size()
                                                            << " estimates for " << frontiers.size() << " frontiers");
    for (size_t f = 0; f < frontiers.size(); ++f) problem.properties[f] = Clamped(estimates[f]);
    const std::vector<int> chosen = SelectFrontiers(problem, o_.max_frontiers);
    const Ordering best = BestOrdering(Restrict(problem, chosen));
    for (size_t f = 0; f < frontiers.size(); ++f) {
      decision_.frontier_ids.push_back(frontiers[f]->id);
      decision_.properties.push_back(problem.properties[f]);
    }
    for (int k : best.order) decision_.order.push_back(chosen[size_t(k)]);
    return decision_.order.empty() ? -1 : decision_.frontier_ids[size_t(decision_.order.front())];
  }

  std::unique_ptr<SubgoalEstimator> estimator_;
  LspOptions o_;
  PlannerOptions planning_;
  std::optional<core::Aabb2> region_;
  std::string name_;
  LspDecision decision_;
};

}  // namespace

std::unique_ptr<SubgoalEstimator> CreateOracleEstimator(const core::World& world, double cell, double clearance) {
  return std::make_unique<OracleEstimator>(world, cell, clearance);
}

std::unique_ptr<Planner> CreateLspPlanner(std::unique_ptr<SubgoalEstimator> estimator, const LspOptions& options,
                                          const PlannerOptions& planning, std::optional<core::Aabb2> region,
                                          std::string name) {
  return std::make_unique<LspPlanner>(std::move(estimator), options, planning, region, std::move(name));
}

const LspDecision* LastDecision(const Planner& planner) {
  const auto* lsp = dynamic_cast<const LspPlanner*>(&planner);
  return lsp ? &lsp->decision() : nullptr;
}

}  // namespace toponav::planning
