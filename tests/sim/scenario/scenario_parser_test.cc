#include "sim/scenario/scenario_parser.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "tests/sim/scenario/scenario_text.h"

namespace novelty::sim {
namespace {

const char* kMinimal = R"(
name tiny        # a comment
frames 20
fps 10
camera 160 120 60
rig trinocular 0.12
sensor noise 0.5 gamma 2.0
material wood phong 0.5 0.3 0.1
material cloth phong 0.9 0.9 0.9
texture cloth checker 0.1 0.1 0.1 10
object table box 1 0.6 0.7 wood at 0 0 fixed
object cloth plane 1 0.6 cloth at 0 0 on table
object cup cup 0.04 0.1 wood at 0.1 0 on cloth absent mass 0.2
lamp l1 0 0 2.5 1 1 1 radius 0.1
window 0.5 1.4 1.6 1.2
arc 0.3 -0.2 1.5 -100 -80 0.1
stop 1
event 0.5 add cup arm 0.4
event 1.0 lamp l1 1 1 2
phase A 1 10 first half
)";

std::string ErrorOf(const std::string& text) {
  try {
    ParseScenarioText(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioParser, ReadsEveryStatement) {
  const Scenario s = ParseScenarioText(kMinimal);
  EXPECT_EQ(s.name, "tiny");
  EXPECT_EQ(s.frames, 20);
  EXPECT_DOUBLE_EQ(s.fps, 10.0);
  EXPECT_EQ(s.camera.width, 160);
  EXPECT_NEAR(s.camera.fx, 80.0 / std::tan(M_PI / 6), 1e-9);
  EXPECT_EQ(s.rig.kind, RigKind::kTrinocular);
  EXPECT_DOUBLE_EQ(s.render.noise_sigma, 0.5);
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[2].id, 3);
  EXPECT_EQ(s.objects[2].support, "cloth");
  EXPECT_FALSE(s.objects[2].present);
  EXPECT_TRUE(s.objects[0].fixed);
  EXPECT_EQ(s.materials.at("cloth").texture.kind, Texture::Kind::kChecker);
  ASSERT_EQ(s.events.size(), 2u);
  EXPECT_EQ(s.events[0].kind, EventSpec::Kind::kAdd);
  EXPECT_DOUBLE_EQ(s.events[0].arm_duration, 0.4);
  EXPECT_EQ(s.events[1].kind, EventSpec::Kind::kLampMove);
  EXPECT_EQ(s.phases.at(0).description, "first half");
  // Multi-number statements keep their order (argument evaluation order is unspecified in C++).
  EXPECT_EQ(*s.window, Eigen::Vector4d(0.5, 1.4, 1.6, 1.2));
  EXPECT_NEAR(s.trajectory.At(0).x, 0.3 + 1.5 * std::cos(-100 * M_PI / 180), 1e-12);
  EXPECT_NEAR(s.trajectory.At(0).y, -0.2 + 1.5 * std::sin(-100 * M_PI / 180), 1e-12);
  EXPECT_NEAR(s.trajectory.Duration(), 1.5 * 20 * M_PI / 180 / 0.1 + 0.1 / 0.3 + 1.0, 1e-9);
}

TEST(ScenarioParser, ErrorsNameFileLineAndProblem) {
  const std::string base = "name x\narc 0 0 1 0 10 0.1\n";
  EXPECT_EQ(ErrorOf(base + "frames ten\n"), "test.scn:3: expected a number for frames, got 'ten'");
  EXPECT_EQ(ErrorOf(base + "bogus 1\n"), "test.scn:3: unknown keyword 'bogus'");
  EXPECT_EQ(ErrorOf(base + "object a box 1 1 1 steel at 0 0\n"),
            "test.scn:3: undeclared material 'steel'");
  EXPECT_EQ(ErrorOf(base + "material m phong 1 1 1\nobject a box 1 1 1 m at 0 0 on b\n"),
            "test.scn:4: support 'b' is not a declared object");
  EXPECT_EQ(ErrorOf(base + "event 1 add ghost\n"),
            "test.scn:3: event on undeclared object 'ghost'");
  EXPECT_EQ(ErrorOf(base + "frames 5\nfps 1\nmaterial m phong 1 1 1\nobject a box 1 1 1 m at 0 0\n"
                           "event 9 remove a\n"),
            "test.scn:7: event at 9.000000 s is after the run's end (5.000000 s)");
  EXPECT_EQ(ErrorOf(base + "camera 320 240\n"),
            "test.scn:3: missing horizontal field of view after '240'");
  EXPECT_EQ(ErrorOf("frames 3\n"), "test.scn: no 'name' statement");
  EXPECT_EQ(ErrorOf("name x\n"), "test.scn: neither 'static_camera' nor a trajectory ('arc')");
  EXPECT_EQ(ErrorOf(base + "arc 0 0 -1 0 10 0.1\n"),
            "test.scn:3: radius must be in [0.01, 100], got -1");
  EXPECT_EQ(ErrorOf(base + "event 1 sun 0 0 -1\n"),
            "test.scn:3: a sun event needs 'daylight' declared before it");
  EXPECT_EQ(ErrorOf(base + "daylight 0 0 -1 1 1 1\nevent 1 sun 0 0 0\n"),
            "test.scn:4: sun direction must not be zero");
  EXPECT_EQ(ErrorOf(base + "material m phong 1 1 1\nobject a box 1 1 1 m at 0 0\n"
                           "event 1 walk a 2 2\n"),
            "test.scn:5: missing walk seconds after '2'");
  EXPECT_EQ(ErrorOf(base + "event 1 exposure 0\n"),
            "test.scn:3: exposure must be in [0.0001, 10000], got 0");
}

TEST(ScenarioParser, ReadsWalkSunAndExposureEvents) {
  const Scenario s = ParseScenarioText(
      "name x\nstatic_camera 0 -2 1 0 0 0\nframes 100\nfps 1\ndaylight 0 0 -1 1 1 1\n"
      "material m phong 1 1 1\nobject a box 1 1 1 m at 0 0\n"
      "event 1 walk a 2 3 4.5\nevent 2 sun 0 3 -4 over 10\nevent 3 exposure 1.5\n");
  ASSERT_EQ(s.events.size(), 3u);
  EXPECT_EQ(s.events[0].kind, EventSpec::Kind::kWalk);
  EXPECT_EQ(s.events[0].position, Eigen::Vector3d(2, 3, 0));
  EXPECT_EQ(s.events[0].duration, 4.5);
  EXPECT_EQ(s.events[1].kind, EventSpec::Kind::kSun);
  EXPECT_TRUE(s.events[1].position.isApprox(Eigen::Vector3d(0, 0.6, -0.8)));  // normalised
  EXPECT_EQ(s.events[1].duration, 10);
  EXPECT_EQ(s.events[2].kind, EventSpec::Kind::kExposure);
  EXPECT_EQ(s.events[2].value, 1.5);
  EXPECT_EQ(s.events[2].duration, 0);
}

// The reproducers of the reliability issue: each was accepted and then crashed, hung, allocated
// gigabytes or wrote outside --out. Each is now an error naming the line, value and range.
TEST(ScenarioParser, OutOfRangeNumbersAreRefusedBeforeTheSimulatorSeesThem) {
  const std::string base = "name x\narc 0 0 1 0 10 0.1\n";
  const std::pair<std::string, std::string> cases[] = {
      {"sensor pixel_samples 1000\n", "pixel_samples must be in [1, 8], got 1000"},
      {"fps 1e-300\n", "fps must be in [0.1, 1000], got 1e-300"},
      {"camera 20000 20000 60\n", "width must be in [8, 4096], got 20000"},
      {"camera 46341 46341 60\n", "width must be in [8, 4096], got 46341"},
      {"repeat 2000000000\n", "repeat count must be in [1, 100000], got 2e+09"},
      {"ambient 1e39 0 0\n", "ambient colour must be in [0, 10000], got 1e+39"},
      {"lamp l 0 0 2 1e300 1 1\n", "lamp intensity must be in [0, 10000], got 1e+300"},
      {"material m phong 1 1 1\nobject a box 1e9 1 1 m at 0 0\n", "box size must be in"},
      {"material m phong 1 1 1\nobject a box 1e-9 1 1 m at 0 0\n", "box size must be in"},
      {"material m phong 1 1 1\nobject a sphere 0.1 m at 1e12 0\n", "x must be in"},
      {"material m phong 1 1 1\nobject a sphere 0.1 m at 0 0 mass 1e20\n", "mass must be in"},
      {"arc 0 0 1e10 0 10 0.1\n", "radius must be in [0.01, 100]"},
      {"start_offset 1e8 0\n", "dx must be in [-10, 10]"},
      {"mount 0 0 1 90 1e6\n", "mount pitch must be in [-90, 90]"},
      {"sensor noise -3\n", "noise must be in [0, 100]"},
      {"material g glass 1 1 1 0.5 10 0.2\n", "index of refraction must be in [1, 5]"},
  };
  for (const auto& [line, problem] : cases) {
    const std::string e = ErrorOf(base + line);
    EXPECT_NE(e.find("test.scn:"), std::string::npos) << line;
    EXPECT_NE(e.find(problem), std::string::npos) << line << " → " << e;
  }
  EXPECT_NE(ErrorOf(base + "camera 4096 4096 60\nsensor pixel_samples 8\n").find("rays a frame"),
            std::string::npos);
}

TEST(ScenarioParser, NameCannotLeaveTheOutputFolder) {
  for (const char* bad : {"../../x", "a/b", ".hidden", "/etc/x"}) {
    EXPECT_NE(
        ErrorOf(std::string("name ") + bad + "\narc 0 0 1 0 10 0.1\n").find("plain file name"),
        std::string::npos)
        << bad;
  }
  EXPECT_EQ(ParseScenarioText("name run-2_b.1\narc 0 0 1 0 10 0.1\n").name, "run-2_b.1");
}

TEST(ScenarioParser, MissingFileIsNamed) {
  try {
    LoadScenario("/nonexistent/x.scn");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/x.scn: cannot open scenario file");
  }
}

// The object scenarios print photographs from ../shared/data/textures beside the checkout; where
// the shared data is absent they are left out (as every test on real data skips).
bool NeedsAbsentSharedData(const std::filesystem::path& scenario) {
  std::ifstream in(scenario);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text.find("../shared/data/") != std::string::npos &&
         !std::filesystem::exists(std::string(NOVELTY_SOURCE_DIR) + "/../shared/data/textures");
}

TEST(ScenarioParser, EveryShippedScenarioParses) {
  int count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(NOVELTY_SOURCE_DIR) + "/share/scenarios")) {
    if (entry.path().extension() != ".scn") continue;
    SCOPED_TRACE(entry.path().string());
    if (NeedsAbsentSharedData(entry.path())) {
      std::printf("skipped (../shared/data/textures absent): %s\n", entry.path().c_str());
      continue;
    }
    const Scenario s = LoadScenario(entry.path().string());
    EXPECT_FALSE(s.name.empty());
    EXPECT_GT(s.frames, 0);
    if (!s.static_camera) {
      EXPECT_GE(s.trajectory.Duration(), s.Duration() - 1e-6);
    }
    ++count;
  }
  EXPECT_GE(count, 1);
}

}  // namespace
}  // namespace novelty::sim
