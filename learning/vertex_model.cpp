#include "learning/vertex_model.h"

#include <torch/torch.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "learning/internal/vertex_net.h"

namespace toponav::learning {

namespace F = torch::nn::functional;
using nlohmann::json;

namespace {

constexpr const char* kFormat = "toponav-vertex-net-1";
constexpr const char* kMetadataKey = "toponav_metadata";

torch::Tensor ImageTensor(const core::Panorama& p) {
  if (p.width != 512 || p.height != 128 || p.rgb.size() != size_t(3 * 512 * 128))
    throw core::DataError("<panorama>", "the vertex network takes 128x512 RGB panoramas, got " + std::to_string(p.height) +
                                             "x" + std::to_string(p.width));
  auto t = torch::from_blob(const_cast<uint8_t*>(p.rgb.data()), {p.height, p.width, 3}, torch::kUInt8);
  return t.permute({2, 0, 1}).to(torch::kFloat32).div(255.0);
}

torch::Tensor LabelTensor(const sim::VertexLabelGrid& g) {
  TOPONAV_CHECK(g.grid.rows == 32 && g.grid.cols == 128 && g.cells.size() == g.grid.size(), "labels must be 32x128");
  return torch::from_blob(const_cast<uint8_t*>(g.cells.data()), {32, 128}, torch::kUInt8).to(torch::kInt64);
}

}  // namespace

struct VertexModel::Impl {
  VertexNetOptions options;
  std::string notes;
  torch::Device device{torch::kCPU};
  internal::VertexNet net{nullptr};
  std::unique_ptr<torch::optim::Adam> adam;

  // [B, 5, 32, 128] logits and the batch's labels [B, 32, 128].
  std::pair<torch::Tensor, torch::Tensor> Forward(const std::vector<LabelledImage>& batch) {
    TOPONAV_CHECK(!batch.empty(), "an empty batch");
    std::vector<torch::Tensor> images, labels;
    for (const auto& b : batch) {
      images.push_back(ImageTensor(*b.image));
      labels.push_back(LabelTensor(*b.labels));
    }
    return {net->forward(torch::stack(images).to(device)), torch::stack(labels).to(device)};
  }

  // vertex_weight * weighted BCE on the vertex logit + the label cross-entropy over vertex cells.
  torch::Tensor LossOf(const torch::Tensor& logits, const torch::Tensor& cells) const {
    const auto is_vertex = cells.gt(0).to(torch::kFloat32);
    const auto bce = F::binary_cross_entropy_with_logits(
        logits.select(1, 0), is_vertex,
        F::BinaryCrossEntropyWithLogitsFuncOptions().pos_weight(torch::full({1}, options.positive_weight, logits.options())));
    const auto log_p = F::log_softmax(logits.slice(1, 1, 5), 1);
    const auto target = (cells - 1).clamp_min(0);
    const auto nll = -log_p.gather(1, target.unsqueeze(1)).squeeze(1);
    const auto label_term = (nll * is_vertex).sum() / (is_vertex.sum() + 1.0);
    return options.vertex_weight * bce + label_term;
  }
};

VertexModel::VertexModel(const VertexNetOptions& options, uint64_t seed, const std::string& device)
    : impl_(std::make_unique<Impl>()) {
  if (!(options.width > 0 && options.width <= 4))
    throw core::ConfigError("<options>", "model.width", std::to_string(options.width), "must be in (0, 4]");
  torch::manual_seed(seed);
  impl_->options = options;
  impl_->device = torch::Device(device);
  impl_->net = internal::VertexNet(options.width);
  impl_->net->to(impl_->device);
}
VertexModel::~VertexModel() = default;
VertexModel::VertexModel(VertexModel&&) noexcept = default;
VertexModel& VertexModel::operator=(VertexModel&&) noexcept = default;

GridOutput VertexModel::Predict(const core::Panorama& image) const {
  torch::NoGradGuard no_grad;
  impl_->net->eval();
  const auto logits = impl_->net->forward(ImageTensor(image).unsqueeze(0).to(impl_->device)).squeeze(0).to(torch::kCPU);
  GridOutput out;
  const auto vertex = torch::sigmoid(logits.select(0, 0)).contiguous();
  const auto labels = torch::softmax(logits.slice(0, 1, 5), 0).permute({1, 2, 0}).contiguous();  // [32, 128, 4]
  out.vertex.assign(vertex.data_ptr<float>(), vertex.data_ptr<float>() + vertex.numel());
  out.labels.assign(labels.data_ptr<float>(), labels.data_ptr<float>() + labels.numel());
  return out;
}

double VertexModel::Loss(const std::vector<LabelledImage>& batch) const {
  torch::NoGradGuard no_grad;
  impl_->net->eval();
  const auto [logits, cells] = impl_->Forward(batch);
  return impl_->LossOf(logits, cells).item<double>();
}

double VertexModel::TrainStep(const std::vector<LabelledImage>& batch, double lr) {
  impl_->net->train();
  if (!impl_->adam) impl_->adam = std::make_unique<torch::optim::Adam>(impl_->net->parameters(), torch::optim::AdamOptions(lr));
  for (auto& group : impl_->adam->param_groups()) static_cast<torch::optim::AdamOptions&>(group.options()).lr(lr);  // keeps the moments
  const auto [logits, cells] = impl_->Forward(batch);
  const auto loss = impl_->LossOf(logits, cells);
  impl_->adam->zero_grad();
  loss.backward();
  impl_->adam->step();
  return loss.item<double>();
}

const VertexNetOptions& VertexModel::options() const { return impl_->options; }
const std::string& VertexModel::notes() const { return impl_->notes; }

int64_t VertexModel::num_parameters() const {
  int64_t n = 0;
  for (const auto& p : impl_->net->parameters()) n += p.numel();
  return n;
}

void VertexModel::Save(const std::string& path, const std::string& notes) const {
  json meta;
  meta["format"] = kFormat;
  meta["width"] = impl_->options.width;
  meta["positive_weight"] = impl_->options.positive_weight;
  meta["vertex_weight"] = impl_->options.vertex_weight;
  meta["notes"] = notes;
  torch::serialize::OutputArchive archive;
  impl_->net->save(archive);
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
  VertexNetOptions o;
  o.width = meta.value("width", 1.0);
  o.positive_weight = meta.value("positive_weight", 8.0);
  o.vertex_weight = meta.value("vertex_weight", 500.0);
  VertexModel model(o, 0, device);
  // (Module::load replaces tensors whatever their shape: compare every shape with the declared architecture.)
  std::vector<std::vector<int64_t>> expected;
  for (const auto& t : model.impl_->net->named_parameters()) expected.push_back(t.value().sizes().vec());
  for (const auto& t : model.impl_->net->named_buffers()) expected.push_back(t.value().sizes().vec());
  bool fits = true;
  try {
    model.impl_->net->load(archive);
    size_t k = 0;
    for (const auto& t : model.impl_->net->named_parameters()) fits = fits && t.value().sizes().vec() == expected[k++];
    for (const auto& t : model.impl_->net->named_buffers()) fits = fits && t.value().sizes().vec() == expected[k++];
  } catch (const c10::Error&) {
    fits = false;
  }
  if (!fits) throw core::DataError(path, "its weights do not fit the architecture it declares (width " + std::to_string(o.width) + ")");
  model.impl_->net->to(model.impl_->device);
  model.impl_->notes = meta.value("notes", "");
  return model;
}

}  // namespace toponav::learning
