#include "learning/trainer.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/rng.h"
#include "learning/learning.h"

namespace toponav::learning {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Example {
  core::Panorama image;
  sim::VertexLabelGrid labels;
};

std::vector<Example> RenderSplit(const sim::DatagenOptions& data, sim::Split split, const sim::WorldOptions& worlds,
                                 const sim::RenderOptions& render) {
  const core::RangeBearingGrid grid;
  std::vector<Example> out;
  std::unique_ptr<sim::WorldSampler> sampler;
  sim::SampleId world{};
  for (const auto& id : sim::ListSamples(data, split)) {
    if (!sampler || id.kind != world.kind || id.world_seed != world.world_seed) {
      sampler = std::make_unique<sim::WorldSampler>(id.kind, id.world_seed, worlds, render, grid, data.min_clearance);
      world = id;
    }
    sim::Sample s = sampler->Make(id);
    out.push_back({std::move(s.image), std::move(s.labels)});
  }
  return out;
}

// The example turned by 'cols' label columns (4 image columns each: bearing stays exact).
Example Rolled(const Example& e, int cols) {
  Example r = e;
  const int w = e.image.width, scale = w / e.labels.grid.cols, shift = cols * scale;
  for (int y = 0; y < e.image.height; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k)
        r.image.rgb[3 * (size_t(y) * w + size_t((x + shift) % w)) + size_t(k)] = e.image.rgb[3 * (size_t(y) * w + size_t(x)) + size_t(k)];
  const auto& g = e.labels.grid;
  for (int row = 0; row < g.rows; ++row)
    for (int c = 0; c < g.cols; ++c) r.labels.cells[g.Index(row, (c + cols) % g.cols)] = e.labels.cells[g.Index(row, c)];
  return r;
}

// The training examples of step 'step': epochs are shuffled orders of all examples (a pure function of the
// seed and the epoch), each example rolled by its own random amount.
class BatchOrder {
 public:
  BatchOrder(size_t n, int batch, int seed) : n_(n), batch_(batch), seed_(uint64_t(seed)) {}
  std::vector<std::pair<size_t, int>> Batch(int step) {
    std::vector<std::pair<size_t, int>> out;
    for (int k = 0; k < batch_; ++k) {
      const uint64_t g = uint64_t(step) * uint64_t(batch_) + uint64_t(k), epoch = g / n_;
      core::Rng roll(core::DeriveSeed(seed_ + 1, g));
      out.push_back({Order(epoch)[size_t(g % n_)], roll.UniformInt(0, 127)});
    }
    return out;
  }

 private:
  const std::vector<size_t>& Order(uint64_t epoch) {
    auto it = orders_.find(epoch);
    if (it != orders_.end()) return it->second;
    if (orders_.size() > 2) orders_.erase(orders_.begin());
    std::vector<size_t> order(n_);
    for (size_t i = 0; i < n_; ++i) order[i] = i;
    core::Rng rng(core::DeriveSeed(seed_, epoch));
    rng.Shuffle(order);
    return orders_[epoch] = std::move(order);
  }
  size_t n_;
  int batch_;
  uint64_t seed_;
  std::map<uint64_t, std::vector<size_t>> orders_;
};

double ValidationLoss(const VertexModel& model, const std::vector<Example>& val, int batch_size) {
  double sum = 0;
  int batches = 0;
  for (size_t i = 0; i < val.size(); i += size_t(batch_size)) {
    std::vector<LabelledImage> batch;
    for (size_t k = i; k < std::min(val.size(), i + size_t(batch_size)); ++k) batch.push_back({&val[k].image, &val[k].labels, {}, nullptr});
    sum += model.Loss(batch);
    ++batches;
  }
  return batches > 0 ? sum / batches : 0.0;
}

// What makes two runs the same run (the step count, the decay and the validation cadence may change: a run can
// be extended).
json OptionsJson(const TrainOptions& o) {
  return {{"width", o.width}, {"batch_size", o.batch_size}, {"learning_rate", o.learning_rate}, {"seed", o.seed}};
}

json DataJson(const sim::DatagenOptions& d) {
  std::vector<std::string> kinds;
  for (auto k : d.kinds) kinds.push_back(core::ToString(k));
  return {{"kinds", kinds}, {"train_seeds", {d.train_first_seed, d.train_first_seed + d.train_num_seeds - 1}},
          {"val_seeds", {d.val_first_seed, d.val_first_seed + d.val_num_seeds - 1}},
          {"samples_per_world", d.samples_per_world}, {"min_clearance", d.min_clearance}};
}

void WriteJsonAtomically(const fs::path& path, const json& j) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << j.dump(1) << "\n";
    out.flush();
    if (!out) throw core::DataError(path.string(), "cannot write (disk full?)");
  }
  fs::rename(tmp, path);
}

}  // namespace

