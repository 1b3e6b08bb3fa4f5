#pragma once
// The map's geometry as JSON, the "map" object of `toponav map`'s map.json: what another tool reads to use a
// map built from simulated or recorded panoramas (README: "map.json").  World units; points are [x, y]
// pairs.
#include <nlohmann/json.hpp>

#include "mapping/mapping.h"

namespace toponav::experiments {

// {"vertices": [{id, x, y, cov: [xx, xy, yy], detections}], "rejected": [the same], "walls": [{a, b,
//  probability, from, to}] (a and b are vertex ids), "known_space": [{outer, holes}] (rings of points),
//  "frontiers": [{id, points, length}]}.
nlohmann::json MapGeometryJson(const mapping::MapView& view);

}  // namespace toponav::experiments
