// Box2D 2.4 world behind sim::MotionSim.  World units are scaled by kScale into Box2D metres so corridors
// (20 units) are ~2 m: the size range Box2D is tuned for.
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "sim/motion.h"
#include "sim/sim.h"

namespace toponav::sim {

using core::Vec2;

namespace {
constexpr double kScale = 0.1;
constexpr float kDt = 1.0f / 60.0f;

b2Vec2 ToB2(const Vec2& p) { return {float(p.x * kScale), float(p.y * kScale)}; }
Vec2 FromB2(const b2Vec2& p) { return {double(p.x) / kScale, double(p.y) / kScale}; }

void AddLoop(b2Body* body, core::Ring ring, bool solid_inside) {
  // Box2D chain edges collide on their right-hand side (outward normals for a counter-clockwise loop).
  // A loop that keeps agents inside (the boundary) runs clockwise.
  if (!solid_inside) core::Reverse(ring);
  std::vector<b2Vec2> pts;
  for (const auto& p : ring) pts.push_back(ToB2(p));
  b2ChainShape chain;
  chain.CreateLoop(pts.data(), int32(pts.size()));
  body->CreateFixture(&chain, 0.0f);
}
}  // namespace

void MotionOptions::Validate() const {
  auto fail = [](const char* key, double v, const char* why) {
    throw core::ConfigError("<options>", key, std::to_string(v), why);
  };
  if (!(step_length > 0 && step_length <= 50)) fail("motion.step_length", step_length, "must be in (0, 50]");
  if (!(open_world_step_length > 0 && open_world_step_length <= 50))
    fail("motion.open_world_step_length", open_world_step_length, "must be in (0, 50]");
  if (!(agent_radius >= 0.25 && agent_radius <= 20)) fail("motion.agent_radius", agent_radius, "must be in [0.25, 20]");
  if (!(substeps >= 1 && substeps <= 1000)) fail("motion.substeps", substeps, "must be in [1, 1000]");
}

struct MotionSim::Impl {
  MotionOptions options;
  core::World world;
  std::unique_ptr<b2World> b2world;
  std::vector<b2Body*> agents;
  std::vector<double> yaws;

  StepResult MoveToward(int agent, const Vec2& target) {
    b2Body* body = agents[size_t(agent)];
    const Vec2 from = FromB2(body->GetPosition());
    const double total_time = kDt * options.substeps;
    const Vec2 v = (target - from) * (kScale / total_time);
    for (int i = 0; i < options.substeps; ++i) {
      // Re-aim every sub-step so sliding along a wall still heads for the target.
      const Vec2 now = FromB2(body->GetPosition());
      const Vec2 left = target - now;
      const double remaining_time = kDt * (options.substeps - i);
      Vec2 vel = left * (kScale / remaining_time);
      const double max_speed = core::Norm(v) * 1.5;
      if (core::Norm(vel) > max_speed && max_speed > 0) vel = vel * (max_speed / core::Norm(vel));
      body->SetLinearVelocity({float(vel.x), float(vel.y)});
      body->SetAwake(true);
      b2world->Step(kDt, 8, 3);
    }
    body->SetLinearVelocity({0, 0});
    const Vec2 to = FromB2(body->GetPosition());
    StepResult r;
    r.distance = core::Distance(from, to);
    if (r.distance > 1e-6) yaws[size_t(agent)] = std::atan2(to.y - from.y, to.x - from.x);
    r.pose = {to.x, to.y, yaws[size_t(agent)]};
    r.blocked = r.distance < 0.5 * core::Distance(from, target);
    return r;
  }
};

double StepLength(const MotionOptions& options, const core::World& world) {
  return world.has_boundary() ? options.step_length : options.open_world_step_length;
}

MotionSim::MotionSim(const core::World& world, const MotionOptions& options) : impl_(std::make_unique<Impl>()) {
  options.Validate();
  Impl& m = *impl_;
  m.options = options;
  m.options.step_length = StepLength(options, world);
  m.world = world;
  m.b2world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
  b2BodyDef def;
  def.type = b2_staticBody;
  b2Body* statics = m.b2world->CreateBody(&def);
  if (world.has_boundary()) {
    AddLoop(statics, world.boundary, false);
  } else {  // open worlds: agents stay inside the region bounds
    const auto& b = world.bounds;
    AddLoop(statics, {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}}, false);
  }
  for (const auto& o : world.obstacles) AddLoop(statics, o, true);
  for (const auto& c : world.clutter) {
    if (c.shape == core::ClutterShape::kBox) {
      b2PolygonShape box;
      box.SetAsBox(float(c.size * kScale), float(c.size * kScale), ToB2(c.center), float(c.yaw));
      statics->CreateFixture(&box, 0.0f);
    } else {
      b2CircleShape circle;
      circle.m_p = ToB2(c.center);
      circle.m_radius = float(c.size * kScale);
      statics->CreateFixture(&circle, 0.0f);
    }
  }
}

