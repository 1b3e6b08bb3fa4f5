#include "experiments/internal/yaml_reader.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"

namespace toponav::experiments::internal {

YamlSection::YamlSection(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {
  if (node_ && !node_.IsNull() && !node_.IsMap())
    throw core::ConfigError(file_, path_.empty() ? "<top level>" : path_, Text(node_), "expected a mapping of keys");
  if (!node_ || !node_.IsMap()) return;
  // Keys must be plain scalars, each at most once (yaml-cpp keeps duplicates and would use the first).
  std::set<std::string> seen;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar())
      throw core::ConfigError(file_, KeyPath("<key>"), Text(kv.first), "keys must be plain names");
    if (!seen.insert(kv.first.Scalar()).second)
      throw core::ConfigError(file_, KeyPath(kv.first.Scalar()), Text(kv.second), "key given twice");
  }
}

int YamlSection::IntBound(double v) {
  if (v <= double(std::numeric_limits<int>::min())) return std::numeric_limits<int>::min();
  if (v >= double(std::numeric_limits<int>::max())) return std::numeric_limits<int>::max();
  return int(v);
}

std::string YamlSection::KeyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

std::string YamlSection::Text(const YAML::Node& n) const {
  if (!n) return "";
  if (n.IsScalar()) return n.Scalar();
  std::ostringstream os;
  os << n;
  std::string s = os.str();
  for (auto& c : s)
    if (c == '\n') c = ' ';
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

void YamlSection::Fail(const std::string& key, const std::string& value, const std::string& problem) const {
  throw core::ConfigError(file_, KeyPath(key), value, problem);
}

bool YamlSection::Has(const std::string& key) const { return node_ && node_.IsMap() && node_[key]; }

YAML::Node YamlSection::Get(const std::string& key) {
  used_.insert(key);
  return node_[key];
}

YamlSection YamlSection::Section(const std::string& key) {
  if (!Has(key)) return YamlSection(YAML::Node(), file_, KeyPath(key));
  return YamlSection(Get(key), file_, KeyPath(key));
}

std::vector<YamlSection> YamlSection::Sequence(const std::string& key) {
  std::vector<YamlSection> out;
  if (!Has(key)) return out;
  const YAML::Node n = Get(key);
  if (!n.IsSequence()) Fail(key, Text(n), "expected a list");
  for (size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap()) Fail(key + "[" + std::to_string(i) + "]", Text(n[i]), "expected a mapping of keys");
    out.emplace_back(n[i], file_, KeyPath(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

void YamlSection::Read(const std::string& key, double* out, double lo, double hi) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  double v = 0;
  if (n.IsScalar() && n.Tag() == "!") Fail(key, Text(n), "expected a number, not a quoted string");
  try {
    if (!n.IsScalar()) throw YAML::BadConversion(n.Mark());
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    Fail(key, Text(n), "expected a number");
  }
  if (!std::isfinite(v) || v < lo || v > hi) {
    std::ostringstream os;
    os << "out of range: must be in [" << lo << ", " << hi << "]";
    Fail(key, Text(n), os.str());
  }
  *out = v;
}

void YamlSection::Read(const std::string& key, int* out, int lo, int hi) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  long long v = 0;
  if (n.IsScalar() && n.Tag() == "!") Fail(key, Text(n), "expected an integer, not a quoted string");
  try {
    if (!n.IsScalar()) throw YAML::BadConversion(n.Mark());
    v = n.as<long long>();
  } catch (const YAML::Exception&) {
    Fail(key, Text(n), "expected an integer");
  }
  if (v < lo || v > hi)
    Fail(key, Text(n), "out of range: must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  *out = int(v);
}

void YamlSection::Read(const std::string& key, uint64_t* out) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (n.IsScalar() && n.Tag() == "!") Fail(key, Text(n), "expected a non-negative integer, not a quoted string");
  try {
    if (!n.IsScalar() || n.Scalar().empty() || n.Scalar()[0] == '-') throw YAML::BadConversion(n.Mark());
    *out = n.as<uint64_t>();
  } catch (const YAML::Exception&) {
    Fail(key, Text(n), "expected a non-negative integer");
  }
}

void YamlSection::Read(const std::string& key, bool* out) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (n.IsScalar() && n.Tag() == "!") Fail(key, Text(n), "expected true or false, not a quoted string");
  try {
    if (!n.IsScalar()) throw YAML::BadConversion(n.Mark());
    *out = n.as<bool>();
  } catch (const YAML::Exception&) {
    Fail(key, Text(n), "expected true or false");
  }
}

void YamlSection::Read(const std::string& key, std::string* out) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (!n.IsScalar()) Fail(key, Text(n), "expected a string");
  *out = n.Scalar();
}

void YamlSection::Read(const std::string& key, std::vector<std::string>* out) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (!n.IsSequence()) Fail(key, Text(n), "expected a list");
  out->clear();
  for (const auto& item : n) {
    if (!item.IsScalar()) Fail(key, Text(n), "expected a list of strings");
    out->push_back(item.Scalar());
  }
}

void YamlSection::Finish() const {
  if (!node_ || !node_.IsMap()) return;
  for (const auto& kv : node_) {
    const std::string key = kv.first.as<std::string>();
    if (!used_.count(key)) throw core::ConfigError(file_, KeyPath(key), Text(kv.second), "unknown key");
  }
}

}  // namespace toponav::experiments::internal
