// sim::Renderer on OSMesa (Mesa's llvmpipe software rasterizer).  A panorama is four 90-degree cube-side views
// rendered side by side into one framebuffer, then resampled (bilinear for colour, nearest for depth and
// ids) into the equirectangular image with tables computed once per renderer (deps.md §3).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "core/detection.h"
#include "core/error.h"
#include "sim/internal/scene.h"
#include "sim/render.h"

namespace toponav::sim {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 pos;
layout(location = 1) in vec3 nrm;
layout(location = 2) in vec3 col;
layout(location = 3) in vec2 uv;
layout(location = 4) in vec2 mat;
layout(location = 5) in int id;
uniform mat4 view_proj;
out vec3 v_pos; out vec3 v_nrm; out vec3 v_col; out vec2 v_uv; out vec2 v_mat; flat out int v_id;
void main() {
  v_pos = pos; v_nrm = nrm; v_col = col; v_uv = uv; v_mat = mat; v_id = id;
  gl_Position = view_proj * vec4(pos, 1.0);
})";

// Patterns follow internal::Pattern: 0 plain, 1 panels, 2 bricks, 3 stripes, 4 windows, 5 tiles, 6 grass,
// 7 ceiling, 8 bark, 9 leaves.
const char* kFragmentShader = R"(#version 330 core
in vec3 v_pos; in vec3 v_nrm; in vec3 v_col; in vec2 v_uv; in vec2 v_mat; flat in int v_id;
uniform vec3 cam;
layout(location = 0) out vec4 o_col;
layout(location = 1) out float o_dist;
layout(location = 2) out int o_id;
float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
void main() {
  int pat = int(v_mat.x + 0.5);
  vec3 c = v_col;
  vec2 uv = v_uv;
  if (pat == 1) {
    if (fract(uv.x / 6.0) < 0.04) c *= 0.65;
    if (abs(uv.y - 3.0) < 0.35) c *= 0.8;
  } else if (pat == 2) {
    float row = floor(uv.y / 1.5);
    float x = uv.x / 3.0 + 0.5 * mod(row, 2.0);
    if (fract(uv.y / 1.5) < 0.1 || fract(x) < 0.05) c = mix(c, vec3(0.92), 0.55);
    else c *= 0.85 + 0.25 * hash(vec2(floor(x), row));
  } else if (pat == 3) {
    if (uv.y > 7.0 && uv.y < 9.5) c *= 0.55;
    if (uv.y < 1.2) c *= 0.45;
  } else if (pat == 4) {
    float fx = fract(uv.x / 6.0), fy = fract(uv.y / 8.0);
    if (fx > 0.2 && fx < 0.8 && fy > 0.3 && fy < 0.8 && uv.y > 4.0)
      c = vec3(0.22, 0.30, 0.40) + 0.18 * hash(floor(uv / vec2(6.0, 8.0)));
  } else if (pat == 5) {
    vec2 t = floor(uv / 5.0);
    if (mod(t.x + t.y, 2.0) > 0.5) c *= 0.86;
    vec2 f = fract(uv / 5.0);
    if (f.x < 0.03 || f.y < 0.03) c *= 0.8;
  } else if (pat == 6) {
    c *= 0.85 + 0.3 * hash(floor(uv));
  } else if (pat == 7) {
    vec2 f = fract(uv / 2.5);
    if (f.x < 0.05 || f.y < 0.05) c *= 0.8;
  } else if (pat == 8) {
    c *= 0.8 + 0.3 * hash(vec2(floor(uv.x * 4.0), floor(uv.y)));
  } else if (pat == 9) {
    c *= 0.75 + 0.4 * hash(floor(uv * 3.0));
  }
  vec3 n = normalize(v_nrm);
  float light = 0.42 + 0.45 * max(dot(n, normalize(vec3(0.62, 0.36, 0.70))), 0.0)
                     + 0.22 * max(dot(n, normalize(vec3(-0.45, -0.80, 0.40))), 0.0);
  if (v_mat.y > 0.0) {  // corner shading: walls darken towards their vertical ends
    float e = min(v_uv.x, v_mat.y - v_uv.x);
    light *= 1.0 - 0.3 * exp(-e / 1.5);
  }
  float dist = length(v_pos - cam);
  c *= light * mix(1.0, 0.7, clamp(dist / 250.0, 0.0, 1.0));
  o_col = vec4(clamp(c, 0.0, 1.0), 1.0);
  o_dist = dist;
  o_id = v_id;
})";

std::atomic<uint64_t> g_next_scene_serial{1};

