#include "sensors/stereo/stereo_depth.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "eval/depth_accuracy.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/rig_frame_reader.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_runner.h"
#include "sim/output/ground_truth_reader.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

// Simulates the first frames of a scenario into a folder of its own (ctest runs in parallel).
fs::path Simulate(const std::string& scenario, int frames) {
  const sim::Scenario s =
      sim::LoadScenario(std::string(NOVELTY_SOURCE_DIR) + "/share/scenarios/" + scenario + ".scn");
  const fs::path dir = fs::temp_directory_path() / ("novelty_stereo_depth_" + scenario);
  fs::remove_all(dir);
  sim::RunOptions o;
  o.out_dir = dir.string();
  o.frames = frames;
  o.progress = false;
  sim::RunScenario(s, o);
  return dir;
}

// The sensors issue's acceptance: ≥ 90 % of textured pixels within 3 % of the true depth.
void ExpectAccurateDepth(const std::string& scenario, size_t cameras) {
  const fs::path dir = Simulate(scenario, 2);
  RigFrameReader reader((dir / (scenario + ".rawlog")).string());
  int frames = 0;
  for (RigFrame f; reader.Next(f, nullptr);) {
    ASSERT_EQ(f.images.size(), cameras);
    std::vector<SweepView> others;
    for (size_t i = 1; i < f.images.size(); ++i)
      others.push_back({f.images[i], f.cameras[i], f.ref_from_camera[i]});
    StereoDepthOptions o;
    const StereoDepth depth = ComputeStereoDepth(f.images[0], f.cameras[0], others, o);
    const eval::DepthAccuracy a = eval::MeasureDepthAccuracy(
        depth.depth, sim::GroundTruthReader((dir / "groundtruth").string()).Depth(f.index), f.images[0],
        {});
    std::printf(
        "%s frame %d: %d textured pixels, %.1f %% within 3 %%, median error %.2f %%; "
        "%d near discontinuities, %.1f %% within\n",
        scenario.c_str(), f.index, a.textured_pixels, 100 * a.within_fraction,
        100 * a.median_relative_error, a.discontinuity_pixels,
        100 * a.discontinuity_within_fraction);
    // min_confidence (novelty-depth --min-confidence) drops exactly the pixels below it.
    o.min_confidence = 0.35f;
    const StereoDepth kept = ComputeStereoDepth(f.images[0], f.cameras[0], others, o);
    int dropped = 0, wrong = 0;
    for (int i = 0; i < int(kept.depth.total()); ++i) {
      const bool keep = depth.confidence.at<float>(i) >= o.min_confidence;
      dropped += keep ? 0 : 1;
      wrong += (keep ? kept.depth.at<float>(i) != depth.depth.at<float>(i)
                     : kept.depth.at<float>(i) != 0.0f) ? 1 : 0;
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(dropped, 0);
    EXPECT_GT(a.textured_pixels, 5000);
    EXPECT_GE(a.within_fraction, 0.90) << scenario << " frame " << f.index;
    ++frames;
  }
  EXPECT_EQ(frames, 2);
  EXPECT_EQ(reader.skipped(), 0);
}

TEST(StereoDepth, TrinocularSpecularSceneMeetsTheAccuracyBudget) {
  ExpectAccurateDepth("specular_scene", 3);
}

TEST(StereoDepth, StereoLambertianTableMeetsTheAccuracyBudget) {
  ExpectAccurateDepth("lambertian_table", 2);
}

}  // namespace
}  // namespace novelty::sensors