MotionSim::~MotionSim() = default;

int MotionSim::AddAgent(const core::Pose2& pose) {
  Impl& m = *impl_;
  const Vec2 p = pose.position();
  if (!core::IsFree(m.world, p) || core::SignedDistance(m.world, p) < m.options.agent_radius)
    throw core::DataError("<agent>", "an agent of radius " + std::to_string(m.options.agent_radius) +
                                         " does not fit at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = ToB2(p);
  def.fixedRotation = true;
  def.bullet = true;
  b2Body* body = m.b2world->CreateBody(&def);
  b2CircleShape disc;
  disc.m_radius = float(m.options.agent_radius * kScale);
  b2FixtureDef fd;
  fd.shape = &disc;
  fd.density = 1.0f;
  fd.friction = 0.0f;
  fd.filter.groupIndex = -1;  // agents never collide with each other
  body->CreateFixture(&fd);
  m.agents.push_back(body);
  m.yaws.push_back(pose.yaw);
  return int(m.agents.size()) - 1;
}

int MotionSim::num_agents() const { return int(impl_->agents.size()); }

core::Pose2 MotionSim::Pose(int agent) const {
  TOPONAV_CHECK(agent >= 0 && agent < num_agents(), "no agent " << agent);
  const Vec2 p = FromB2(impl_->agents[size_t(agent)]->GetPosition());
  return {p.x, p.y, impl_->yaws[size_t(agent)]};
}

StepResult MotionSim::Step(int agent, const std::vector<Vec2>& waypoints) {
  TOPONAV_CHECK(agent >= 0 && agent < num_agents(), "no agent " << agent);
  Impl& m = *impl_;
  const Vec2 pos = Pose(agent).position();
  if (waypoints.empty()) {
    StepResult r;
    r.pose = Pose(agent);
    r.reached_end = true;
    return r;
  }
  // The point step_length further along the polyline pos -> waypoints...
  double budget = m.options.step_length;
  Vec2 cur = pos, target = waypoints.back();
  bool reaches_end = true;
  for (const auto& w : waypoints) {
    const double d = core::Distance(cur, w);
    if (budget <= 0) {
      target = cur;
      reaches_end = false;
      break;
    }
    if (d >= budget) {
      target = cur + (w - cur) * (budget / d);
      reaches_end = false;
      break;
    }
    budget -= d;
    cur = w;
  }
  StepResult r = m.MoveToward(agent, target);
  r.reached_end = reaches_end && core::Distance(r.pose.position(), waypoints.back()) < 0.05 * m.options.step_length + 1e-9;
  return r;
}

StepResult MotionSim::Nudge(int agent, const Vec2& offset) {
  TOPONAV_CHECK(agent >= 0 && agent < num_agents(), "no agent " << agent);
  return impl_->MoveToward(agent, Pose(agent).position() + offset);
}

}  // namespace toponav::sim

namespace toponav::sim {
std::string MotionLibraryInfo() {
  return "Box2D " + std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
         std::to_string(b2_version.revision);
}
}  // namespace toponav::sim