[[noreturn]] void GlFail(const std::string& what) { throw core::InternalError("OpenGL (OSMesa): " + what); }

GLuint Compile(GLenum type, const char* src) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    GlFail(std::string("shader compilation failed: ") + log);
  }
  return s;
}

// One OpenGL context per thread, created on first use and kept for the thread's lifetime.
class ThreadGl {
 public:
  ~ThreadGl() { Destroy(); }

  static ThreadGl& Get() {
    thread_local ThreadGl gl;
    if (!gl.ctx_) {
      try {
        gl.Init();
      } catch (...) {
        gl.Destroy();  // a failed start is retried on the next call, not cached half-made
        throw;
      }
    }
    gl.MakeCurrent();
    return gl;
  }

  GLuint program() const { return program_; }

  // Makes sure a framebuffer of w x h pixels with colour, distance and id attachments is bound.
  void BindFramebuffer(int w, int h) {
    if (w != fb_w_ || h != fb_h_) {
      FreeFramebuffer();
      glGenFramebuffers(1, &fbo_);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
      glGenRenderbuffers(4, rb_);
      const GLenum formats[4] = {GL_RGBA8, GL_R32F, GL_R32I, GL_DEPTH_COMPONENT24};
      const GLenum points[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_DEPTH_ATTACHMENT};
      for (int i = 0; i < 4; ++i) {
        glBindRenderbuffer(GL_RENDERBUFFER, rb_[i]);
        glRenderbufferStorage(GL_RENDERBUFFER, formats[i], w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, points[i], GL_RENDERBUFFER, rb_[i]);
      }
      const GLenum draw[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
      glDrawBuffers(3, draw);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        GlFail("framebuffer of " + std::to_string(w) + " x " + std::to_string(h) + " is incomplete");
      fb_w_ = w;
      fb_h_ = h;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  }

  // The vertex array of a scene, uploaded on first use (a small per-thread cache).
  GLuint SceneVao(uint64_t serial, const internal::Scene& scene) {
    for (auto& s : scenes_)
      if (s.serial == serial) {
        s.last_use = ++clock_;
        return s.vao;
      }
    if (scenes_.size() >= 8) {
      auto oldest = std::min_element(scenes_.begin(), scenes_.end(),
                                     [](const Uploaded& a, const Uploaded& b) { return a.last_use < b.last_use; });
      Free(*oldest);
      scenes_.erase(oldest);
    }
    Uploaded u;
    u.serial = serial;
    u.last_use = ++clock_;
    glGenVertexArrays(1, &u.vao);
    glBindVertexArray(u.vao);
    glGenBuffers(1, &u.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, u.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(scene.vertices.size() * sizeof(internal::SceneVertex)),
                 scene.vertices.data(), GL_STATIC_DRAW);
    const GLsizei stride = sizeof(internal::SceneVertex);
    auto attrib = [&](GLuint loc, int n, size_t offset) {
      glEnableVertexAttribArray(loc);
      glVertexAttribPointer(loc, n, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset));
    };
    attrib(0, 3, offsetof(internal::SceneVertex, pos));
    attrib(1, 3, offsetof(internal::SceneVertex, normal));
    attrib(2, 3, offsetof(internal::SceneVertex, color));
    attrib(3, 2, offsetof(internal::SceneVertex, uv));
    attrib(4, 2, offsetof(internal::SceneVertex, material));
    glEnableVertexAttribArray(5);
    glVertexAttribIPointer(5, 1, GL_INT, stride, reinterpret_cast<void*>(offsetof(internal::SceneVertex, id)));
    scenes_.push_back(u);
    return u.vao;
  }

 private:
  struct Uploaded {
    uint64_t serial = 0, last_use = 0;
    GLuint vao = 0, vbo = 0;
  };

  void Init() {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx_) GlFail("cannot create an OpenGL 3.3 core context (is libosmesa6 installed?)");
    MakeCurrent();
    const GLuint vs = Compile(GL_VERTEX_SHADER, kVertexShader), fs = Compile(GL_FRAGMENT_SHADER, kFragmentShader);
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) GlFail("shader program failed to link");
  }

  void Destroy() noexcept {
    if (!ctx_) return;
    if (OSMesaGetCurrentContext() == ctx_ || OSMesaMakeCurrent(ctx_, dummy_, GL_UNSIGNED_BYTE, 1, 1)) {
      for (auto& s : scenes_) Free(s);
      FreeFramebuffer();
      if (program_) glDeleteProgram(program_);
    }
    scenes_.clear();
    program_ = 0;
    OSMesaDestroyContext(ctx_);
    ctx_ = nullptr;
  }

  void MakeCurrent() {
    if (OSMesaGetCurrentContext() == ctx_) return;
    if (!OSMesaMakeCurrent(ctx_, dummy_, GL_UNSIGNED_BYTE, 1, 1)) GlFail("cannot make the context current");
  }

  void Free(Uploaded& s) {
    glDeleteBuffers(1, &s.vbo);
    glDeleteVertexArrays(1, &s.vao);
  }

  void FreeFramebuffer() {
    if (!fbo_) return;
    glDeleteRenderbuffers(4, rb_);
    glDeleteFramebuffers(1, &fbo_);
    fbo_ = 0;
    fb_w_ = fb_h_ = 0;
  }

  OSMesaContext ctx_ = nullptr;
  unsigned char dummy_[16] = {};
  GLuint program_ = 0, fbo_ = 0, rb_[4] = {0, 0, 0, 0};
  int fb_w_ = 0, fb_h_ = 0;
  std::vector<Uploaded> scenes_;
  uint64_t clock_ = 0;
};

