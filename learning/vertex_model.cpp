#include "learning/vertex_model.h"

#include <torch/torch.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "learning/internal/vertex_net.h"

namespace toponav::learning {

namespace F = torch::nn::functional;
using nlohmann::json;

namespace {

constexpr const char* kFormat = "toponav-vertex-net-1";
// Every key Save writes; Load refuses others.
constexpr const char* kMetadataKeys[] = {"format", "width", "positive_weight", "vertex_weight", "subgoal", "notes"};
constexpr const char* kMetadataKey = "toponav_metadata";

torch::Tensor ImageTensor(const core::Panorama& p) {
  if (p.width != 512 || p.height != 128 || p.rgb.size() != size_t(3 * 512 * 128))
    throw core::DataError("<panorama>", "the vertex network takes 128x512 RGB panoramas, got " +
                                            std::to_string(p.height) + "x" + std::to_string(p.width));
  auto t = torch::from_blob(const_cast<uint8_t*>(p.rgb.data()), {p.height, p.width, 3}, torch::kUInt8);
  return t.permute({2, 0, 1}).to(torch::kFloat32).div(255.0);
}

torch::Tensor LabelTensor(const sim::VertexLabelGrid& g) {
  TOPONAV_CHECK(g.grid.rows == 32 && g.grid.cols == 128 && g.cells.size() == g.grid.size(), "labels must be 32x128");
  return torch::from_blob(const_cast<uint8_t*>(g.cells.data()), {32, 128}, torch::kUInt8).to(torch::kInt64);
}

// [4, 64, 256]: mask, Ps, success cost, exploration cost.
torch::Tensor SubgoalTensor(const core::SubgoalLabelGrid& g) {
  TOPONAV_CHECK(g.grid.rows == 64 && g.grid.cols == 256 && g.mask.size() == g.grid.size() &&
                    g.ps.size() == g.grid.size() && g.delta_success.size() == g.grid.size() &&
                    g.exploration.size() == g.grid.size(),
                "subgoal labels must be 64x256");
  const auto f = [](const std::vector<float>& v) {
    return torch::from_blob(const_cast<float*>(v.data()), {64, 256}, torch::kFloat32);
  };
  const auto mask = torch::from_blob(const_cast<uint8_t*>(g.mask.data()), {64, 256}, torch::kUInt8).to(torch::kFloat32);
  return torch::stack({mask, f(g.ps), f(g.delta_success), f(g.exploration)});
}

// Sum of v over the mask's cells / (the mask's count + 1) (lsp.md §2.7: a masked mean that is 0 when empty).
torch::Tensor MaskedMean(const torch::Tensor& v, const torch::Tensor& mask) {
  return (v * mask).sum() / (mask.sum() + 1.0);
}

}  // namespace

struct VertexModel::Impl {
  VertexNetOptions options;
  std::string notes;
  torch::Device device{torch::kCPU};
  internal::VertexNet net{nullptr};   // the vertex network, or ...
  internal::SubgoalNet sub{nullptr};  // ... its LSP extension (options.subgoal)
  std::unique_ptr<torch::optim::Adam> adam;

  torch::nn::Module& module() { return options.subgoal ? static_cast<torch::nn::Module&>(*sub) : *net; }
  // Vertex logits [B, 5, 32, 128] and subgoal outputs [B, 3, 64, 256] (undefined without the extension).
  std::pair<torch::Tensor, torch::Tensor> Run(const torch::Tensor& images, const std::vector<GoalInView>& goals) {
    if (!options.subgoal) return {net->forward(images), torch::Tensor()};
    std::vector<torch::Tensor> g;
    for (const auto& goal : goals) g.push_back(internal::GoalImage(goal.range, goal.bearing));
    return sub->forward(images, torch::stack(g).to(device));
  }

