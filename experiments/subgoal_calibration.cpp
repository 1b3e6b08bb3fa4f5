#include "experiments/subgoal_calibration.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "core/error.h"
#include "experiments/navigation_trial.h"
#include "sim/worlds.h"

namespace toponav::experiments {

namespace {

struct Bin {
  double x = 0, y = 0, weight = 0;  // sums of estimate and truth, and the count
};

// Knots through the bins' means (bins with fewer than CalibrationFit::kMinBinSamples dropped), pooled where a
// bin's mean truth falls below the one before (pool adjacent violators), so y never decreases.
planning::PiecewiseLinear MonotoneKnots(const std::vector<Bin>& bins) {
  std::vector<Bin> pooled;
  for (const Bin& b : bins) {
    if (b.weight < CalibrationFit::kMinBinSamples) continue;
    pooled.push_back(b);
    while (pooled.size() > 1) {
      const Bin& last = pooled.back();
      const Bin& prev = pooled[pooled.size() - 2];
      if (prev.y / prev.weight <= last.y / last.weight) break;
      const Bin merged{prev.x + last.x, prev.y + last.y, prev.weight + last.weight};
      pooled.pop_back();
      pooled.back() = merged;
    }
  }
  planning::PiecewiseLinear f;
  for (const Bin& b : pooled) {
    const double x = b.x / b.weight;
    if (f.knots.empty() || x > f.knots.back().first) f.knots.push_back({x, b.y / b.weight});
  }
  return f;
}

double CrossEntropy(double p, double truth) {
  const double q = std::clamp(p, 1e-4, 1.0 - 1e-4);
  return -(truth * std::log(q) + (1.0 - truth) * std::log(1.0 - q));
}

// The cross-entropy of Ps over 'samples' with each estimate through 'map'.
double ScorePs(const std::vector<PieceSample>& samples, const planning::SubgoalCalibration& map) {
  double ce = 0;
  for (const PieceSample& s : samples) ce += CrossEntropy(map.Apply(s.estimate).ps, s.truth.ps);
  return samples.empty() ? 0.0 : ce / double(samples.size());
}

planning::PiecewiseLinear ReadKnots(const YAML::Node& root, const std::string& key, const std::string& path) {
  planning::PiecewiseLinear f;
  const YAML::Node list = root[key];
  if (!list) return f;
  if (!list.IsSequence()) throw core::ConfigError(path, key, "", "must be a list of [estimate, truth] pairs");
  for (size_t i = 0; i < list.size(); ++i) {
    const YAML::Node pair = list[i];
    const std::string at = fmt::format("{}[{}]", key, i);
    if (!pair.IsSequence() || pair.size() != 2) throw core::ConfigError(path, at, "", "must be [estimate, truth]");
    try {
      f.knots.push_back({pair[0].as<double>(), pair[1].as<double>()});
    } catch (const YAML::Exception&) {
      throw core::ConfigError(path, at, YAML::Dump(pair), "must be two numbers");
    }
  }
  return f;
}

}  // namespace

CalibrationFit FitSubgoalCalibration(const std::vector<PieceSample>& samples) {
  CalibrationFit fit;
  fit.samples = samples.size();
  const auto& edges = CalibrationFit::kPsEdges;
  std::vector<Bin> ps(edges.size() + 1);
  for (const PieceSample& s : samples) {
    Bin& b = ps[size_t(std::upper_bound(edges.begin(), edges.end(), s.estimate.ps) - edges.begin())];
    b.x += s.estimate.ps;
    b.y += s.truth.ps;
    b.weight += 1;
    if (s.truth.ps > 0.5) ++fit.successes;
  }
  fit.calibration.ps = MonotoneKnots(ps);
  fit.cross_entropy = {ScorePs(samples, {}), ScorePs(samples, fit.calibration)};
  return fit;
}

std::vector<PieceSample> MeasurePieceEstimates(const Config& config, const std::vector<uint64_t>& seeds,
                                               const std::function<void(int, int)>& progress) {
  Config raw = config;
  raw.lsp.calibration = {};
  std::vector<PieceSample> out;
  NavigationTrialOptions o;
  o.planner = GoalPlanner::kLsp;
  o.max_steps = config.bench.max_steps;
  o.mcmc_every = config.bench.mcmc_every;
  o.on_subgoal_truth = [&](const std::vector<planning::SubgoalProperties>& estimates,
                           const std::vector<planning::SubgoalProperties>& truth) {
    for (size_t f = 0; f < estimates.size(); ++f) out.push_back({estimates[f], truth[f]});
  };
  for (size_t i = 0; i < seeds.size(); ++i) {
    const core::World w = sim::GenerateWorld(core::WorldKind::kGuidedMaze, raw.worlds, seeds[i]);
    RunNavigationTrial(w, raw, o, seeds[i]);
    if (progress) progress(int(i + 1), int(seeds.size()));
  }
  return out;
}

planning::SubgoalCalibration LoadSubgoalCalibration(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw core::ConfigError(path, "<file>", "", "not a readable file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw core::ConfigError(path, "<file>", "", std::string("not valid YAML: ") + e.what());
  }
  if (root.IsNull()) return {};
  if (!root.IsMap()) throw core::ConfigError(path, "<file>", "", "must be a mapping with the key ps");
  for (const auto& kv : root) {
    const std::string key = kv.first.as<std::string>();
    if (key != "ps") throw core::ConfigError(path, key, "", "unknown key (known: ps)");
  }
  planning::SubgoalCalibration c{ReadKnots(root, "ps", path)};
  c.Validate(path);
  return c;
}

std::string SubgoalCalibrationYaml(const planning::SubgoalCalibration& c, const std::vector<std::string>& comment) {
  std::ostringstream os;
  for (const std::string& line : comment) os << "# " << line << "\n";
  os << "ps: [";
  for (size_t i = 0; i < c.ps.knots.size(); ++i)
    os << (i ? ", " : "") << fmt::format("[{:.4g}, {:.4g}]", c.ps.knots[i].first, c.ps.knots[i].second);
  os << "]\n";
  return os.str();
}

}  // namespace toponav::experiments
