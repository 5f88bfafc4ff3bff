#include "experiments/surprise_experiment.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "mrpt_plugins/c_appearance_map.h"
#include "tests/maps/appearance/table_clip.h"
#include "tests/sim/scenario/simulated_run.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

// The appearance tests' clip (two arcs round a table, then a black cup is put down and the arc
// driven again: thesis 4.3's black cup, 102 frames at 160×120) with its phases named as
// glass_and_cup.scn names them, so that the finding of fig. 4.12 for the cup is judged.
class SurpriseRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string clip = std::string(appearance::kClip) +
                             "phase A 1 63 the room as learnt\n"
                             "phase C 64 102 the black cup added\n";
    dir_ = sim::SimulateIntoTempFolder(clip, "novelty_surprise_" + std::to_string(getpid()));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  SurpriseExperimentOptions Options() const {
    SurpriseExperimentOptions o;
    o.rawlog = (dir_ / "clip.rawlog").string();
    o.groundtruth = (dir_ / "groundtruth").string();
    return o;
  }
  static std::string Out(const std::string& name) {
    fs::create_directories(dir_ / name);
    return (dir_ / name).string();
  }
  static std::vector<std::string> Lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
  }
  static fs::path dir_;
};
fs::path SurpriseRun::dir_;

// The thesis's finding for the black cup: both surprise and differencing detect it (PAS > 0 dB),
// over the first run after it was put down; and everything the run writes is there.
TEST_F(SurpriseRun, TheBlackCupIsDetectedByBothAndTheRunWritesItsFiles) {
  SurpriseExperimentOptions o = Options();
  const std::string out = Out("main");
  o.map_out = out + "/map.appearance_map";
  int progress_calls = 0;
  o.progress = [&](int, int total) {
    ++progress_calls;
    EXPECT_EQ(total, 102);
  };
  const SurpriseExperimentResult r = RunSurpriseExperiment(o, out);
  EXPECT_EQ(r.frames, 102);
  EXPECT_EQ(r.skipped, 0);
  EXPECT_FALSE(r.ended_early);
  EXPECT_EQ(progress_calls, 102);
  int cup_rows = 0;
  for (const auto& row : r.rows) cup_rows += row.region == "cup";
  EXPECT_GT(cup_rows, 10);
  const std::vector<std::string> findings = Lines(fs::path(out) / "findings.csv");
  ASSERT_GE(findings.size(), 2u);
  EXPECT_NE(findings[1].find("black cup: detected by both"), std::string::npos) << findings[1];
  EXPECT_EQ(findings[1].substr(findings[1].rfind(',') + 1), "yes") << findings[1];
  EXPECT_GT(Lines(fs::path(out) / "metrics.csv").size(), 10u);
  for (const char* file : {"report.html", "map.3Dscene", "map.appearance_map"})
    EXPECT_TRUE(fs::exists(fs::path(out) / file)) << file;
  mrpt_plugins::CAppearanceMap loaded;
  loaded.LoadFromFile(o.map_out);
  EXPECT_EQ(loaded.map().store().size(), r.views);
  EXPECT_FALSE(fs::is_empty(fs::path(out) / "panels"));
  // frames.csv: how well each frame was predicted; the simulator's exact poses and depth cover
  // what the main job's findings are read over (0.926, README) less the clip's first frames.
  EXPECT_EQ(Lines(fs::path(out) / "frames.csv").size(), 103u);
  EXPECT_EQ(r.prediction.frames, 101) << "every frame but the first";
  EXPECT_GT(r.prediction.median_coverage, 0.9);
  // The verdict, from the surprise alone: the cup is put down at frame 64 and nothing changes
  // before, so every stretch of something new lies in 64-102, and there is one.
  ASSERT_FALSE(r.verdict.stretches.empty()) << r.verdict_sentence;
  for (const eval::NovelStretch& s : r.verdict.stretches) {
    EXPECT_GE(s.first, 64) << r.verdict_sentence;
    EXPECT_LE(s.last, 102);
  }
  EXPECT_EQ(r.verdict_sentence.rfind("Something new in frames ", 0), 0u) << r.verdict_sentence;
}