// Row-major 4x4 product.
void MatMul(const float a[16], const float b[16], float out[16]) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      float s = 0;
      for (int k = 0; k < 4; ++k) s += a[r * 4 + k] * b[k * 4 + c];
      out[r * 4 + c] = s;
    }
}

}  // namespace

const core::OptionFields<RenderOptions>& RenderOptions::Fields() {
  using O = RenderOptions;
  static const core::OptionFields<O> fields{
      {"width", &O::width, 8, 4096},
      {"height", &O::height, 2, 2048},
      {"vertical_fov_deg", &O::vertical_fov_deg, 10.0, 150.0},
      {"camera_height", &O::camera_height, 0.01, 1000.0},
      {"wall_height", &O::wall_height, 0.01, 1000.0},
      {"supersample", &O::supersample, 1, 4},
      {"plain_wall_fraction", &O::plain_wall_fraction, 0.0, 1.0},
  };
  return fields;
}

void RenderOptions::Validate() const {
  core::CheckRanges(*this, Fields(), "render.");
  auto fail = [](const char* key, double v, const char* why) {
    throw core::ConfigError("<options>", key, std::to_string(v), why);
  };
  if (width % 4 != 0) fail("render.width", width, "must be a multiple of 4");
  if (!(camera_height < wall_height)) fail("render.camera_height", camera_height, "must be < wall_height");
  if (width * supersample > 8192) fail("render.supersample", supersample, "must keep width * supersample <= 8192");
}

struct Renderer::Impl {
  RenderOptions options;
  internal::Scene scene;
  uint64_t serial = 0;
  int face_w = 0, face_h = 0;
  float tan_half_v = 1.0f;  // tangent of the cube face's vertical half field of view
  // Per panorama pixel: byte offsets of four RGBA source pixels with 8-bit fixed-point bilinear weights
  // (summing to 256), and the nearest source pixel.
  std::vector<uint32_t> taps;      // 4 per pixel
  std::vector<uint16_t> weights;   // 4 per pixel
  std::vector<uint32_t> nearest;   // 1 per pixel

  // Selects the atlas attachments asked for by 'outputs' (a RenderOutput mask) and clears them.
  void ClearTargets(int outputs) const;
  // Draws the scene into the atlas's four 90-degree cube faces, looking from 'pose'.
  void DrawFaces(const core::Pose2& pose, GLuint program) const;
  // The atlas's colour, resampled bilinearly into the panorama.
  void ReadRgb(Panorama* pano) const;
  // Depth and ids: nearest source pixel (interpolating them would invent values between surfaces).
  template <typename T>
  void ReadNearest(std::vector<T>* out, GLenum attachment, GLenum format, GLenum type) const;
};

