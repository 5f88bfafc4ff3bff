// View synthesis on data: real RGB-D frames (ICL-NUIM, ../shared/data) and the simulator's
// glass-and-cup scenario with frames held out of the reference set.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "eval/psnr.h"
#include "maps/views/depth_mesh_warper.h"
#include "maps/views/view_blender.h"
#include "maps/views/view_selection.h"
#include "maps/views/view_synthesis.h"
#include "sensors/dataset/rgbd_folder_reader.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/simulate_frames.h"

namespace novelty::views {
namespace {

// What novelty-synth runs, with its defaults: PSNR over the covered pixels, and the coverage.
SynthesisResult Synthesise(const std::vector<ReferenceView>& refs, const core::PinholeCamera& cam,
                           const Eigen::Isometry3d& pose, const SynthesisOptions& o = {}) {
  std::vector<const ReferenceView*> ptrs;
  for (const ReferenceView& r : refs) ptrs.push_back(&r);
  return SynthesiseView(ptrs, cam, pose, o);
}

class IclNuim : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::string(NOVELTY_SOURCE_DIR) + "/../shared/data/icl-nuim-5";
    if (!std::filesystem::exists(dir_ + "/pose.txt")) {
      GTEST_SKIP() << dir_ << " is absent (shared test data)";
    }
    cam_.width = 640;
    cam_.height = 480;
    cam_.fx = 481.2;
    cam_.fy = -480.0;
    cam_.cx = 319.5;
    cam_.cy = 239.5;
    reader_ = std::make_unique<sensors::RgbdFolderReader>(dir_, cam_, 5000.0);
    target_ = reader_->Read(2);
  }
  // Frame 2's view synthesised from `sources`; PSNR against the real frame 2.
  std::pair<double, double> PsnrAndCoverage(const std::vector<int>& sources,
                                            const SynthesisOptions& o = {}) {
    std::vector<ReferenceView> refs;
    for (int s : sources) refs.push_back(views::ReferenceViewOf(reader_->Read(s)));
    const SynthesisResult r = Synthesise(refs, cam_, *target_.T_world_cam, o);
    const double psnr = eval::Psnr(r.rgb, target_.rgb, r.valid);
    std::printf("frame 2 from %zu source(s), first %d: PSNR %.2f dB at coverage %.4f\n",
                sources.size(), sources[0], psnr, r.coverage);
    return {psnr, r.coverage};
  }
  std::string dir_;
  core::PinholeCamera cam_;
  std::unique_ptr<sensors::RgbdFolderReader> reader_;
  core::Frame target_;
};

// Independent figures (each source's depth reprojected into frame 2, then a 5×5 closing): frame 1
// covers 0.273 of frame 2, frame 4 0.207, frame 5 0.142, their union 0.287; frame 4 alone
// reprojects at 35.9 dB (the shared data's README). With the program's defaults every pixel a
// view covers is covered. The target of 33 dB from 1, 4, 5 at that coverage is not met: the
// defaults (the thesis's average) give 31.4 dB, and no blend weighting reaches it — frame 5 is
// 3 dB worse than frames 1 and 4 where they overlap, and neither view angle, resolution nor
// depth consensus tells it apart (1 and 4 alone give 33.3 dB at 0.280).
TEST_F(IclNuim, DefaultsKeepCoverage) {
  const auto [psnr3, coverage3] = PsnrAndCoverage({1, 4, 5});
  EXPECT_GE(coverage3, 0.28);
  EXPECT_GT(psnr3, 30.0);
  const auto [psnr4, coverage4] = PsnrAndCoverage({4});
  EXPECT_GT(psnr4, 35.0);
  EXPECT_GE(coverage4, 0.20);
  const auto [psnr5, coverage5] = PsnrAndCoverage({5});
  EXPECT_GE(coverage5, 0.13);
  (void)psnr5;
}

