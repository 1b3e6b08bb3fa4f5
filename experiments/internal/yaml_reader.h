#pragma once
// Strict reading of one YAML mapping: every key must be read exactly once (Finish() rejects the rest), and
// every value is type- and range-checked.  Errors are core::ConfigError(file, dotted.key.path, value, why).
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace toponav::experiments::internal {

class YamlSection {
 public:
  YamlSection(YAML::Node node, std::string file, std::string path);

  bool Has(const std::string& key) const;
  // A nested mapping (empty if absent).
  YamlSection Section(const std::string& key);
  // A list of mappings (empty if absent); items are named key[0], key[1], ... in errors.
  std::vector<YamlSection> Sequence(const std::string& key);

  void Read(const std::string& key, double* out, double lo, double hi);
  void Read(const std::string& key, int* out, int lo, int hi);
  void Read(const std::string& key, uint64_t* out);
  void Read(const std::string& key, bool* out);
  void Read(const std::string& key, std::string* out);
  void Read(const std::string& key, std::vector<std::string>* out);

  // Throws for any key of this mapping that was never read.
  void Finish() const;

  [[noreturn]] void Fail(const std::string& key, const std::string& value, const std::string& problem) const;

 private:
  std::string KeyPath(const std::string& key) const;
  YAML::Node Get(const std::string& key);
  std::string Text(const YAML::Node& n) const;

  YAML::Node node_;
  std::string file_, path_;
  std::set<std::string> used_;
};

}  // namespace toponav::experiments::internal