  // vertex_weight * weighted BCE on the vertex logit + the label cross-entropy over vertex cells, and for the
  // extension the masked subgoal terms.
  torch::Tensor BatchLoss(const std::vector<LabelledImage>& batch) {
    TOPONAV_CHECK(!batch.empty(), "an empty batch");
    std::vector<torch::Tensor> images, labels, subgoal;
    std::vector<GoalInView> goals;
    for (const auto& b : batch) {
      images.push_back(ImageTensor(*b.image));
      labels.push_back(LabelTensor(*b.labels));
      goals.push_back(b.goal);
      if (options.subgoal) {
        TOPONAV_CHECK(b.subgoal, "a subgoal model's training example without subgoal labels");
        subgoal.push_back(SubgoalTensor(*b.subgoal));
      }
    }
    const auto [logits, out] = Run(torch::stack(images).to(device), goals);
    auto loss = VertexLoss(logits, torch::stack(labels).to(device));
    if (options.subgoal) loss = loss + SubgoalLoss(out, torch::stack(subgoal).to(device));
    return loss;
  }

  torch::Tensor VertexLoss(const torch::Tensor& logits, const torch::Tensor& cells) const {
    const auto is_vertex = cells.gt(0).to(torch::kFloat32);
    const auto bce =
        F::binary_cross_entropy_with_logits(logits.select(1, 0), is_vertex,
                                            F::BinaryCrossEntropyWithLogitsFuncOptions().pos_weight(
                                                torch::full({1}, options.positive_weight, logits.options())));
    const auto log_p = F::log_softmax(logits.slice(1, 1, 5), 1);
    const auto target = (cells - 1).clamp_min(0);
    const auto nll = -log_p.gather(1, target.unsqueeze(1)).squeeze(1);
    return options.vertex_weight * bce + MaskedMean(nll, is_vertex);
  }

