#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <vector>

#include "core/error.h"
#include "sim/sim.h"

namespace toponav::sim {

std::string OffscreenGlInfo() {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx) throw core::InternalError("OSMesa: cannot create an OpenGL 3.3 core context");
  std::vector<unsigned char> buf(16 * 16 * 4);
  if (!OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, 16, 16)) {
    OSMesaDestroyContext(ctx);
    throw core::InternalError("OSMesa: cannot make the context current");
  }
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  std::string info = std::string(renderer ? renderer : "?") + " | " + (version ? version : "?");
  OSMesaDestroyContext(ctx);
  return info;
}

}  // namespace toponav::sim
