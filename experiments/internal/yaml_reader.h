#pragma once
// Strict reading of one YAML mapping: every key must be read exactly once (Finish() rejects the rest), and
// every value is type- and range-checked.  Errors are core::ConfigError(file, dotted.key.path, value, why).
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "core/option_fields.h"

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

  // Reads every key an options struct declares (core/option_fields.h), with its range.
  template <class Options>
  void ReadFields(Options* o, const core::OptionFields<Options>& fields) {
    for (const auto& f : fields) {
      if (const auto* d = std::get_if<double Options::*>(&f.member)) Read(f.key, &(o->*(*d)), f.lo, f.hi);
      else if (const auto* i = std::get_if<int Options::*>(&f.member))
        Read(f.key, &(o->*(*i)), IntBound(f.lo), IntBound(f.hi));
      else Read(f.key, &(o->*std::get<bool Options::*>(f.member)));
    }
  }

 private:
  static int IntBound(double v);  // a field's bound as an int (infinite: the int's limit)
  std::string KeyPath(const std::string& key) const;
  YAML::Node Get(const std::string& key);
  std::string Text(const YAML::Node& n) const;

  YAML::Node node_;
  std::string file_, path_;
  std::set<std::string> used_;
};

}  // namespace toponav::experiments::internal
