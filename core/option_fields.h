#pragma once
// Each options struct declares its YAML keys once, with their ranges: the config reader reads every key with
// that range and the struct's Validate() checks the same ranges (plus its rules between keys), so the two
// can never disagree.
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"

namespace toponav::core {

template <class Options>
struct OptionField {
  const char* key;
  std::variant<double Options::*, int Options::*, bool Options::*> member;
  double lo = -std::numeric_limits<double>::infinity();  // closed range [lo, hi]; ignored for bools
  double hi = std::numeric_limits<double>::infinity();
};
template <class Options>
using OptionFields = std::vector<OptionField<Options>>;

// "must be in [lo, hi]", the words both the reader and Validate() use.
inline std::string RangeText(double lo, double hi) {
  std::ostringstream os;
  os << "must be in [" << lo << ", " << hi << "]";
  return os.str();
}

// Throws ConfigError("<options>", prefix + key, value, "must be in [lo, hi]") for the first field out of its
// range (or not finite).
template <class Options>
void CheckRanges(const Options& o, const OptionFields<Options>& fields, const std::string& prefix) {
  for (const auto& f : fields) {
    double v = 0;
    if (const auto* d = std::get_if<double Options::*>(&f.member)) v = o.*(*d);
    else if (const auto* i = std::get_if<int Options::*>(&f.member)) v = o.*(*i);
    else continue;
    if (!std::isfinite(v) || v < f.lo || v > f.hi) {
      std::ostringstream value;
      value << v;
      throw ConfigError("<options>", prefix + f.key, value.str(), RangeText(f.lo, f.hi));
    }
  }
}

}  // namespace toponav::core