Renderer::Renderer(const core::World& world, const RenderOptions& options) : impl_(std::make_unique<Impl>()) {
  options.Validate();
  Impl& m = *impl_;
  m.options = options;
  m.scene = internal::BuildScene(world, options);
  m.serial = g_next_scene_serial++;
  const double half_el = options.vertical_fov_deg * core::kPi / 360.0;
  m.tan_half_v = float(std::tan(half_el) / std::cos(core::kPi / 4));  // covers +-half_el at the face corners
  m.face_w = options.width / 4 * options.supersample;
  m.face_h = int(std::ceil(m.face_w * m.tan_half_v)) + 2;
  const int W = options.width, H = options.height, atlas_w = 4 * m.face_w;
  m.taps.resize(size_t(W) * H * 4);
  m.weights.resize(size_t(W) * H * 4);
  m.nearest.resize(size_t(W) * H);
  for (int row = 0; row < H; ++row)
    for (int col = 0; col < W; ++col) {
      const double bearing = core::ColumnToBearing(col, W);
      const double el = half_el - (row + 0.5) * 2.0 * half_el / H;
      int face = int(std::floor((bearing + core::kPi / 4) / (core::kPi / 2)));
      face = ((face % 4) + 4) % 4;
      const double rel = core::WrapAngle(bearing - face * core::kPi / 2);
      // Camera frame of the face: x right (clockwise of forward), y up.  Counter-clockwise bearings are left.
      const double x_ndc = -std::tan(rel);
      const double y_ndc = std::tan(el) / std::cos(rel) / m.tan_half_v;
      const double px = face * m.face_w + (x_ndc + 1) * 0.5 * m.face_w - 0.5;
      const double py = (y_ndc + 1) * 0.5 * m.face_h - 0.5;  // rows counted from the bottom (glReadPixels order)
      const int lo_x = face * m.face_w, hi_x = lo_x + m.face_w - 1;
      const int x0 = std::clamp(int(std::floor(px)), lo_x, hi_x), x1 = std::min(x0 + 1, hi_x);
      const int y0 = std::clamp(int(std::floor(py)), 0, m.face_h - 1), y1 = std::min(y0 + 1, m.face_h - 1);
      const float fx = float(std::clamp(px - x0, 0.0, 1.0)), fy = float(std::clamp(py - y0, 0.0, 1.0));
      const size_t k = (size_t(row) * W + col);
      const uint32_t t[4] = {uint32_t(y0 * atlas_w + x0), uint32_t(y0 * atlas_w + x1), uint32_t(y1 * atlas_w + x0),
                             uint32_t(y1 * atlas_w + x1)};
      const float w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
      int iw[4], sum = 0, largest = 0;
      for (int i = 0; i < 4; ++i) {
        iw[i] = int(std::lround(w[i] * 256));
        sum += iw[i];
        if (iw[i] > iw[largest]) largest = i;
      }
      iw[largest] += 256 - sum;  // exact sum (flat regions stay exact); the largest weight absorbs the rounding
      for (int i = 0; i < 4; ++i) {
        m.taps[4 * k + size_t(i)] = 4 * t[i];
        m.weights[4 * k + size_t(i)] = uint16_t(iw[i]);
      }
      const int nx = std::clamp(int(std::lround(px)), lo_x, hi_x),
                ny = std::clamp(int(std::lround(py)), 0, m.face_h - 1);
      m.nearest[k] = uint32_t(ny * atlas_w + nx);
    }
}

Renderer::~Renderer() = default;

const RenderOptions& Renderer::options() const { return impl_->options; }
int Renderer::num_triangles() const { return int(impl_->scene.vertices.size() / 3); }