  // out [B, 3, 64, 256] (Ps logit, success cost, exploration cost); labels [B, 4, 64, 256] (mask, Ps, costs).
  static torch::Tensor SubgoalLoss(const torch::Tensor& out, const torch::Tensor& labels) {
    const auto mask = labels.select(1, 0), y = labels.select(1, 1);
    const auto bce = F::binary_cross_entropy_with_logits(
        out.select(1, 0), y, F::BinaryCrossEntropyWithLogitsFuncOptions().reduction(torch::kNone));
    const auto ds = (out.select(1, 1) - labels.select(1, 2)).pow(2) / 1e4;
    const auto re = (out.select(1, 2) - labels.select(1, 3)).pow(2) / 4e4;
    return MaskedMean(bce, mask) + MaskedMean(ds, mask * y) + MaskedMean(re, mask * (1 - y));
  }
};

VertexModel::VertexModel(const VertexNetOptions& options, uint64_t seed, const std::string& device)
    : impl_(std::make_unique<Impl>()) {
  if (!(options.width > 0 && options.width <= 4))
    throw core::ConfigError("<options>", "model.width", std::to_string(options.width), "must be in (0, 4]");
  torch::manual_seed(seed);
  impl_->options = options;
  impl_->device = torch::Device(device);
  if (options.subgoal)
    impl_->sub = internal::SubgoalNet(options.width);
  else
    impl_->net = internal::VertexNet(options.width);
  impl_->module().to(impl_->device);
}
VertexModel::~VertexModel() = default;
VertexModel::VertexModel(VertexModel&&) noexcept = default;
VertexModel& VertexModel::operator=(VertexModel&&) noexcept = default;

namespace {

std::vector<float> Values(const torch::Tensor& t) {
  const auto c = t.contiguous();
  return {c.data_ptr<float>(), c.data_ptr<float>() + c.numel()};
}

GridOutput VertexGrid(const torch::Tensor& logits) {  // [5, 32, 128]
  GridOutput out;
  out.vertex = Values(torch::sigmoid(logits.select(0, 0)));
  out.labels = Values(torch::softmax(logits.slice(0, 1, 5), 0).permute({1, 2, 0}));  // [32, 128, 4]
  return out;
}

}  // namespace

std::pair<GridOutput, SubgoalOutput> VertexModel::PredictWithGoal(const core::Panorama& image,
                                                                  const GoalInView& goal) const {
  TOPONAV_CHECK(impl_->options.subgoal, "PredictWithGoal on a model without the subgoal extension");
  c10::InferenceMode inference;  // no autograd bookkeeping at all
  impl_->module().eval();
  const auto [logits, out] = impl_->Run(ImageTensor(image).unsqueeze(0).to(impl_->device), {goal});
  SubgoalOutput s;
  const auto o = out.squeeze(0).to(torch::kCPU);
  s.ps = Values(torch::sigmoid(o.select(0, 0)));
  s.delta_success = Values(o.select(0, 1));
  s.exploration = Values(o.select(0, 2));
  return {VertexGrid(logits.squeeze(0).to(torch::kCPU)), s};
}

GridOutput VertexModel::Predict(const core::Panorama& image) const {
  if (impl_->options.subgoal) return PredictWithGoal(image, {}).first;
  c10::InferenceMode inference;  // no autograd bookkeeping at all
  impl_->module().eval();
  return VertexGrid(impl_->net->forward(ImageTensor(image).unsqueeze(0).to(impl_->device)).squeeze(0).to(torch::kCPU));
}

double VertexModel::Loss(const std::vector<LabelledImage>& batch) const {
  c10::InferenceMode inference;  // no autograd bookkeeping at all
  impl_->module().eval();
  return impl_->BatchLoss(batch).item<double>();
}

double VertexModel::TrainStep(const std::vector<LabelledImage>& batch, double lr) {
  impl_->module().train();
  if (!impl_->adam)
    impl_->adam = std::make_unique<torch::optim::Adam>(impl_->module().parameters(), torch::optim::AdamOptions(lr));
  for (auto& group : impl_->adam->param_groups())
    static_cast<torch::optim::AdamOptions&>(group.options()).lr(lr);  // keeps the moments
  const auto loss = impl_->BatchLoss(batch);
  impl_->adam->zero_grad();
  loss.backward();
  impl_->adam->step();
  return loss.item<double>();
}

namespace {

constexpr int kModulesPerEncoderBlock = 7;  // conv, BatchNormLeaky, Identity twice, max-pool

// A tensor's name in the vertex network's terms (a subgoal network's encoder is split in two at block 3).
std::string CanonicalName(const std::string& name) {
  const auto rest = [&](size_t n) { return name.substr(n); };
  if (name.rfind("vertex_head.", 0) == 0) return "head." + rest(12);
  if (name.rfind("encoder_a.", 0) == 0) return "encoder." + rest(10);
  if (name.rfind("encoder_b.", 0) == 0) {
    const size_t dot = name.find('.', 10);
    return "encoder." + std::to_string(std::stoi(name.substr(10, dot - 10)) + 2 * kModulesPerEncoderBlock) +
           name.substr(dot);
  }
  return name;
}

std::map<std::string, torch::Tensor> CanonicalTensors(torch::nn::Module& m) {
  std::map<std::string, torch::Tensor> out;
  for (const auto& t : m.named_parameters()) out[CanonicalName(t.key())] = t.value();
  for (const auto& t : m.named_buffers()) out[CanonicalName(t.key())] = t.value();
  return out;
}

}  // namespace

namespace {

// How 'src' fits 'to': 2 the same shape, 1 a convolution's input channels plus the goal's 2, 0 not at all.
int Fit(const torch::Tensor& src, const torch::Tensor& to) {
  if (src.sizes() == to.sizes()) return 2;
  const bool goal_channels = src.dim() == 4 && to.dim() == 4 && to.size(0) == src.size(0) &&
                             to.size(1) == src.size(1) + 2 && to.size(2) == src.size(2) && to.size(3) == src.size(3);
  return goal_channels ? 1 : 0;
}

}  // namespace

int VertexModel::InitFrom(const VertexModel& source) {
  torch::NoGradGuard no_grad;
  const auto from = CanonicalTensors(source.impl_->module());
  const auto into = CanonicalTensors(impl_->module());
  for (const auto& [name, to] : into)
    if (from.count(name) && Fit(from.at(name), to) == 0) return 0;  // another architecture: all or nothing
  int copied = 0;
  for (const auto& [name, to] : into) {
    if (!from.count(name)) continue;
    const torch::Tensor& src = from.at(name);
    torch::Tensor target =
        Fit(src, to) == 2 ? to : to.slice(1, 0, src.size(1));  // image channels first, the goal's after
    target.copy_(src.to(to.device()));
    ++copied;
  }
  return copied;
}

const VertexNetOptions& VertexModel::options() const { return impl_->options; }
const std::string& VertexModel::notes() const { return impl_->notes; }

int64_t VertexModel::num_parameters() const {
  int64_t n = 0;
  for (const auto& p : impl_->module().parameters()) n += p.numel();
  return n;
}

void VertexModel::Save(const std::string& path, const std::string& notes) const {
  json meta;
  meta["format"] = kFormat;
  meta["width"] = impl_->options.width;
  meta["positive_weight"] = impl_->options.positive_weight;
  meta["vertex_weight"] = impl_->options.vertex_weight;
  meta["subgoal"] = impl_->options.subgoal;
  meta["notes"] = notes;
  torch::serialize::OutputArchive archive;
  impl_->module().save(archive);
  archive.write(kMetadataKey, c10::IValue(meta.dump()));
  try {
    archive.save_to(path);
  } catch (const c10::Error& e) {
    throw core::DataError(path, "cannot write the model file");
  }
  impl_->notes = notes;
}

VertexModel VertexModel::Load(const std::string& path, const std::string& device) {
  if (!std::filesystem::is_regular_file(path)) throw core::DataError(path, "no such model file");
  torch::serialize::InputArchive archive;
  try {
    archive.load_from(path);
  } catch (const c10::Error&) {
    throw core::DataError(path, "not a readable model file (truncated, or not a toponav/LibTorch archive)");
  }
  c10::IValue value;
  json meta;
  try {
    if (!archive.try_read(kMetadataKey, value) || !value.isString()) throw std::runtime_error("no metadata");
    meta = json::parse(value.toStringRef());
    if (meta.at("format").get<std::string>() != kFormat) throw std::runtime_error("format " + meta.at("format").dump());
  } catch (const std::exception& e) {
    throw core::DataError(path, std::string("not a toponav vertex-network file (") + e.what() + ")");
  }
  // A key this build does not know may change what the outputs mean: refuse it rather than read the model
  // under the old meaning.
  for (const auto& item : meta.items())
    if (std::find(std::begin(kMetadataKeys), std::end(kMetadataKeys), item.key()) == std::end(kMetadataKeys))
      throw core::DataError(path, "its metadata has the key '" + item.key() +
                                      "', unknown to this toponav build (a newer one wrote it): rebuild toponav");
  VertexNetOptions o;
  o.width = meta.value("width", 1.0);
  o.positive_weight = meta.value("positive_weight", 8.0);
  o.vertex_weight = meta.value("vertex_weight", 500.0);
  o.subgoal = meta.value("subgoal", false);
  VertexModel model(o, 0, device);
  // (Module::load replaces tensors whatever their shape: compare every shape with the declared architecture.)
  std::vector<std::vector<int64_t>> expected;
  torch::nn::Module& net = model.impl_->module();
  for (const auto& t : net.named_parameters()) expected.push_back(t.value().sizes().vec());
  for (const auto& t : net.named_buffers()) expected.push_back(t.value().sizes().vec());
  bool fits = true;
  try {
    net.load(archive);
    size_t k = 0;
    for (const auto& t : net.named_parameters()) fits = fits && t.value().sizes().vec() == expected[k++];
    for (const auto& t : net.named_buffers()) fits = fits && t.value().sizes().vec() == expected[k++];
  } catch (const c10::Error&) {
    fits = false;
  }
  if (!fits)
    throw core::DataError(
        path, "its weights do not fit the architecture it declares (width " + std::to_string(o.width) + ")");
  net.to(model.impl_->device);
  model.impl_->notes = meta.value("notes", "");
  return model;
}

}  // namespace toponav::learning
