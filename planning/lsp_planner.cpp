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
      {"piece_length", &O::piece_length, 0.0, 1000.0},
  };
  return fields;
}

void LspOptions::Validate() const {
  core::CheckRanges(*this, Fields(), "lsp.");
  if (piece_length > 0 && piece_length < cell)
    throw core::ConfigError("<options>", "lsp.piece_length", std::to_string(piece_length),
                            "must be 0 (frontiers whole) or at least lsp.cell (" + std::to_string(cell) + ")");
  calibration.Validate("<options: lsp.calibration>");
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

// The view with every piece but 'keep' as a wall: the optimistic path then leads through 'keep'.
mapping::MapView MaskOtherPieces(const mapping::MapView& view, const std::vector<mapping::Frontier>& pieces,
                                 size_t keep) {
  mapping::MapView v = view;
  for (size_t k = 0; k < pieces.size(); ++k)
    if (k != keep) AddWalls(&v, pieces[k].points);
  return v;
}

}  // namespace

LspPlanner::LspPlanner(std::shared_ptr<SubgoalEstimator> estimator, const LspOptions& o, const PlannerOptions& planning,
                       std::optional<core::Aabb2> region, std::string name)
    : estimator_(std::move(estimator)), o_(o), planning_(planning), region_(region), name_(std::move(name)) {
  o.Validate();  // the ranges of max_frontiers, cell and piece_length
  TOPONAV_CHECK(estimator_, "an LSP planner without an estimator");
  // The way through the subgoal never crosses a map wall: where the walls close it, there is none (and the way to
  // the subgoal's target, or the optimistic way on the problem's graph, is taken instead).
  planning_.wall_crossing_cost = 0.0;
}

std::vector<FrontierChoice> LspPlanner::Plan(const PlanningProblem& p) {
  TOPONAV_CHECK(p.view && p.graph && p.targets && p.goal && p.agents.size() == 1,
                "LSP plans for one agent with a goal");
  decision_ = {};
  FrontierChoice c;
  const int piece = ChooseSubgoal(p);
  const int subgoal = piece >= 0 ? pieces_[size_t(piece)].id : -1;
  if (subgoal >= 0) {
    const mapping::MapView masked = MaskOtherPieces(*p.view, pieces_, size_t(piece));
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

int LspPlanner::ChooseSubgoal(const PlanningProblem& p) {
  pieces_.clear();
  for (const mapping::Frontier& f : p.view->frontiers)
    for (mapping::Frontier& piece : FrontierPieces(f, o_.piece_length)) pieces_.push_back(std::move(piece));
  std::vector<const mapping::Frontier*> frontiers;
  std::vector<int> index;
  for (const mapping::Frontier* f : TargetFrontiers(*p.view, *p.targets))
    for (size_t k = 0; k < pieces_.size(); ++k)
      if (pieces_[k].id == f->id) {
        frontiers.push_back(&pieces_[k]);
        index.push_back(int(k));
      }
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
    decision_.pieces.push_back(*frontiers[f]);
    decision_.properties.push_back(problem.properties[f]);
  }
  for (int k : best.order) decision_.order.push_back(chosen[size_t(k)]);
  return decision_.order.empty() ? -1 : index[size_t(decision_.order.front())];
}

std::vector<mapping::Frontier> FrontierPieces(const mapping::Frontier& frontier, double length) {
  const double total = core::PolylineLength(frontier.points);
  const int n = length > 0 ? int(std::ceil(total / length - 1e-9)) : 1;
  if (n <= 1) return {frontier};
  std::vector<mapping::Frontier> out;
  for (int k = 0; k < n; ++k) {
    mapping::Frontier piece;
    piece.id = frontier.id;
    piece.points = core::SubPolyline(frontier.points, total * k / n, total * (k + 1) / n);
    piece.length = total / n;
    piece.midpoint = core::PointAlong(frontier.points, total * (k + 0.5) / n);
    out.push_back(std::move(piece));
  }
  out.front().front_turn = frontier.front_turn;
  out.back().back_turn = frontier.back_turn;
  return out;
}

std::unique_ptr<SubgoalEstimator> CreateOracleEstimator(const core::World& world, double cell, double clearance) {
  return std::make_unique<OracleEstimator>(world, cell, clearance);
}

std::unique_ptr<LspPlanner> CreateLspPlanner(std::shared_ptr<SubgoalEstimator> estimator, const LspOptions& options,
                                             const PlannerOptions& planning, std::optional<core::Aabb2> region,
                                             std::string name) {
  return std::make_unique<LspPlanner>(std::move(estimator), options, planning, region, std::move(name));
}

std::vector<FrontierEstimate> Estimates(const LspDecision& decision) {
  std::vector<FrontierEstimate> out;
  for (size_t i = 0; i < decision.pieces.size(); ++i)
    out.push_back({decision.pieces[i].id, decision.pieces[i].points, decision.properties[i].ps, false});
  if (!decision.order.empty()) out[size_t(decision.order.front())].subgoal = true;
  return out;
}

}  // namespace toponav::planning
