#pragma once
// Sampling the most likely map: MCMC over which candidate vertices are in the map (paper Sec. III-C).
#include "core/rng.h"
#include "mapping/internal/map_core.h"

namespace toponav::mapping::internal {

// 'samples' single-vertex flips of the candidates seen in the latest options.mcmc_window observations
// (random-order systematic scan: each is proposed once per pass), Metropolis acceptance; leaves the vertices'
// flags at the most likely state seen and returns how much that raised the log posterior (>= 0).  Refreshes
// star polygons of observations whose vertices drifted first.
double SampleMostLikelyMap(MapCore* m, core::Rng& rng, int samples, MapperStats* stats);

}  // namespace toponav::mapping::internal