namespace {

struct RunState {
  int step = 0;
  int best_step = 0;
  double best_val_loss = -1.0;
};

// A checkpoint of the same options and data in 'dir' to resume from, or a fresh start.
RunState Resume(const fs::path& dir, const json& identity, VertexModel* model, const std::string& device) {
  const fs::path state_file = dir / "train_state.json", checkpoint = dir / "checkpoint.pt";
  if (!fs::exists(state_file) || !fs::exists(checkpoint)) return {};
  json state;
  try {
    std::ifstream in(state_file);
    in >> state;
  } catch (const json::exception&) {
    throw core::DataError(state_file.string(), "unreadable training state: use --fresh to start over");
  }
  if (state.value("identity", json()) != identity)
    throw core::DataError(state_file.string(), "the run in this directory had other options or data: use --fresh or another --out");
  *model = VertexModel::Load(checkpoint.string(), device);
  return {state.at("step").get<int>(), state.at("best_step").get<int>(), state.at("best_val_loss").get<double>()};
}

// After a validation: the best model so far (with its data and metrics in its notes), the checkpoint and
// the state a resumed run starts from.
void Checkpoint(const fs::path& dir, const VertexModel& model, const json& identity, json notes, int step, double val_loss,
                RunState* s) {
  if (s->best_val_loss < 0 || val_loss < s->best_val_loss) {
    s->best_val_loss = val_loss;
    s->best_step = step;
    notes["format"] = "toponav-vertex-net-notes-1";
    notes["step"] = step;
    notes["val_loss"] = val_loss;
    model.Save((dir / "model.pt").string(), notes.dump());
  }
  model.Save((dir / "checkpoint.pt").string());
  WriteJsonAtomically(dir / "train_state.json",
                      {{"identity", identity}, {"step", step}, {"best_step", s->best_step}, {"best_val_loss", s->best_val_loss}});
}

}  // namespace

TrainResult Train(const sim::DatagenOptions& data, const sim::WorldOptions& worlds, const sim::RenderOptions& render,
                  const TrainOptions& o, const std::string& out_dir, bool fresh,
                  const std::function<void(const TrainProgress&)>& report, int report_every) {
  o.Validate();
  data.Validate();
  const auto t0 = std::chrono::steady_clock::now();
  const BackendInfo backend = SelectBackend(o.cuda, o.threads);
  const fs::path dir(out_dir);
  fs::create_directories(dir);
  if (fresh)
    for (const char* f : {"train_state.json", "checkpoint.pt", "model.pt", "train_log.csv"}) fs::remove(dir / f);
  const std::vector<Example> train = RenderSplit(data, sim::Split::kTrain, worlds, render);
  const std::vector<Example> val = RenderSplit(data, sim::Split::kVal, worlds, render);
  if (train.empty() || val.empty()) throw core::ConfigError("<options>", "datagen", "", "training needs training and validation samples");
  const json identity = {{"train", OptionsJson(o)}, {"data", DataJson(data)}};
  VertexNetOptions net;
  net.width = o.width;
  VertexModel model(net, uint64_t(o.seed), backend.device);
  RunState s = Resume(dir, identity, &model, backend.device);
  TrainResult r;
  r.resumed_from = s.step;
  r.train_samples = int(train.size());
  r.val_samples = int(val.size());
  BatchOrder order(train.size(), o.batch_size, o.seed);
  std::ofstream log(dir / "train_log.csv", std::ios::app);
  if (s.step == 0) log << "step,train_loss,val_loss\n";
  double loss_sum = 0;
  int loss_count = 0;
  for (int step = s.step; step < o.steps; ++step) {
    std::vector<Example> rolled;
    for (const auto& [i, cols] : order.Batch(step)) rolled.push_back(Rolled(train[i], cols));
    std::vector<LabelledImage> batch;
    for (const auto& e : rolled) batch.push_back({&e.image, &e.labels, {}, nullptr});
    loss_sum += model.TrainStep(batch, o.LearningRate(step));
    ++loss_count;
    const bool validate = (step + 1) % o.validate_every == 0 || step + 1 == o.steps;
    if (!validate && (step + 1) % report_every != 0) continue;
    TrainProgress p;
    p.step = step + 1;
    p.steps = o.steps;
    p.train_loss = loss_sum / loss_count;
    if (validate) {
      p.val_loss = ValidationLoss(model, val, o.batch_size);
      json notes = identity;
      notes["train_samples"] = train.size();
      notes["val_samples"] = val.size();
      Checkpoint(dir, model, identity, notes, step + 1, p.val_loss, &s);
      log << step + 1 << "," << p.train_loss << "," << p.val_loss << "\n" << std::flush;
    }
    p.best_val_loss = s.best_val_loss;
    p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    p.eta_seconds = p.seconds / double(step + 1 - r.resumed_from) * double(o.steps - step - 1);
    if (report) report(p);
    loss_sum = 0;
    loss_count = 0;
  }
  r.steps = o.steps;
  r.best_step = s.best_step;
  r.best_val_loss = s.best_val_loss;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.model_path = (dir / "model.pt").string();
  return r;
}

}  // namespace toponav::learning
