#include "experiments/view_synthesis_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tests/sim/scenario/simulated_run.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

// glass_and_cup.scn's first 24 frames at 160×120 without its events.
std::string ShortClip() {
  return sim::GlassAndCupRoom(24, "camera 160 120 60");
}

// Every 4th frame a reference view, the 18 others synthesised. docs/appearance.md measures
// 33.6 dB over covered pixels at a mean coverage of 0.917 along the whole path: a short clip of it
// must reach 30 dB and 0.85 (the sky through the window has no depth).
TEST(ViewSynthesisRun, SynthesisesTheFramesBetweenTheViewsAlongThePath) {
  const fs::path dir = sim::SimulateIntoTempFolder(
      ShortClip(), "novelty_view_synthesis_" + std::to_string(getpid()));
  ViewSynthesisRunOptions o;
  o.rawlog = (dir / "glass_and_cup.rawlog").string();
  o.groundtruth = (dir / "groundtruth").string();
  int progressed = 0;
  o.progress = [&](int done, int) { progressed = done; };
  const fs::path out = dir / "synth";
  fs::create_directories(out);
  const ViewSynthesisRunResult r = RunViewSynthesis(o, out.string());
  std::printf("%d virtual views from %d, PSNR %.2f dB over covered pixels, coverage %.3f\n",
              r.virtual_views, r.reference_views, r.mean_psnr_db, r.mean_coverage);
  EXPECT_EQ(r.reference_views, 6);
  EXPECT_EQ(r.virtual_views, 18);
  EXPECT_EQ(progressed, 18);
  EXPECT_EQ(r.skipped, 0);
  EXPECT_GE(r.mean_psnr_db, 30.0);
  EXPECT_GE(r.mean_coverage, 0.85);
  EXPECT_TRUE(fs::is_regular_file(out / "000002.png"));
  EXPECT_FALSE(fs::exists(out / "000005.png")) << "frame 5 is a reference view";
  std::ifstream csv(out / "frames.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 19);
  o.every = 1;
  EXPECT_THROW(RunViewSynthesis(o, out.string()), std::invalid_argument);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::experiments