// Before the cup, the room as learnt: nothing new, said so; and a configuration without a
// differencing map runs too (panels of four tiles), unless ground truth asks to score against it.
TEST_F(SurpriseRun, NothingNewBeforeTheCupAndNoDifferencingMapNeeded) {
  const fs::path ini = dir_ / "appearance_only.ini";
  std::ofstream(ini) << "[map]\nCAppearanceMap_count = 1\n";
  SurpriseExperimentOptions o = Options();
  o.config = ini.string();
  EXPECT_THROW(RunSurpriseExperiment(o, Out("scored_alone")), std::invalid_argument);
  o.groundtruth.clear();
  o.pose_source = "odometry";
  o.max_frames = 63;
  o.panels_every = 62;
  const std::string out = Out("alone");
  const SurpriseExperimentResult r = RunSurpriseExperiment(o, out);
  EXPECT_EQ(r.frames, 63);
  EXPECT_TRUE(r.verdict.stretches.empty()) << r.verdict_sentence;
  EXPECT_EQ(r.verdict_sentence.rfind("Nothing new in frames ", 0), 0u) << r.verdict_sentence;
  EXPECT_NE(SurpriseRunSummary(r, out, "m").find(r.verdict_sentence), std::string::npos);
  const cv::Mat panel = cv::imread(out + "/panels/000062.png");
  ASSERT_FALSE(panel.empty());
  EXPECT_EQ(panel.cols, 4 * 160 + 3 * 4) << "camera, expected, surprise, uncertainty";
}

// Without ground truth: the same run from the rawlog's wheel odometry, nothing scored (a
// findings.csv of its header, no metrics rows), the prediction measured all the same.
TEST_F(SurpriseRun, RunsWithoutGroundTruth) {
  SurpriseExperimentOptions o = Options();
  o.groundtruth.clear();
  EXPECT_THROW(RunSurpriseExperiment(o, Out("refused")), std::invalid_argument)
      << "poses from a ground truth that is not there";
  o.pose_source = "odometry";
  const std::string out = Out("no_truth");
  const SurpriseExperimentResult r = RunSurpriseExperiment(o, out);
  EXPECT_EQ(r.frames, 102);
  EXPECT_TRUE(r.rows.empty());
  EXPECT_EQ(Lines(fs::path(out) / "findings.csv").size(), 1u);
  EXPECT_EQ(Lines(fs::path(out) / "frames.csv").size(), 103u);
  EXPECT_GT(r.prediction.frames, 90);
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes.back().find("No ground truth"), std::string::npos);
}

// learn_until: after frame 40 the maps judge without learning, so they end with the views a run
// stopped at frame 40 has, and the cup put down at 64 stays new: its PAS at the end of the run
// is higher than with learning, where the map has taken it in.
TEST_F(SurpriseRun, MapsLearnUntilTheFrameAskedAndJudgeTheRestAsTheyWere) {
  SurpriseExperimentOptions o = Options();
  o.max_frames = 40;
  const SurpriseExperimentResult first = RunSurpriseExperiment(o, Out("first40"));
  o.max_frames.reset();
  o.learn_until = 40;
  const SurpriseExperimentResult frozen = RunSurpriseExperiment(o, Out("frozen"));
  EXPECT_EQ(frozen.frames, 102);
  EXPECT_EQ(frozen.views, first.views);
  o.learn_until = 0;
  const SurpriseExperimentResult learning = RunSurpriseExperiment(o, Out("learning"));
  EXPECT_GT(learning.views, frozen.views);
  const auto last_cup = [](const SurpriseExperimentResult& r) {
    return eval::MeanOver(r.rows, "cup", 95, 102).pas_surprise;
  };
  EXPECT_GT(last_cup(frozen), last_cup(learning));
  o.learn_until = -1;
  EXPECT_THROW(RunSurpriseExperiment(o, Out("bad")), std::invalid_argument);
}

// fig. 4.13: maps with sparser reference views run side by side and hold fewer views.
TEST_F(SurpriseRun, SparserMapsRunSideBySide) {
  SurpriseExperimentOptions o = Options();
  o.compare_views = ParseViewFactors("2");
  o.max_frames = 70;
  const std::string out = Out("sparser");
  const SurpriseExperimentResult r = RunSurpriseExperiment(o, out);
  EXPECT_EQ(r.frames, 70);
  std::ifstream in(fs::path(out) / "report.html");
  const std::string report{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(report.find("R2"), std::string::npos);
}

TEST_F(SurpriseRun, BadOptionsAreErrors) {
  EXPECT_THROW(ParseViewFactors("0.5"), std::invalid_argument);
  EXPECT_THROW(ParseViewFactors("2,x"), std::invalid_argument);
  SurpriseExperimentOptions o = Options();
  o.view_reduction = 0.5;
  EXPECT_THROW(RunSurpriseExperiment(o, Out("bad")), std::invalid_argument);
  o = Options();
  o.objects_in = o.rawlog;  // no CObjectDatabaseMap in the default maps
  EXPECT_THROW(RunSurpriseExperiment(o, Out("bad")), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::experiments
