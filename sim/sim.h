#pragma once
// Front door of the simulator layer: procedural worlds, world files, ray-cast ground truth, agent motion.
#include <string>

#include "sim/motion.h"
#include "sim/noisy_sensor.h"
#include "sim/paths.h"
#include "sim/raycast.h"
#include "sim/render.h"
#include "sim/world_io.h"
#include "sim/worlds.h"

namespace toponav::sim {

// Creates a small OSMesa (off-screen OpenGL) context and reports "renderer | version".  Throws
// core::InternalError if no context can be made.
std::string OffscreenGlInfo();

// Embree and Box2D versions, for `toponav info`.
std::string RayCasterLibraryInfo();
std::string MotionLibraryInfo();

}  // namespace toponav::sim
