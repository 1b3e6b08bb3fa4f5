#pragma once
// Seeded random numbers. There is no global RNG: every component takes an Rng& (or a seed) explicitly.
// The engine (xoshiro256**) and every distribution are implemented here rather than taken from <random>,
// whose distributions differ between standard libraries: the same seed gives the same world everywhere.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace toponav::core {

// Seeds a user gives (command line, configs) lie in [0, kMaxSeed], so seed ranges never wrap around.
constexpr uint64_t kMaxSeed = uint64_t(1) << 62;

// Seed for trial 'trial_index' of an experiment: stable, well mixed, independent of shard or order.
uint64_t DeriveSeed(uint64_t experiment_seed, uint64_t trial_index);

class Rng {
 public:
  explicit Rng(uint64_t seed);
  uint64_t NextU64();
  double Uniform();                          // [0, 1)
  double Uniform(double lo, double hi);      // [lo, hi)
  int UniformInt(int lo, int hi);            // inclusive [lo, hi]
  double Normal(double mean = 0.0, double stddev = 1.0);
  bool Bernoulli(double p);
  int Poisson(double mean);
  template <typename T>
  void Shuffle(std::vector<T>& v) {
    for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[static_cast<size_t>(UniformInt(0, int(i - 1)))]);
  }

 private:
  uint64_t s_[4];
};

}  // namespace toponav::core
