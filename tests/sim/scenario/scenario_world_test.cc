#include "sim/scenario/scenario_world.h"

#include <gtest/gtest.h>

#include <sstream>

#include "sim/output/ground_truth_writer.h"
#include "sim/render/renderer.h"
#include "sim/scenario/scenario_parser.h"
#include "tests/sim/scenario/scenario_text.h"

namespace novelty::sim {
namespace {

const char* kTable = R"(
name table
frames 30
fps 10
camera 160 120 60
material wood phong 0.5 0.3 0.1
material white phong 0.9 0.9 0.9
material black phong 0.05 0.05 0.05
object table box 1.0 0.6 0.70 wood at 0 0 fixed
object cloth plane 1.0 0.6 white at 0 0 on table
object box box 0.1 0.1 0.2 wood at -0.2 0 on cloth mass 0.4
object cup cup 0.04 0.1 black at 0.15 0.05 on cloth absent mass 0.2
lamp l1 0 0 2.5 1.5 1.5 1.5
)";

TEST(ScenarioWorld, ObjectsComeToRestOnTheTable) {
  const Scenario s = ParseScenarioText(std::string(kTable) +
                                       "static_camera 1.2 -1.2 1.3 0 0 0.7\n"
                                       "event 0.5 add cup\n");
  ScenarioWorld world(s);
  world.AdvanceTo(2.5);
  const double cloth_top = 0.70 + 0.001;
  EXPECT_NEAR(world.ObjectPose("box").translation().z(), cloth_top + 0.1, 0.003);
  EXPECT_NEAR(world.ObjectPose("cup").translation().z(), cloth_top + 0.05, 0.003);
  const Eigen::Vector3d up = world.ObjectPose("cup").linear() * Eigen::Vector3d::UnitZ();
  EXPECT_GT(up.z(), 0.9999);  // upright, not tipped over
  EXPECT_NEAR(world.ObjectPose("cup").translation().x(), 0.15, 0.003);
}

TEST(ScenarioWorld, EventsHappenWhenTheArmArrives) {
  const Scenario s = ParseScenarioText(std::string(kTable) +
                                       "static_camera 1.2 -1.2 1.3 0 0 0.7\n"
                                       "event 1.0 add cup arm 0.8\n"
                                       "event 2.0 remove box\n");
  ScenarioWorld world(s);
  world.AdvanceTo(0.9);
  EXPECT_FALSE(world.IsPresent("cup"));
  EXPECT_TRUE(world.AddedIds().empty());
  world.AdvanceTo(1.2);  // the arm is reaching in, the cup not yet placed
  EXPECT_FALSE(world.IsPresent("cup"));
  EXPECT_EQ(world.AddedIds(), std::vector<int>{kArmObjectId});
  world.AdvanceTo(1.5);
  EXPECT_TRUE(world.IsPresent("cup"));
  world.AdvanceTo(2.1);  // the arm has gone, the box removed
  EXPECT_EQ(world.AddedIds(), std::vector<int>{4});
  EXPECT_EQ(world.RemovedIds(), std::vector<int>{3});
  EXPECT_EQ(world.applied_events().size(), 2u);
}

TEST(ScenarioWorld, NoveltyMaskMarksAddedObjectsAndWhereRemovedOnesWere) {
  const Scenario s = ParseScenarioText(std::string(kTable) +
                                       "static_camera 1.0 -1.0 1.4 0 0 0.7\n"
                                       "event 0.2 add cup\nevent 0.2 remove box\n");
  ScenarioWorld world(s);
  world.AdvanceTo(1.0);
  RayScene now, reference;
  world.AddToScene(now);
  now.Commit();
  world.AddNoveltyReferenceToScene(reference);
  reference.Commit();
  const cv::Mat ids = RenderIds(now, s.camera, world.HeadPose());
  const cv::Mat ref_ids = RenderIds(reference, s.camera, world.HeadPose());
  const cv::Mat mask =
      GroundTruthWriter::NoveltyMask(ids, ref_ids, world.AddedIds(), world.RemovedIds());
  int added = 0, removed = 0;
  for (int i = 0; i < mask.rows * mask.cols; ++i) {
    const int m = mask.at<uint8_t>(i);
    EXPECT_EQ(m == 255, ids.at<int>(i) == 4);                             // the cup now
    EXPECT_EQ(m == 128, ref_ids.at<int>(i) == 3 && ids.at<int>(i) != 4);  // where the box was
    added += m == 255;
    removed += m == 128;
  }
  EXPECT_GT(added, 20);
  EXPECT_GT(removed, 20);
}

TEST(ScenarioWorld, AnObjectAddedAndLaterRemovedLeavesARemovedRegion) {
  const Scenario s = ParseScenarioText(std::string(kTable) +
                                       "static_camera 1.0 -1.0 1.4 0 0 0.7\n"
                                       "event 0.2 add cup\nevent 1.0 remove cup\n");
  ScenarioWorld world(s);
  world.AdvanceTo(1.5);
  EXPECT_EQ(world.RemovedIds(), std::vector<int>{4});
  EXPECT_TRUE(world.AddedIds().empty());
  RayScene now, reference;
  world.AddToScene(now);
  now.Commit();
  world.AddNoveltyReferenceToScene(reference);
  reference.Commit();
  const cv::Mat mask = GroundTruthWriter::NoveltyMask(
      RenderIds(now, s.camera, world.HeadPose()), RenderIds(reference, s.camera, world.HeadPose()),
      world.AddedIds(), world.RemovedIds());
  EXPECT_GT(cv::countNonZero(mask == 128), 20);
  EXPECT_EQ(cv::countNonZero(mask == 255), 0);
}

TEST(ScenarioWorld, AWalkerSlidesAtConstantSpeedAndCountsAsForeground) {
  const Scenario s = ParseScenarioText(std::string(kTable) +
                                       "static_camera 1.2 -1.2 1.3 0 0 0.7\n"
                                       "object person box 0.4 0.3 1.7 wood at -2 -1 absent\n"
                                       "event 0.5 add person\n"
                                       "event 0.5 walk person 1 -1 2\n");
  ScenarioWorld world(s);
  world.AdvanceTo(1.5);  // half way: x from −2 to 1 over 2 s
  EXPECT_NEAR(world.ObjectPose("person").translation().x(), -0.5, 0.01);
  EXPECT_NEAR(world.ObjectPose("person").translation().y(), -1.0, 1e-9);
  EXPECT_NEAR(world.ObjectPose("person").translation().z(), 0.85, 1e-9);  // standing on the floor
  world.AdvanceTo(3.0);
  EXPECT_NEAR(world.ObjectPose("person").translation().x(), 1.0, 1e-9);
  EXPECT_EQ(world.AddedIds(), std::vector<int>{5});
  // The background is the scene without it.
  RayScene background;
  world.AddBackgroundToScene(background);
  background.Commit();
  const cv::Mat ids = RenderIds(background, s.camera, world.HeadPose());
  EXPECT_EQ(cv::countNonZero(ids == 5), 0);
  EXPECT_GT(cv::countNonZero(ids == 3), 20);  // the box, there from the start
}

TEST(ScenarioWorld, SunAndExposureChangeLinearlyOverTheirDurations) {
  const Scenario s = ParseScenarioText(std::string(kTable) +
                                       "static_camera 1.2 -1.2 1.3 0 0 0.7\n"
                                       "daylight 1 0 0 0.2 0.2 0.2\n"
                                       "sensor exposure 1.0\n"
                                       "event 1 sun 0 1 0 over 2\n"
                                       "event 1 exposure 2 over 4\n");
  ScenarioWorld world(s);
  world.AdvanceTo(0.9);
  EXPECT_NEAR(world.CurrentLighting().directional[0].direction.x(), 1.0, 1e-9);
  EXPECT_NEAR(world.CurrentExposure(), 1.0, 1e-9);
  world.AdvanceTo(2.0);  // half way: (0.5, 0.5, 0) normalised, exposure 1.25
  const Eigen::Vector3d d = world.CurrentLighting().directional[0].direction;
  EXPECT_NEAR(d.x(), std::sqrt(0.5), 1e-3);
  EXPECT_NEAR(d.y(), std::sqrt(0.5), 1e-3);
  EXPECT_NEAR(world.CurrentExposure(), 1.25, 1e-3);
  world.AdvanceTo(5.5);
  EXPECT_NEAR(world.CurrentLighting().directional[0].direction.y(), 1.0, 1e-9);
  EXPECT_NEAR(world.CurrentExposure(), 2.0, 1e-9);
}

TEST(ScenarioWorld, CameraHeadSitsOnTheMastLookingAtTheArcCentre) {
  const Scenario s = ParseScenarioText(std::string(kTable) +
                                       "mount 0 0 1.10 90 15\n"
                                       "arc 0 0 1.5 -100 -80 0.1\n");
  ScenarioWorld world(s);
  world.AdvanceTo(2.0);
  const Eigen::Isometry3d head = world.HeadPose();
  EXPECT_NEAR(head.translation().z(), 1.10, 0.005);
  const Eigen::Vector3d axis = head.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(std::asin(-axis.z()), 15.0 * M_PI / 180, 0.01);  // pitched 15° down
  // Horizontally the optical axis points at the arc's centre (the origin).
  const Eigen::Vector2d to_centre = -head.translation().head<2>().normalized();
  EXPECT_GT(axis.head<2>().normalized().dot(to_centre), std::cos(3.0 * M_PI / 180));
}

}  // namespace
}  // namespace novelty::sim
