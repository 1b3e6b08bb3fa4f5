#include "learning/trainer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/detection.h"
#include "core/error.h"
#include "core/geometry.h"
#include "core/rng.h"
#include "learning/internal/columns.h"
#include "learning/learning.h"

namespace toponav::learning {

namespace fs = std::filesystem;
using nlohmann::json;

using internal::MoveColumns;

namespace {

// The example with column c of each of its grids (the image, the vertex labels, the subgoal labels) moved to
// column to(c, the grid's width); the label values and the goal as they were.
template <class To>
TrainingExample ColumnsMoved(const TrainingExample& e, const To& to) {
  TrainingExample r = e;
  MoveColumns(e.image.rgb, e.image.height, e.image.width, 3, to, &r.image.rgb);
  MoveColumns(e.labels.cells, e.labels.grid.rows, e.labels.grid.cols, 1, to, &r.labels.cells);
  if (e.subgoal) {
    const auto& sg = e.subgoal->grid;
    MoveColumns(e.subgoal->mask, sg.rows, sg.cols, 1, to, &r.subgoal->mask);
    for (auto field : {&core::SubgoalLabelGrid::ps, &core::SubgoalLabelGrid::delta_success,
                       &core::SubgoalLabelGrid::exploration})
      MoveColumns((*e.subgoal).*field, sg.rows, sg.cols, 1, to, &((*r.subgoal).*field));
  }
  return r;
}

}  // namespace

TrainingSet RenderVertexExamples(const sim::DatagenOptions& data, const sim::WorldOptions& worlds,
                                 const sim::RenderOptions& render) {
  data.Validate();
  const core::RangeBearingGrid grid;
  TrainingSet set;
  for (const sim::Split split : {sim::Split::kTrain, sim::Split::kVal}) {
    std::unique_ptr<sim::WorldSampler> sampler;
    sim::SampleId world{};
    for (const auto& id : sim::ListSamples(data, split)) {
      if (!sampler || id.kind != world.kind || id.world_seed != world.world_seed) {
        sampler = std::make_unique<sim::WorldSampler>(id.kind, id.world_seed, worlds, render, grid, data);
        world = id;
      }
      sim::Sample s = sampler->Make(id);
      (split == sim::Split::kTrain ? set.train : set.val)
          .push_back({std::move(s.image), std::move(s.labels), {}, std::nullopt});
    }
  }
  set.identity_json = sim::DatagenJson(data).dump();
  return set;
}

TrainingExample Rolled(const TrainingExample& e, int cols) {
  const int label_cols = e.labels.grid.cols;
  TrainingExample r = ColumnsMoved(e, [&](int c, int width) { return (c + cols * width / label_cols) % width; });
  r.goal.bearing = core::WrapAngle(e.goal.bearing + cols * 2.0 * M_PI / label_cols);
  return r;
}

TrainingExample Mirrored(const TrainingExample& e) {
  TrainingExample r = ColumnsMoved(e, internal::MirrorColumn);
  const uint8_t right = 1 + uint8_t(core::VertexLabel::kRightGap), left = 1 + uint8_t(core::VertexLabel::kLeftGap);
  for (auto& v : r.labels.cells) v = v == right ? left : v == left ? right : v;
  r.goal.bearing = core::WrapAngle(-e.goal.bearing);
  return r;
}

namespace {

// One example of a batch: which, turned by how many label columns, and whether mirrored first.
struct Draw {
  size_t index = 0;
  int cols = 0;
  bool mirror = false;
};

// The training examples of step 'step': epochs are shuffled orders of all examples (a pure function of the
// seed and the epoch), each example rolled by its own random amount and, with 'mirror', mirrored with
// probability one half.
class BatchOrder {
 public:
  BatchOrder(size_t n, int batch, int seed, bool mirror)
      : n_(n), batch_(batch), seed_(uint64_t(seed)), mirror_(mirror) {}
  std::vector<Draw> Batch(int step) {
    std::vector<Draw> out;
    for (int k = 0; k < batch_; ++k) {
      const uint64_t g = uint64_t(step) * uint64_t(batch_) + uint64_t(k), epoch = g / n_;
      core::Rng roll(core::DeriveSeed(seed_ + 1, g));
      Draw d{Order(epoch)[size_t(g % n_)], roll.UniformInt(0, 127)};
      d.mirror = mirror_ && roll.UniformInt(0, 1) == 1;
      out.push_back(d);
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
  bool mirror_;
  std::map<uint64_t, std::vector<size_t>> orders_;
};

LabelledImage Labelled(const TrainingExample& e) {
  return {&e.image, &e.labels, e.goal, e.subgoal ? &*e.subgoal : nullptr};
}

double ValidationLoss(const VertexModel& model, const std::vector<TrainingExample>& val, int batch_size) {
  double sum = 0;
  int batches = 0;
  for (size_t i = 0; i < val.size(); i += size_t(batch_size)) {
    std::vector<LabelledImage> batch;
    for (size_t k = i; k < std::min(val.size(), i + size_t(batch_size)); ++k) batch.push_back(Labelled(val[k]));
    sum += model.Loss(batch);
    ++batches;
  }
  return batches > 0 ? sum / batches : 0.0;
}

// What makes two runs the same run (the step count, the decay and the validation cadence may change: a run can
// be extended).
json OptionsJson(const TrainOptions& o) {
  json j = {{"width", o.width}, {"batch_size", o.batch_size}, {"learning_rate", o.learning_rate},
            {"seed", o.seed},   {"subgoal", o.subgoal},       {"init_from", o.init_from},
            {"vertex_weight", o.vertex_weight}};
  if (o.mirror) j["mirror"] = true;  // absent when off: a run without mirroring keeps its identity
  return j;
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
    throw core::DataError(state_file.string(),
                          "the run in this directory had other options or data: use --fresh or another --out");
  *model = VertexModel::Load(checkpoint.string(), device);
  return {state.at("step").get<int>(), state.at("best_step").get<int>(), state.at("best_val_loss").get<double>()};
}

// After a validation: the best model so far (with its data and metrics in its notes), the checkpoint and
// the state a resumed run starts from.
void Checkpoint(const fs::path& dir, const VertexModel& model, const json& identity, json notes, int step,
                double val_loss, RunState* s) {
  if (s->best_val_loss < 0 || val_loss < s->best_val_loss) {
    s->best_val_loss = val_loss;
    s->best_step = step;
    notes["format"] = "toponav-vertex-net-notes-1";
    notes["step"] = step;
    notes["val_loss"] = val_loss;
    model.Save((dir / "model.pt").string(), notes.dump());
  }
  model.Save((dir / "checkpoint.pt").string());
  WriteJsonAtomically(
      dir / "train_state.json",
      {{"identity", identity}, {"step", step}, {"best_step", s->best_step}, {"best_val_loss", s->best_val_loss}});
}

}  // namespace

namespace {

// Both splits non-empty; with options.subgoal, every example labelled for it.
void CheckExamples(const TrainingSet& data, const TrainOptions& o) {
  if (data.train.empty() || data.val.empty())
    throw core::ConfigError("<options>", "datagen", "", "training needs training and validation samples");
  if (o.subgoal)
    for (const auto* split : {&data.train, &data.val})
      for (const auto& e : *split)
        if (!e.subgoal)
          throw core::ConfigError("<options>", "train.subgoal", "true", "every example needs subgoal labels");
}

// A fresh model for the options: random weights, or those of options.init_from where they fit.
VertexModel InitialModel(const TrainOptions& o, const std::string& device) {
  VertexNetOptions net;
  net.width = o.width;
  net.subgoal = o.subgoal;
  net.vertex_weight = o.vertex_weight;
  VertexModel model(net, uint64_t(o.seed), device);
  if (!o.init_from.empty() && model.InitFrom(VertexModel::Load(o.init_from, device)) == 0)
    throw core::DataError(o.init_from, "none of its weights fit the network to train (another width?)");
  return model;
}

}  // namespace

TrainResult Train(const TrainingSet& data, const TrainOptions& o, const std::string& out_dir, bool fresh,
                  const std::function<void(const TrainProgress&)>& report, int report_every) {
  o.Validate();
  const auto t0 = std::chrono::steady_clock::now();
  const BackendInfo backend = SelectBackend(o.cuda, o.threads);
  const fs::path dir(out_dir);
  fs::create_directories(dir);
  if (fresh)
    for (const char* f : {"train_state.json", "checkpoint.pt", "model.pt", "train_log.csv"}) fs::remove(dir / f);
  CheckExamples(data, o);
  const std::vector<TrainingExample>& train = data.train;
  const std::vector<TrainingExample>& val = data.val;
  const json identity = {{"train", OptionsJson(o)}, {"data", json::parse(data.identity_json)}};
  VertexModel model = InitialModel(o, backend.device);
  RunState s = Resume(dir, identity, &model, backend.device);
  TrainResult r;
  r.resumed_from = s.step;
  r.train_samples = int(train.size());
  r.val_samples = int(val.size());
  BatchOrder order(train.size(), o.batch_size, o.seed, o.mirror);
  std::ofstream log(dir / "train_log.csv", std::ios::app);
  if (s.step == 0) log << "step,train_loss,val_loss\n";
  double loss_sum = 0;
  int loss_count = 0;
  for (int step = s.step; step < o.steps; ++step) {
    std::vector<TrainingExample> rolled;
    for (const Draw& d : order.Batch(step))
      rolled.push_back(Rolled(d.mirror ? Mirrored(train[d.index]) : train[d.index], d.cols));
    std::vector<LabelledImage> batch;
    for (const auto& e : rolled) batch.push_back(Labelled(e));
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

TrainResult Train(const sim::DatagenOptions& data, const sim::WorldOptions& worlds, const sim::RenderOptions& render,
                  const TrainOptions& options, const std::string& out_dir, bool fresh,
                  const std::function<void(const TrainProgress&)>& report, int report_every) {
  options.Validate();
  return Train(RenderVertexExamples(data, worlds, render), options, out_dir, fresh, report, report_every);
}

}  // namespace toponav::learning