void Renderer::Impl::ClearTargets(int outputs) const {
  const float sky[4] = {scene.sky[0], scene.sky[1], scene.sky[2], 1.f};
  const float far_dist[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  const GLint no_id[4] = {kNoObstacle, 0, 0, 0};
  // Write only the attachments that were asked for: the fragment cost is most of a panorama's time.
  const GLenum draw[3] = {GLenum((outputs & kRenderRgb) ? GL_COLOR_ATTACHMENT0 : GL_NONE),
                          GLenum((outputs & kRenderDepth) ? GL_COLOR_ATTACHMENT1 : GL_NONE),
                          GLenum((outputs & kRenderIds) ? GL_COLOR_ATTACHMENT2 : GL_NONE)};
  glDrawBuffers(3, draw);
  if (outputs & kRenderRgb) glClearBufferfv(GL_COLOR, 0, sky);
  if (outputs & kRenderDepth) glClearBufferfv(GL_COLOR, 1, far_dist);
  if (outputs & kRenderIds) glClearBufferiv(GL_COLOR, 2, no_id);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void Renderer::Impl::DrawFaces(const core::Pose2& pose, GLuint program) const {
  const float ex = float(pose.x), ey = float(pose.y), ez = float(options.camera_height);
  glUniform3f(glGetUniformLocation(program, "cam"), ex, ey, ez);
  const GLint vp_loc = glGetUniformLocation(program, "view_proj");
  const float n = 0.2f, f = 5000.f;  // agents keep their radius (>= 0.25) from walls: nothing is nearer
  const float proj[16] = {1, 0, 0, 0,
                          0, 1 / tan_half_v, 0, 0,
                          0, 0, -(f + n) / (f - n), -2 * f * n / (f - n),
                          0, 0, -1, 0};
  std::vector<GLint> firsts;
  std::vector<GLsizei> counts;
  for (int face = 0; face < 4; ++face) {
    const double yaw = pose.yaw + face * core::kPi / 2;
    const float fx = float(std::cos(yaw)), fy = float(std::sin(yaw));
    // Rows: right = (fy, -fx, 0), up = (0, 0, 1), back = -forward.
    const float view[16] = {fy,  -fx, 0, -(fy * ex - fx * ey),
                            0,   0,   1, -ez,
                            -fx, -fy, 0, fx * ex + fy * ey,
                            0,   0,   0, 1};
    float vp[16];
    MatMul(proj, view, vp);
    glUniformMatrix4fv(vp_loc, 1, GL_TRUE, vp);
    glViewport(face * face_w, 0, face_w, face_h);
    // Draw only objects whose ground-plane bounding circle reaches this face's 90-degree wedge.
    firsts.clear();
    counts.clear();
    for (const auto& o : scene.objects) {
      bool draw = o.radius < 0;
      if (!draw) {
        const double dx = o.cx - pose.x, dy = o.cy - pose.y, d = std::hypot(dx, dy);
        draw = d <= o.radius ||
               std::abs(core::WrapAngle(std::atan2(dy, dx) - yaw)) <= core::kPi / 4 + std::asin(o.radius / d) + 1e-3;
      }
      if (!draw) continue;
      if (!counts.empty() && GLint(o.first) == firsts.back() + counts.back()) {
        counts.back() += GLsizei(o.count);  // merge consecutive runs
      } else {
        firsts.push_back(GLint(o.first));
        counts.push_back(GLsizei(o.count));
      }
    }
    glMultiDrawArrays(GL_TRIANGLES, firsts.data(), counts.data(), GLsizei(firsts.size()));
  }
}

void Renderer::Impl::ReadRgb(Panorama* pano) const {
  const int atlas_w = 4 * face_w;
  const size_t pixels = size_t(pano->width) * pano->height;
  std::vector<uint8_t> atlas(size_t(atlas_w) * face_h * 4);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, atlas_w, face_h, GL_RGBA, GL_UNSIGNED_BYTE, atlas.data());
  pano->rgb.resize(pixels * 3);
  const uint8_t* src = atlas.data();
  for (size_t k = 0; k < pixels; ++k) {
    const uint32_t* t = &taps[4 * k];
    const uint16_t* w = &weights[4 * k];
    for (size_t c = 0; c < 3; ++c) {
      const unsigned v = w[0] * src[t[0] + c] + w[1] * src[t[1] + c] + w[2] * src[t[2] + c] + w[3] * src[t[3] + c];
      pano->rgb[3 * k + c] = uint8_t((v + 128) >> 8);
    }
  }
}

template <typename T>
void Renderer::Impl::ReadNearest(std::vector<T>* out, GLenum attachment, GLenum format, GLenum type) const {
  const int atlas_w = 4 * face_w;
  std::vector<T> atlas(size_t(atlas_w) * face_h);
  glReadBuffer(attachment);
  glReadPixels(0, 0, atlas_w, face_h, format, type, atlas.data());
  out->resize(size_t(options.width) * options.height);
  for (size_t k = 0; k < out->size(); ++k) (*out)[k] = atlas[nearest[k]];
}

Panorama Renderer::Render(const core::Pose2& pose, int outputs) const {
  const Impl& m = *impl_;
  ThreadGl& gl = ThreadGl::Get();
  gl.BindFramebuffer(4 * m.face_w, m.face_h);
  const GLuint vao = gl.SceneVao(m.serial, m.scene);
  glUseProgram(gl.program());
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  m.ClearTargets(outputs);
  glBindVertexArray(vao);
  m.DrawFaces(pose, gl.program());
  glFinish();
  Panorama pano;
  pano.width = m.options.width;
  pano.height = m.options.height;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (outputs & kRenderRgb) m.ReadRgb(&pano);
  if (outputs & kRenderDepth) m.ReadNearest(&pano.depth, GL_COLOR_ATTACHMENT1, GL_RED, GL_FLOAT);
  if (outputs & kRenderIds) m.ReadNearest(&pano.ids, GL_COLOR_ATTACHMENT2, GL_RED_INTEGER, GL_INT);
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR) GlFail("error " + std::to_string(err) + " while rendering");
  return pano;
}

}  // namespace toponav::sim
