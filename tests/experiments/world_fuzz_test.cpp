// Fuzzing the world loader and the agent loop: many random and adversarial world files (seeded, so every
// failure reproduces); every file the loader accepts must survive observation and a few search steps.  A
// library assertion (Box2D, Embree, CGAL) would kill this process, so passing means no signal, ever.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/rng.h"
#include "experiments/map_drive.h"
#include "experiments/trial.h"
#include "sim/raycast.h"
#include "sim/world_io.h"

namespace toponav::experiments {
namespace {

// A star-shaped polygon of n points around (cx, cy) with radii in [r0, r1], as JSON.
std::string Polygon(core::Rng& rng, double cx, double cy, double r0, double r1, int n) {
  std::ostringstream os;
  os.precision(17);
  os << "[";
  for (int i = 0; i < n; ++i) {
    const double a = 2 * core::kPi * (i + rng.Uniform(0.0, 0.8)) / n, r = rng.Uniform(r0, r1);
    os << (i ? "," : "") << "[" << cx + r * std::cos(a) << "," << cy + r * std::sin(a) << "]";
  }
  os << "]";
  return os.str();
}

std::string Number(double v) {
  if (std::isnan(v)) return "NaN";
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

// One world file: a room with obstacles and, for half of the seeds, one adversarial change: huge or
// non-finite coordinates, points closer than the minimum spacing, a sliver, a start or goal outside the
// world, an unknown nested key, huge bounds, clutter outside free space or with a bad size.
std::string FuzzWorld(uint64_t seed) {
  core::Rng rng(seed);
  const int mode = rng.Uniform() < 0.5 ? -1 : rng.UniformInt(0, 11);  // -1: no adversarial change
  const double big = mode == 1 ? 1e20 : mode == 2 ? 1e308 : mode == 3 ? 5e4 : 100.0;
  const double tiny = mode == 4 ? 0.01 : mode == 5 ? 1e-9 : 0.0;
  std::ostringstream os;
  os.precision(17);
  os << "{\"boundary\": [[0,0],[" << big << ",0],[" << big << "," << big << "],"
     << (tiny > 0 ? "[" + Number(tiny) + "," + Number(big) + "]," : "") << "[0," << big << "]],";
  os << "\"obstacles\": [";
  const int n = int(rng.UniformInt(0, 4));
  for (int i = 0; i < n; ++i) {
    const double cx = rng.Uniform(20, 80), cy = rng.Uniform(20, 80);
    if (mode == 6 && i == 0)  // a sliver
      os << "[[" << cx << "," << cy << "],[" << cx + 30 << "," << cy + 1e-4 << "],[" << cx + 60 << "," << cy << "]]";
    else os << Polygon(rng, cx, cy, mode == 7 ? 0.001 : 2, mode == 7 ? 0.04 : 8, int(rng.UniformInt(3, 9)));
    os << (i + 1 < n ? "," : "");
  }
  os << "],";
  const double sx = mode == 8 ? -50 : rng.Uniform(1, 99), sy = rng.Uniform(1, 99);
  os << "\"start\": {\"x\": " << sx << ", \"y\": " << sy << (mode == 9 ? ", \"z\": 1" : "") << "},";
  os << "\"goal\": [" << (mode == 10 ? 1e7 : rng.Uniform(1, 99)) << "," << rng.Uniform(1, 99) << "]";
  if (mode == 11) os << ", \"bounds\": {\"min\": [-1e9,-1e9], \"max\": [1e9,1e9]}";
  if (mode == 0)
    os << ", \"clutter\": [{\"shape\": \"box\", \"center\": [" << rng.Uniform(-20, 120)
       << ",50], \"size\": " << rng.Uniform(-1, 3) << "}]";
  os << "}";
  return os.str();
}

TEST(WorldFuzz, EveryWorldTheLoaderAcceptsSurvivesObservationAMapDriveAndSearchSteps) {
  Config config;
  TrialOptions t;
  t.max_steps = 3;
  int accepted = 0, rejected = 0;
  for (uint64_t seed = 0; seed < 240; ++seed) {
    const std::string text = FuzzWorld(seed);
    core::World w;
    try {
      w = sim::WorldFromJson(text, "fuzz-" + std::to_string(seed));
    } catch (const core::DataError&) {
      ++rejected;
      continue;
    }
    ++accepted;
    SCOPED_TRACE(text);
    const sim::RayCaster caster(w);
    EXPECT_GE(caster.VisibilityPolygon(w.start.position()).size(), 3u);
    try {
      MapDriveOptions drive;
      drive.max_steps = 3;
      drive.seed = seed;
      RunMapDrive(w, config, drive);
    } catch (const core::DataError& e) {
      const std::string what = e.what();  // refusals a user can act on
      EXPECT_TRUE(what.find("does not fit") != std::string::npos || what.find("no drivable path") != std::string::npos)
          << what;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "an accepted world made the map drive fail: " << e.what();
    }
    for (int agents : {1, 2}) {
      t.num_agents = agents;
      try {
        RunSearchTrial(w, config, t, seed);
      } catch (const core::DataError& e) {
        // A clear refusal is fine (e.g. the agent's radius does not fit at the start: the world file cannot
        // know the config's agent radius).
        EXPECT_NE(std::string(e.what()).find("does not fit"), std::string::npos) << e.what();
      } catch (const std::exception& e) {
        ADD_FAILURE() << "an accepted world made the trial fail: " << e.what();
      }
    }
  }
  EXPECT_GT(accepted, 40) << "the generator must also make valid worlds";
  EXPECT_GT(rejected, 40) << "and adversarial ones";
}

TEST(WorldFuzz, TheLoaderNamesWhatIsWrong) {
  auto error_of = [](const std::string& text) {
    try {
      sim::WorldFromJson(text, "w.json");
    } catch (const core::DataError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string room = R"("boundary": [[0,0],[100,0],[100,100],[0,100]])";
  EXPECT_NE(
      error_of("{" + room +
               R"(, "obstacles": [[[10,10],[20,10],[20.01,10],[20,20]]], "start": {"x":5,"y":5}, "goal": [90,90]})")
          .find("obstacles[0][1]: closer than"),
      std::string::npos);
  EXPECT_NE(error_of("{" + room +
                     R"(, "obstacles": [[[10,10],[60,10.0001],[110,10]]], "start": {"x":5,"y":5}, "goal": [90,90]})")
                .find("sliver"),
            std::string::npos);
  EXPECT_NE(
      error_of(R"({"boundary": [[0,0],[1e20,0],[1e20,1e20]], "obstacles": [], "start": {"x":5,"y":1}, "goal": [9,1]})")
          .find("farther than"),
      std::string::npos);
  EXPECT_NE(error_of("{" + room + R"(, "obstacles": [], "start": {"x":5,"y":5}, "goal": [900,90]})").find("goal"),
            std::string::npos);
  EXPECT_NE(error_of("{" + room + R"(, "obstacles": [], "start": {"x":5,"y":5,"z":1}, "goal": [90,90]})")
                .find("start.z: unknown key"), std::string::npos);
  EXPECT_NE(
      error_of(
          "{" + room +
          R"(, "obstacles": [])"
          R"(, "start": {"x":5,"y":5}, "goal": [90,90], "bounds": {"min": [-1e4,-1e4], "max": [1e4,1e4]}})")
          .find("larger than"),
      std::string::npos);
  EXPECT_NE(
      error_of(
          "{" + room +
          R"(, "obstacles": [], "clutter": [{"shape": "box", "center": [150, 50], "size": 1}])"
          R"(, "start": {"x":5,"y":5}, "goal": [90,90]})")
          .find("clutter[0].center"),
      std::string::npos);
  EXPECT_EQ(error_of("{" + room + R"(, "obstacles": [], "start": {"x":5,"y":5}, "goal": [90,90]})"), "accepted");
}

}  // namespace
}  // namespace toponav::experiments
