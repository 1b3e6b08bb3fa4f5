// Box2D 2.4 world behind sim::MotionSim.  World units are scaled by kScale into Box2D metres so corridors
// (20 units) are ~2 m: the size range Box2D is tuned for.
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

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

const core::OptionFields<MotionOptions>& MotionOptions::Fields() {
  using O = MotionOptions;
  static const core::OptionFields<O> fields{
      {"step_length", &O::step_length, 0.01, 50.0},
      {"agent_radius", &O::agent_radius, 0.25, 20.0},
      {"substeps", &O::substeps, 1, 1000},
      {"avoid_margin", &O::avoid_margin, 0.0, 10.0},
      {"avoid_window", &O::avoid_window, 1.0, 100.0},
      {"avoid_cell", &O::avoid_cell, 0.05, 5.0},
  };
  return fields;
}

void MotionOptions::Validate() const {
  core::CheckRanges(*this, Fields(), "motion.");
  if (avoid_window / avoid_cell > 400)
    throw core::ConfigError("<options>", "motion.avoid_cell", std::to_string(avoid_cell),
                            "gives more than 400 cells across avoid_window");
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

  // Smallest clearance (signed distance to walls and clutter) at points along from -> to, 'from' excluded.
  double Clearance(const Vec2& from, const Vec2& to) const {
    const double len = core::Distance(from, to);
    const int n = std::max(2, int(std::ceil(len / 0.25)));
    double d = std::numeric_limits<double>::infinity();
    for (int i = 1; i <= n; ++i) d = std::min(d, core::SignedDistance(world, from + (to - from) * (double(i) / n)));
    return d;
  }

  // Where to head next along 'path' (pos, then the waypoints) without brushing an obstacle: 'target' (the
  // point one step along the path) if the straight line there keeps the clearance; else the point one step
  // along the shortest route on a local grid to the path point that best trades detour for progress.  An agent already
  // closer than the clearance may move along or away, never closer.
  Vec2 AvoidingTarget(const std::vector<Vec2>& path, const Vec2& target, double step, bool* turned) const {
    *turned = false;
    const Vec2 pos = path.front();
    if (options.avoid_margin <= 0 || core::Distance(pos, target) < 1e-9) return target;
    const double need = std::min(options.agent_radius + options.avoid_margin, core::SignedDistance(world, pos) - 0.02);
    if (Clearance(pos, target) >= need) return target;
    // Local grid centred on the agent; Dijkstra over free cells (8-neighbour moves).
    const double h = options.avoid_cell;
    const int half = int(std::ceil(options.avoid_window / h)), n = 2 * half + 1;
    auto cell_of = [&](const Vec2& p, int* i, int* j) {
      *i = int(std::lround((p.x - pos.x) / h)) + half;
      *j = int(std::lround((p.y - pos.y) / h)) + half;
      return *i >= 0 && *j >= 0 && *i < n && *j < n;
    };
    auto centre = [&](int i, int j) { return Vec2{pos.x + (i - half) * h, pos.y + (j - half) * h}; };
    std::vector<signed char> free(size_t(n) * n, -1);  // -1 not yet tested
    auto is_free = [&](int i, int j) {
      signed char& f = free[size_t(j) * n + i];
      if (f < 0) {
        const Vec2 c = centre(i, j);
        // Open worlds: the region's edge is a wall for motion too (SignedDistance does not know it).
        const bool inside = world.has_boundary() || core::BoxHits(world.bounds, c, -options.agent_radius);
        f = inside && core::SignedDistance(world, c) >= need ? 1 : 0;
      }
      return f == 1;
    };
    std::vector<double> dist(size_t(n) * n, std::numeric_limits<double>::infinity());
    std::vector<int> parent(size_t(n) * n, -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    const int s0 = half * n + half;
    dist[size_t(s0)] = 0;
    open.push({0.0, s0});
    while (!open.empty()) {
      const auto [d, c] = open.top();
      open.pop();
      if (d > dist[size_t(c)]) continue;
      const int ci = c % n, cj = c / n;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int i = ci + di, j = cj + dj;
          if ((di == 0 && dj == 0) || i < 0 || j < 0 || i >= n || j >= n || !is_free(i, j)) continue;
          // Diagonal moves must not squeeze between two blocked cells.
          if (di != 0 && dj != 0 && (!is_free(ci + di, cj) || !is_free(ci, cj + dj))) continue;
          const double nd = d + h * std::sqrt(double(di * di + dj * dj));
          const int k = j * n + i;
          if (nd < dist[size_t(k)]) {
            dist[size_t(k)] = nd;
            parent[size_t(k)] = c;
            open.push({nd, k});
          }
        }
    }
    // The path point (sampled every half cell, inside the grid) minimizing grid route - 2 x arc length (a
    // detour is worth the progress it buys; the route can never be shorter than the path itself).
    int best = -1;
    double best_cost = std::numeric_limits<double>::infinity(), s = 0;
    for (size_t w = 1; w < path.size(); ++w) {
      const double len = core::Distance(path[w - 1], path[w]);
      const int m = std::max(1, int(std::ceil(len / (0.5 * h))));
      for (int q = 1; q <= m; ++q) {
        const Vec2 p = path[w - 1] + (path[w] - path[w - 1]) * (double(q) / m);
        int i, j;
        if (!cell_of(p, &i, &j)) continue;
        const double c = dist[size_t(j) * n + i] - 2.0 * (s + len * q / m);
        if (c < best_cost) {
          best_cost = c;
          best = j * n + i;
        }
      }
      s += len;
    }
    if (best < 0 || best == s0) return target;  // boxed in: push on and let the physics slide
    std::vector<int> route{best};
    while (route.back() != s0) route.push_back(parent[size_t(route.back())]);
    std::reverse(route.begin(), route.end());
    // One step along the route (straight from the agent to a route cell it can reach with the clearance).
    Vec2 aim = centre(route[1] % n, route[1] / n);
    for (size_t k = 1; k < route.size(); ++k) {
      const Vec2 p = centre(route[k] % n, route[k] / n);
      if (dist[size_t(route[k])] > step + 1e-9 || Clearance(pos, p) < need) break;
      aim = p;
    }
    // A coarse grid (avoid_cell near the step length) must not make a step longer than asked.
    const double reach = core::Distance(pos, aim);
    if (reach > step) aim = pos + (aim - pos) * (step / reach);
    *turned = true;
    return aim;
  }
};

MotionSim::MotionSim(const core::World& world, const MotionOptions& options) : impl_(std::make_unique<Impl>()) {
  options.Validate();
  Impl& m = *impl_;
  m.options = options;
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
  bool turned = false;
  std::vector<Vec2> path{pos};
  path.insert(path.end(), waypoints.begin(), waypoints.end());
  const Vec2 aim = m.AvoidingTarget(path, target, m.options.step_length, &turned);
  StepResult r = m.MoveToward(agent, aim);
  r.avoided = turned;
  r.reached_end =
      reaches_end && core::Distance(r.pose.position(), waypoints.back()) < 0.05 * m.options.step_length + 1e-9;
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
