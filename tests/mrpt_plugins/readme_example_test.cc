#include <gtest/gtest.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "tests/mrpt_plugins/clip_observations.h"

namespace novelty::mrpt_plugins {
namespace {

std::string Between(const std::string& text, const std::string& begin, const std::string& end) {
  const auto a = text.find(begin);
  const auto b = a == std::string::npos ? a : text.find(end, a + begin.size());
  if (b == std::string::npos) return "";
  return text.substr(a + begin.size(), b - a - begin.size());
}

std::string Read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The README shows a whole program, which scripts/example.sh builds against the installed
// package and runs.
TEST(ReadmeExample, TheReadmeQuotesTheCompiledExampleWhole) {
  const std::string code = Read(std::string(NOVELTY_SOURCE_DIR) + "/examples/surprise_pngs.cc");
  ASSERT_FALSE(code.empty());
  const std::string readme = Read(std::string(NOVELTY_SOURCE_DIR) + "/README.md");
  const std::string quoted = Between(readme, "```cpp\n", "```\n");
  EXPECT_EQ(quoted, code) << "README.md's ```cpp block must equal examples/surprise_pngs.cc";
}

// examples/maps.ini, which the README points to, loads: both maps, the changed keys changed, the
// others at their defaults.
TEST(ReadmeExample, TheExamplesIniLoads) {
  const std::string path = std::string(NOVELTY_SOURCE_DIR) + "/examples/maps.ini";
  EXPECT_NE(Read(std::string(NOVELTY_SOURCE_DIR) + "/README.md").find("examples/maps.ini"),
            std::string::npos);
  mrpt::maps::CMultiMetricMap maps;
  maps.setListOfMaps(LoadMultiMapConfig(path));
  ASSERT_EQ(maps.maps.size(), 2u);
  const CAppearanceMap& map = *maps.mapByClass<CAppearanceMap>();
  EXPECT_EQ(map.map().options().surprise.update.forgetting_factor, 0.8);
  EXPECT_EQ(map.map().options().views.new_view_distance,
            appearance::AppearanceMapOptions().views.new_view_distance);
}

// The example's steps on a short clip with the shipped .ini (the example itself is built against
// the installed package and run by scripts/example.sh): surprise appears once the map has views,
// its picture has the frame's size, and correct robot poses raise no pose warning.
TEST(ReadmeExample, GivesSurpriseFromTheShippedIni) {
  mrpt::maps::CMultiMetricMap maps;
  maps.setListOfMaps(
      LoadMultiMapConfig(std::string(NOVELTY_SOURCE_DIR) + "/share/novelty_run.ini"));
  for (const sim::SimulatedFrame& f : Frames())
    maps.insertObservation(Observation(f), mrpt::poses::CPose3D());
  const CAppearanceMap& map = *maps.mapByClass<CAppearanceMap>();
  const cv::Mat& surprise = map.lastProducts().surprise;
  ASSERT_EQ(surprise.size(), cv::Size(160, 120));
  int finite = 0;
  for (auto it = surprise.begin<float>(); it != surprise.end<float>(); ++it) {
    if (std::isfinite(*it)) {
      ++finite;
      ASSERT_GE(*it, 0.0f);  // a KL divergence
    }
  }
  EXPECT_GT(finite, 160 * 120 / 2);  // the arc returns over its own views
  EXPECT_EQ(map.surpriseImage().getWidth(), 160u);
  EXPECT_EQ(map.poseWarnings(), 0);
}

// The trap of the pose convention: the camera's pose passed where insertObservation wants the
// robot's. The map cannot refuse it, but every such frame is warned about; the right poses of the
// same frames raise nothing.
TEST(ReadmeExample, TheCameraPosePassedAsTheRobotPoseIsWarnedAbout) {
  Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();  // camera on the robot, 1.1 m up
  mount.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  mount.linear() =
      Eigen::AngleAxisd(16.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()) * mount.linear();
  mount.translation() << 0.1, 0.0, 1.1;
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(160, 120, 60.0 * M_PI / 180);
  CAppearanceMap right, wrong, twice;
  for (CAppearanceMap* m : {&right, &wrong, &twice})
    m->setMinLoggingLevel(mrpt::system::LVL_ERROR);  // the warnings are counted, not shown
  const int n = 12;
  for (int k = 0; k < n; ++k) {
    const sim::SimulatedFrame& f = Frames()[std::size_t(k)];
    const auto obs = sensors::MakeRgbdObservation(f.time, f.rgb, f.depth, camera, mount);
    right.insertObservation(obs, sensors::ToMrpt(f.T_world_cam * mount.inverse()));
    wrong.insertObservation(obs, sensors::ToMrpt(f.T_world_cam));  // the optical pose
    mrpt::poses::CPose3D sensor;
    obs.getSensorPose(sensor);  // robot ⊕ sensorPose: the sensor's pose in the world
    twice.insertObservation(obs, sensors::ToMrpt(f.T_world_cam * mount.inverse()) + sensor);
  }
  EXPECT_EQ(right.poseWarnings(), 0);
  EXPECT_EQ(wrong.poseWarnings(), n);
  EXPECT_EQ(twice.poseWarnings(), n);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
