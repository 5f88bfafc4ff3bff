#include "sim/output/ground_truth_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/output/ground_truth_format.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/simulate_frames.h"
#include "tests/sim/scenario/simulated_run.h"

namespace novelty::sim {
namespace {

namespace fs = std::filesystem;

// A box put on the table at 1 s and a cup taken away at 2 s, in two phases.
const char* kScenario = R"(
name gt
frames 20
fps 7
camera 64 48 60
rig rgbd
mount 0.0 0.0 1.10 90 16
material wood phong 0.45 0.28 0.14
material red phong 0.75 0.10 0.08
object table box 1.2 0.8 0.72 wood at 0 0 fixed
object box box 0.20 0.12 0.20 red at 0.1 0.0 on table absent mass 0.4
object cup cup 0.06 0.11 red at -0.15 0.05 on table mass 0.25
lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9
arc 0 0 1.6 -95 -85 0.05
phase A 1 7 before
phase B 8 20 after
event 1.0 add box
event 2.0 remove cup
)";

// What the writer wrote (through the simulator's runner) reads back as the simulator has it in
// memory: poses, depth to its 0.2 mm step, novelty codes, phases, names, and the regions.
TEST(GroundTruthReader, ReadsBackWhatTheWriterWrote) {
  const fs::path dir = SimulateIntoTempFolder(kScenario, "novelty_gt_reader");
  const GroundTruthReader gt((dir / "groundtruth").string());
  std::istringstream in(kScenario);
  const std::vector<SimulatedFrame> frames = SimulateFrames(ParseScenario(in, "gt.scn"));
  ASSERT_EQ(gt.CameraPoses().size(), frames.size());
  int frames_with_box = 0, frames_with_removed = 0, removed_in_memory = 0, added_in_memory = 0;
  for (const SimulatedFrame& f : frames) {
    const Eigen::Isometry3d& T = gt.CameraPoses().at(f.index);
    EXPECT_LT((T.matrix() - f.T_world_cam.matrix()).cwiseAbs().maxCoeff(), 1e-5) << f.index;
    const cv::Mat depth = gt.Depth(f.index);
    ASSERT_EQ(depth.type(), CV_32FC1);
    EXPECT_LE(cv::norm(depth, f.depth, cv::NORM_INF),
              0.5 / ground_truth::kDepthUnitsPerMetre + 1e-6);
    EXPECT_EQ(cv::norm(gt.Novelty(f.index), f.novelty, cv::NORM_INF), 0.0) << f.index;
    EXPECT_EQ(gt.PhaseOf(f.index), f.index <= 7 ? "A" : "B");
    const auto regions = gt.ChangedRegions(f.index, 1);
    if (regions.count("box")) {
      ++frames_with_box;
      EXPECT_EQ(cv::countNonZero(regions.at("box")),
                cv::countNonZero(f.novelty == ground_truth::kNoveltyAdded));
    }
    frames_with_removed += regions.count("removed") ? 1 : 0;
    removed_in_memory += cv::countNonZero(f.novelty == ground_truth::kNoveltyRemoved) > 0;
    added_in_memory += cv::countNonZero(f.novelty == ground_truth::kNoveltyAdded) > 0;
  }
  EXPECT_EQ(frames_with_box, added_in_memory);  // the box is the only added object
  EXPECT_EQ(frames_with_removed, removed_in_memory);
  EXPECT_GT(frames_with_box, 10);  // from frame 8 (1.0 s) on
  EXPECT_GT(frames_with_removed, 0);
  EXPECT_EQ(gt.Phases().size(), 2u);
  EXPECT_EQ(gt.ObjectNames().at(ground_truth::kArmId), "arm");
  EXPECT_EQ(gt.ObjectNames().at(0), "room");
  const cv::Mat ids = gt.Ids(1);
  ASSERT_EQ(ids.type(), CV_32SC1);
  double lo, hi;
  cv::minMaxLoc(ids, &lo, &hi);
  EXPECT_GE(lo, -1.0);  // −1: no surface
  EXPECT_TRUE(gt.Depth(999).empty());
}

TEST(GroundTruthReader, BadFilesAreNamedWithTheirLine) {
  EXPECT_THROW(GroundTruthReader("/nonexistent"), std::runtime_error);
  const fs::path dir = fs::temp_directory_path() / "novelty_gt_bad";
  fs::create_directories(dir);
  std::ofstream(dir / "poses.csv") << "frame,time\n1,0,A,x\n";
  try {
    GroundTruthReader reader(dir.string());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("poses.csv:2: malformed row"), std::string::npos)
        << e.what();
  }
  // A NaN or zero quaternion is not a pose.
  for (const char* q : {"nan,0,0,1", "0,0,0,0", "0,0,0,2"}) {
    std::ofstream(dir / "poses.csv") << "frame,time,phase,x,y,z,qx,qy,qz,qw\n1,0,A,1,2,3," << q
                                     << "\n";
    try {
      GroundTruthReader reader(dir.string());
      ADD_FAILURE() << q;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("poses.csv:2: malformed row (not a rigid pose"),
                std::string::npos)
          << e.what();
    }
  }
  std::ofstream(dir / "poses.csv") << "frame,time,phase,x,y,z,qx,qy,qz,qw\n1,0,A,1,2,3,0,0,0,1\n";
  EXPECT_EQ(GroundTruthReader(dir.string()).CameraPoses().size(), 1u);
}

}  // namespace
}  // namespace novelty::sim
