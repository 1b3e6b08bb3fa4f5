#include "experiments/subgoal_eval.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>

#include "core/error.h"
#include "core/subgoal_labels.h"
#include "experiments/subgoal_data.h"
#include "sim/worlds.h"

namespace toponav::experiments {

double RocAuc(const std::vector<float>& scores, const std::vector<bool>& positive) {
  TOPONAV_CHECK(scores.size() == positive.size(), "scores and flags differ in length");
  std::vector<size_t> order(scores.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return scores[a] < scores[b]; });
  double rank_sum = 0.0;  // of the positives, ranks from 1, ties averaged
  size_t pos = 0;
  for (size_t i = 0; i < order.size();) {
    size_t j = i;
    while (j < order.size() && scores[order[j]] == scores[order[i]]) ++j;
    const double rank = 0.5 * double(i + 1 + j);
    for (size_t k = i; k < j; ++k)
      if (positive[order[k]]) rank_sum += rank, ++pos;
    i = j;
  }
  const size_t neg = scores.size() - pos;
  if (pos == 0 || neg == 0) return 0.5;
  return (rank_sum - 0.5 * double(pos) * double(pos + 1)) / (double(pos) * double(neg));
}

void CountOrderedPairs(const std::vector<FrontierCost>& frontiers, double* agree, size_t* pairs) {
  for (size_t i = 0; i < frontiers.size(); ++i)
    for (size_t j = i + 1; j < frontiers.size(); ++j) {
      const FrontierCost& lo = frontiers[i].truth <= frontiers[j].truth ? frontiers[i] : frontiers[j];
      const FrontierCost& hi = &lo == &frontiers[i] ? frontiers[j] : frontiers[i];
      if (hi.truth < SubgoalEval::kOrderRatio * lo.truth) continue;
      ++*pairs;
      *agree += hi.estimate > lo.estimate ? 1.0 : hi.estimate == lo.estimate ? 0.5 : 0.0;
    }
}

namespace {

// Accumulates one sample's frontier cells.
struct Tally {
  std::string model;
  std::vector<float> ps;
  std::vector<bool> positive;
  std::vector<int> band;  // per cell: its range band (SubgoalEval::kBandEdges)
  double cross_entropy = 0, ps_pos = 0, ps_neg = 0, success = 0, exploration = 0;
  double truth_sum = 0, estimate_sum = 0, order_agree = 0;
  size_t order_pairs = 0;

  void Add(const core::SubgoalCells& out, const core::SubgoalLabelGrid& truth) {
    if (out.empty())
      throw core::ConfigError("<sensor>", "sensor.model", model, "gives no subgoal cells: not a subgoal model");
    TOPONAV_CHECK(
        out.rows == truth.grid.rows && out.cols == truth.grid.cols,
        "network grid " << out.rows << "x" << out.cols << " vs labels " << truth.grid.rows << "x" << truth.grid.cols);
    std::map<float, std::pair<double, int>> frontiers;  // a frontier's cells share its true cost: their sum, count
    for (size_t i = 0; i < truth.mask.size(); ++i) {
      if (!truth.mask[i]) continue;
      const int r = int(i) / out.cols, c = int(i) % out.cols;
      const double p = std::clamp(double(out.at(r, c).ps), 1e-6, 1.0 - 1e-6);
      const bool y = truth.ps[i] > 0.5;
      const double range = truth.grid.RowRange(r);
      ps.push_back(float(p));
      positive.push_back(y);
      band.push_back(range < SubgoalEval::kBandEdges[0] ? 0 : range < SubgoalEval::kBandEdges[1] ? 1 : 2);
      cross_entropy -= y ? std::log(p) : std::log(1.0 - p);
      (y ? ps_pos : ps_neg) += p;
      if (y) {
        success += std::abs(out.at(r, c).delta_success - truth.delta_success[i]);
        continue;
      }
      const double estimate = out.at(r, c).exploration;
      exploration += std::abs(estimate - truth.exploration[i]);
      truth_sum += truth.exploration[i], estimate_sum += estimate;
      auto& [sum, n] = frontiers[truth.exploration[i]];
      sum += estimate, ++n;
    }
    std::vector<FrontierCost> costs;
    for (const auto& [t, s] : frontiers) costs.push_back({t, s.first / s.second});
    CountOrderedPairs(costs, &order_agree, &order_pairs);
  }

  SubgoalEval Summary() const {
    SubgoalEval e;
    e.cells = ps.size();
    e.positives = size_t(std::count(positive.begin(), positive.end(), true));
    const size_t neg = e.cells - e.positives;
    e.auc = RocAuc(ps, positive);
    e.cross_entropy = e.cells ? cross_entropy / double(e.cells) : 0.0;
    e.mean_ps_positive = e.positives ? ps_pos / double(e.positives) : 0.0;
    e.mean_ps_negative = neg ? ps_neg / double(neg) : 0.0;
    e.success_mae = e.positives ? success / double(e.positives) : 0.0;
    e.exploration_mae = neg ? exploration / double(neg) : 0.0;
    e.exploration_truth = neg ? truth_sum / double(neg) : 0.0;
    e.exploration_estimate = neg ? estimate_sum / double(neg) : 0.0;
    e.frontier_pairs = order_pairs;
    e.exploration_order = order_pairs ? order_agree / double(order_pairs) : 0.5;
    for (int b = 0; b < 3; ++b) {
      std::vector<float> scores;
      std::vector<bool> flags;
      for (size_t i = 0; i < ps.size(); ++i)
        if (band[i] == b) scores.push_back(ps[i]), flags.push_back(positive[i]);
      e.band_auc[b] = RocAuc(scores, flags);
      e.band_cells[b] = scores.size();
    }
    return e;
  }
};

}  // namespace

SubgoalEval EvaluateSubgoalEstimates(const Config& config, const LearnedSensorOptions& model,
                                     const SubgoalEvalOptions& options, const std::function<void(int, int)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  SensorConfig learned;
  learned.kind = SensorKind::kLearned;
  learned.learned = model;
  learned.Validate();
  Tally tally;
  tally.model = model.model;
  int examples = 0;
  const bool maze = options.kind == core::WorldKind::kGuidedMaze;
  for (size_t k = 0; k < options.seeds.size(); ++k) {
    const uint64_t seed = options.seeds[k];
    const core::World world = sim::GenerateWorld(options.kind, config.worlds, seed);
    SensorSetup setup{&world, config.render, std::nullopt, seed};
    if (maze) setup.goal = world.goal;
    setup.goal_at_agent = !maze;  // a search's samples: the goal where the agent stands
    const auto sensor = CreateSensor(learned, setup);
    for (const SubgoalSample& s : CollectSubgoalSamples(world, config, seed, options.every, core::kSubgoalGrid)) {
      tally.Add(sensor->Observe(s.pose, 0).subgoal, s.labels);
      ++examples;
    }
    if (progress) progress(int(k + 1), int(options.seeds.size()));
  }
  SubgoalEval e = tally.Summary();
  e.worlds = int(options.seeds.size());
  e.examples = examples;
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

}  // namespace toponav::experiments
