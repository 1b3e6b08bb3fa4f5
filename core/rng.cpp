#include "core/rng.h"

#include <cmath>

#include "core/error.h"

namespace toponav::core {
namespace {
uint64_t SplitMix64(uint64_t& x) {
  uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
uint64_t Rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
}  // namespace

uint64_t DeriveSeed(uint64_t experiment_seed, uint64_t trial_index) {
  uint64_t x = experiment_seed ^ Rotl(trial_index * 0xd1342543de82ef95ULL + 0x2545f4914f6cdd1dULL, 17);
  SplitMix64(x);
  return SplitMix64(x);
}

Rng::Rng(uint64_t seed) {
  uint64_t x = seed;
  for (auto& s : s_) s = SplitMix64(x);
}

uint64_t Rng::NextU64() {  // xoshiro256** (Blackman & Vigna)
  const uint64_t result = Rotl(s_[1] * 5, 7) * 9;
  const uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = Rotl(s_[3], 45);
  return result;
}

double Rng::Uniform() { return double(NextU64() >> 11) * 0x1.0p-53; }

double Rng::Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }

int Rng::UniformInt(int lo, int hi) {
  TOPONAV_CHECK(lo <= hi, "UniformInt(" << lo << ", " << hi << ")");
  const uint64_t span = uint64_t(int64_t(hi) - int64_t(lo)) + 1;
  const uint64_t limit = UINT64_MAX - UINT64_MAX % span;  // rejection: no modulo bias
  uint64_t r;
  do r = NextU64();
  while (r >= limit);
  return int(int64_t(lo) + int64_t(r % span));
}

double Rng::Normal(double mean, double stddev) {
  // Marsaglia polar method; one value per call keeps the stream position simple to reason about.
  double u, v, s;
  do {
    u = Uniform(-1.0, 1.0);
    v = Uniform(-1.0, 1.0);
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  return mean + stddev * u * std::sqrt(-2.0 * std::log(s) / s);
}

bool Rng::Bernoulli(double p) { return Uniform() < p; }

int Rng::Poisson(double mean) {
  TOPONAV_CHECK(mean >= 0.0 && mean < 500.0, "Poisson mean " << mean);
  const double limit = std::exp(-mean);  // Knuth's method: fine for the small means we use
  int k = 0;
  double p = Uniform();
  while (p > limit) {
    ++k;
    p *= Uniform();
  }
  return k;
}

}  // namespace toponav::core