// Weighting views by their angle to the surface, relative to each pixel's best view, ranks them
// without changing what is covered, and here gains over the plain average.
TEST_F(IclNuim, AngleWeightingKeepsCoverageAndBeatsThePlainAverage) {
  SynthesisOptions weighted;
  weighted.blend.angle_power = 10.0;
  const auto [psnr, coverage] = PsnrAndCoverage({1, 4, 5}, weighted);
  SynthesisOptions thesis;
  thesis.blend = BlendOptions::ThesisAverage();
  const auto [psnr_thesis, coverage_thesis] = PsnrAndCoverage({1, 4, 5}, thesis);
  EXPECT_NEAR(coverage, coverage_thesis, 0.002) << "weights must not change what is covered";
  EXPECT_GT(psnr, psnr_thesis);
}

// The weighting that made the old defaults: cos φ^10000 taken absolutely dropped every pixel no
// view saw within a few degrees (coverage 0.034 from frame 4). Relative to the best view, even
// that power keeps every covered pixel.
TEST_F(IclNuim, SharpAngleWeightingKeepsCoverage) {
  SynthesisOptions sharp;
  sharp.blend.angle_power = 10000.0;
  sharp.blend.depth_tolerance = 0.03;
  const auto [psnr4, coverage4] = PsnrAndCoverage({4}, sharp);
  EXPECT_GE(coverage4, 0.20);
  const auto [psnr, coverage] = PsnrAndCoverage({1, 4, 5}, sharp);
  EXPECT_GE(coverage, 0.28);
  (void)psnr4;
  (void)psnr;
}

// Reference views every 4th frame of the glass-and-cup clip; the frames in between are held out
// and synthesised from the views that view selection picks.
TEST(ViewSynthesisOnSimulatedData, HeldOutFramesMatchTheRenderedOnes) {
  const sim::Scenario s =
      sim::LoadScenario(std::string(NOVELTY_SOURCE_DIR) + "/share/scenarios/glass_and_cup.scn");
  std::vector<ReferenceView> refs;
  std::vector<std::pair<Eigen::Isometry3d, cv::Mat>> held_out;
  for (const sim::SimulatedFrame& f : sim::SimulateFrames(s, 48)) {
    const int k = f.index - 1;
    if (k % 4 == 0) {
      ReferenceView v;
      v.camera = s.camera;
      v.T_world_cam = f.T_world_cam;
      v.depth = f.depth;
      v.planes["rgb"] = f.rgb;
      refs.push_back(v);
    } else if (k % 4 == 2) {
      held_out.emplace_back(f.T_world_cam, f.rgb);
    }
  }
  std::vector<Eigen::Isometry3d> poses;
  for (const ReferenceView& r : refs) poses.push_back(r.T_world_cam);
  double worst = 1e9;
  const SynthesisOptions o;
  const ViewSelectionOptions selection;
  DepthMeshWarper warper(o.warp, WarpOutputsFor(o.blend));
  for (const auto& [pose, rgb] : held_out) {
    const SynthesisResult r = SynthesiseSelected(warper, refs, poses, s.camera, pose, selection, o);
    EXPECT_GT(r.coverage, 0.85);  // the sky through the window has no depth
    worst = std::min(worst, eval::Psnr(r.rgb, rgb, r.valid));
  }
  EXPECT_GE(worst, 30.0) << "worst held-out PSNR over covered pixels";
  // Facing away from every view: none is picked, nothing is valid.
  Eigen::Isometry3d away = held_out.front().first;
  away.linear() = away.linear() * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()).matrix();
  const SynthesisResult none =
      SynthesiseSelected(warper, refs, poses, s.camera, away, selection, o);
  EXPECT_EQ(none.coverage, 0.0);
  EXPECT_EQ(cv::countNonZero(none.valid), 0);
  EXPECT_EQ(none.rgb.size(), held_out.front().second.size());
  RecordProperty("worst_psnr_db", std::to_string(worst));
  std::printf("worst held-out PSNR: %.2f dB over %zu frames\n", worst, held_out.size());
}

}  // namespace
}  // namespace novelty::views
