#include "experiments/soak_experiment.h"

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

// glass_and_cup.scn cut to 12 frames at 80×60 without its events, as the bad-input cases use it.
std::string TinyClip() {
  return sim::GlassAndCupRoom(12, "camera 80 60 60");
}

class Soak : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = sim::SimulateIntoTempFolder(TinyClip(), "novelty_soak_" + std::to_string(getpid()));
  }
  void TearDown() override { fs::remove_all(dir_); }
  SoakOptions Options() const {
    SoakOptions o;
    o.rawlog = (dir_ / "glass_and_cup.rawlog").string();
    o.groundtruth = (dir_ / "groundtruth").string();
    o.frames = 30;
    o.sample_every = 10;
    return o;
  }
  fs::path dir_;
};

// 30 frames of a 12-frame clip: three loops (12 + 12 + 6), a sample every 10 frames. The route
// repeats, so the map takes no view after the first loop: the plateau starts by the sample at 20.
TEST_F(Soak, LoopsTheClipSamplesAndFindsThePlateau) {
  int last_progress = 0;
  SoakOptions o = Options();
  o.progress = [&](int played, int total) {
    EXPECT_EQ(total, 30);
    EXPECT_EQ(played, last_progress + 1);
    last_progress = played;
  };
  const SoakResult r = RunSoak(o);
  EXPECT_EQ(r.played, 30);
  EXPECT_EQ(r.loops, 3);
  ASSERT_EQ(r.samples.size(), 3u);
  EXPECT_EQ(r.samples[0].frame, 10);
  EXPECT_EQ(r.samples[2].frame, 30);
  EXPECT_GT(r.samples[0].views, 0);
  EXPECT_EQ(r.samples[1].views, r.samples[2].views);
  EXPECT_TRUE(r.plateau.reached);
  EXPECT_LE(r.plateau.frame, 20);
  EXPECT_EQ(last_progress, 30);

  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  WriteSoakReport(r, out.string());
  std::ifstream csv(out / "soak.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 4);  // header and three samples
  EXPECT_TRUE(fs::exists(out / "findings.csv"));
  EXPECT_TRUE(fs::exists(out / "soak.html"));
}

TEST_F(Soak, OptionsOutOfRangeAndARawlogWithoutFramesAreErrors) {
  SoakOptions o = Options();
  o.frames = 0;
  EXPECT_THROW(RunSoak(o), std::invalid_argument);
  o = Options();
  o.sample_every = 0;
  EXPECT_THROW(RunSoak(o), std::invalid_argument);
  o = Options();
  const fs::path empty = dir_ / "empty.rawlog";
  std::ofstream(empty).close();
  o.rawlog = empty.string();
  EXPECT_THROW(RunSoak(o), std::runtime_error);
}

}  // namespace
}  // namespace novelty::experiments
