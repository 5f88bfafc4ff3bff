#include "mrpt_plugins/rawlog_map_player.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cstring>
#include <filesystem>

#include "maps/appearance/appearance_map.h"
#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sim/output/ground_truth_reader.h"
#include "tests/sim/scenario/simulated_run.h"

namespace novelty::mrpt_plugins {
namespace {

namespace fs = std::filesystem;

// A short arc there and back (the way back replaces views), simulated into a rawlog with ground
// truth in the temp folder novelty_player_<name>.
fs::path SimulateClip(const std::string& name) {
  return sim::SimulateIntoTempFolder(R"(
name clip
frames 24
fps 7
camera 96 72 60
rig rgbd
sensor noise 1.0 gamma 2.2
mount 0.0 0.0 1.10 90 16
material wood phong 0.45 0.28 0.14 0.1 20
material red phong 0.75 0.10 0.08 0.2 30
object table box 1.2 0.8 0.72 wood at 0 0 fixed
object box box 0.14 0.06 0.20 red at 0.25 0.20 on table mass 0.4
lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9
arc 0 0 1.6 -100 -90 0.15
arc 0 0 1.6 -90 -100 0.15
)",
                                     "novelty_player_" + name);
}

// The maps of an .ini, as an MRPT program builds them.
void BuildMaps(const mrpt::config::CConfigFileBase& ini, mrpt::maps::CMultiMetricMap& multi) {
  mrpt::maps::TSetOfMetricMapInitializers inits;
  inits.loadFromConfigFile(ini, "map");
  multi.setListOfMaps(inits);
}

const char* kIni = R"(
[map]
CAppearanceMap_count = 1
CDifferencingMap_count = 1
[map_CAppearanceMap_00_options]
xi = 0.02
[map_CDifferencingMap_00_options]
)";

// The MRPT way (a CMultiMetricMap from an .ini, observations through insertObservation with the
// robot pose) and the library way (frames decoded by RawlogFrameReader into an AppearanceMap
// with the same options) give the same surprise, bit for bit, frame after frame.
TEST(RawlogMapPlayer, MultiMetricMapPathEqualsTheLibraryApi) {
  const fs::path dir = SimulateClip("same");
  const auto poses = sim::GroundTruthReader((dir / "groundtruth").string()).CameraPoses();
  const mrpt::config::CConfigFileMemory ini(kIni);
  mrpt::maps::CMultiMetricMap multi;
  BuildMaps(ini, multi);
  const auto mrpt_map = multi.mapByClass<CAppearanceMap>();
  ASSERT_TRUE(mrpt_map);
  ASSERT_TRUE(multi.mapByClass<CDifferencingMap>());

  appearance::AppearanceMap library(
      AppearanceMapConfig::FromConfig(ini, "map_CAppearanceMap_00_options", "test").map);
  sensors::RawlogFrameReader reader((dir / "clip.rawlog").string());
  RawlogMapPlayer player((dir / "clip.rawlog").string(), PoseSource::kGroundTruth, poses);
  int frames = 0, index = 0;
  for (core::Frame f; reader.Next(f);) {
    ASSERT_TRUE(player.Next(multi, index));
    ASSERT_EQ(index, f.index);
    const cv::Mat expected = library.Insert(f.rgb, f.depth, f.camera, poses.at(f.index)).surprise;
    const cv::Mat got = mrpt_map->lastProducts().surprise;
    ASSERT_EQ(got.size(), expected.size());
    EXPECT_EQ(std::memcmp(got.data, expected.data, expected.total() * expected.elemSize()), 0)
        << "frame " << f.index;
    ++frames;
  }
  EXPECT_FALSE(player.Next(multi, index));
  EXPECT_EQ(frames, 24);
  EXPECT_EQ(player.skipped(), 0);
  EXPECT_EQ(mrpt_map->map().store().size(), library.store().size());
  EXPECT_GT(library.store().size(), 1);
}

// A frame without a pose is skipped and counted by name; a rawlog cut short ends the play with
// the reason, keeping the frames read.
TEST(RawlogMapPlayer, AFrameRangePlaysOnlyItsFramesAndEndsAfterIt) {
  const fs::path dir = SimulateClip("range");
  auto poses = sim::GroundTruthReader((dir / "groundtruth").string()).CameraPoses();
  poses.erase(3);  // outside the range: not played, so not skipped
  mrpt::maps::CMultiMetricMap multi;
  BuildMaps(mrpt::config::CConfigFileMemory(kIni), multi);
  RawlogMapPlayer player((dir / "clip.rawlog").string(), PoseSource::kGroundTruth, poses);
  player.SetFrameRange(5, 9);
  std::vector<int> played;
  for (int index = 0; player.Next(multi, index);) played.push_back(index);
  EXPECT_EQ(played, (std::vector<int>{5, 6, 7, 8, 9}));
  EXPECT_EQ(player.skipped(), 0);
  EXPECT_THROW(player.SetFrameRange(0, 3), std::invalid_argument);
  EXPECT_THROW(player.SetFrameRange(4, 3), std::invalid_argument);
}

TEST(RawlogMapPlayer, MissingPosesAndATruncatedRawlogAreReportedNotFatal) {
  const fs::path dir = SimulateClip("faults");
  auto poses = sim::GroundTruthReader((dir / "groundtruth").string()).CameraPoses();
  poses.erase(3);
  // The same rawlog cut in half, beside its images (MRPT finds them by the rawlog's name).
  fs::create_directories(dir / "cut");
  const fs::path cut = dir / "cut" / "clip.rawlog";
  fs::copy_file(dir / "clip.rawlog", cut);
  fs::resize_file(cut, fs::file_size(cut) / 2);
  fs::create_directory_symlink(dir / "clip_Images", dir / "cut" / "clip_Images");
  mrpt::maps::CMultiMetricMap multi;
  BuildMaps(mrpt::config::CConfigFileMemory(kIni), multi);
  {
    RawlogMapPlayer player((dir / "clip.rawlog").string(), PoseSource::kGroundTruth, poses);
    std::vector<int> hooked, inserted;
    player.SetBeforeInsert([&](int frame) { hooked.push_back(frame); });
    int index = 0, frames = 0;
    while (player.Next(multi, index)) {
      ++frames;
      inserted.push_back(index);
    }
    EXPECT_EQ(frames, 23);
    EXPECT_EQ(hooked, inserted) << "told of each frame inserted, not of the skipped frame 3";
    ASSERT_EQ(player.skipped(), 1);
    EXPECT_NE(player.skip_reasons()[0].find("frame 3"), std::string::npos)
        << player.skip_reasons()[0];
    EXPECT_TRUE(player.stopped_by().empty());
  }
  {
    RawlogMapPlayer player(cut.string(), PoseSource::kGroundTruth, poses);
    int index = 0, frames = 0;
    while (player.Next(multi, index)) ++frames;
    EXPECT_GT(frames, 0);
    EXPECT_EQ(player.skipped(), frames < 3 ? 0 : 1);  // frame 3 has no pose
    EXPECT_LT(frames, 23);
    EXPECT_FALSE(player.stopped_by().empty());
    EXPECT_NE(player.stopped_by().find("cut/clip.rawlog"), std::string::npos)
        << player.stopped_by();
  }
  EXPECT_THROW(ParsePoseSource("gps"), std::invalid_argument);
  EXPECT_EQ(ParsePoseSource("odometry"), PoseSource::kOdometry);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
