#include "experiments/illumination_map_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

#include "mrpt_plugins/c_illumination_invariant_map.h"
#include "sensors/dataset/fixed_camera_folder.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_runner.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

// The four-lightings clip (tests/data/four_lightings.scn): four passes under four lightings, then
// a fifth, "test", where a red box was put down; simulated once for the suite.
class FourLightings : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("illumination_map_run_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    const sim::Scenario s =
        sim::LoadScenario(std::string(NOVELTY_SOURCE_DIR) + "/tests/data/four_lightings.scn");
    sim::RunOptions o;
    o.out_dir = (dir_ / "sim").string();
    o.progress = false;
    rawlog_ = sim::RunScenario(s, o).rawlog;
    truth_ = std::make_unique<sim::GroundTruthReader>((dir_ / "sim" / "groundtruth").string());
  }
  static void TearDownTestSuite() {
    truth_.reset();
    fs::remove_all(dir_);
  }
  static IlluminationMapRunOptions Options() {
    IlluminationMapRunOptions o;
    o.poses = "groundtruth";
    o.truth = truth_.get();
    return o;
  }
  static std::vector<std::string> Lightings() {
    return {rawlog_ + ":L1", rawlog_ + ":L2", rawlog_ + ":L3", rawlog_ + ":L4"};
  }

  static fs::path dir_;
  static std::string rawlog_;
  static std::unique_ptr<sim::GroundTruthReader> truth_;
};
fs::path FourLightings::dir_;
std::string FourLightings::rawlog_;
std::unique_ptr<sim::GroundTruthReader> FourLightings::truth_;

// Learnt from the four passes, saved, loaded and judging the fifth: the AUC >= 0.95 over
// the pass (6.4's target), one picture and one frames.csv row per frame.
TEST_F(FourLightings, LearnsSavesAndFindsTheBoxPutDown) {
  const std::string map = (dir_ / "room.illumination_invariant").string();
  const LearnIlluminationMapResult learnt = LearnIlluminationMap(Lightings(), "", map, Options());
  EXPECT_EQ(learnt.skipped, 0);
  int lighting_frames = 0;
  for (const auto& phase : truth_->Phases())
    if (phase.name != "test") lighting_frames += phase.last - phase.first + 1;
  EXPECT_EQ(learnt.frames, lighting_frames);
  ASSERT_TRUE(fs::is_regular_file(map));
  const fs::path out = dir_ / "judged";
  fs::create_directories(out);
  const JudgeIlluminationMapResult r =
      JudgeIlluminationMap(map, rawlog_ + ":test", out.string(), 5, Options());
  std::printf("%s\n", r.summary.c_str());
  EXPECT_EQ(r.frames, 10);
  EXPECT_EQ(r.skipped, 0);
  EXPECT_FALSE(r.ended_early);
  EXPECT_GE(r.auc, 0.95);
  // The threshold learnt from the four lightings alone (default 1 %) on the test pass's
  // unchanged pixels, with room for the box's own shadow and one short pass.
  EXPECT_LE(r.false_alarm_rate, 0.03);
  int pictures = 0;
  for (const auto& e : fs::directory_iterator(out / "novelty")) pictures += e.is_regular_file();
  EXPECT_EQ(pictures, 10);
  std::ifstream csv(out / "frames.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 11) << "a header and one row per frame";
  for (const char* file : {"findings.csv", "report.html", "panels/000058.png", "panels/000063.png"})
    EXPECT_TRUE(fs::exists(out / file)) << file << ": a panel every 5 frames from the first";
}

// A pass with nothing new under a lighting the map never saw: no ROC, but its false-alarm rate at
// the map's threshold, near the 1 % it was learnt for.
TEST_F(FourLightings, NothingNewGivesTheFalseAlarmRate) {
  const std::string map = (dir_ / "three.illumination_invariant").string();
  LearnIlluminationMap({rawlog_ + ":L1", rawlog_ + ":L2", rawlog_ + ":L3"}, "", map, Options());
  const fs::path out = dir_ / "unseen";
  fs::create_directories(out);
  const JudgeIlluminationMapResult r =
      JudgeIlluminationMap(map, rawlog_ + ":L4", out.string(), 0, Options());
  std::printf("%s\n", r.summary.c_str());
  EXPECT_EQ(r.auc, -1.0) << "no novelty in the pass: no ROC";
  ASSERT_TRUE(std::isfinite(r.novel_share));
  EXPECT_LE(r.novel_share, 0.03);
  EXPECT_EQ(r.novel_share, r.false_alarm_rate) << "with nothing new, every pixel above is one";
  std::ifstream csv(out / "frames.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find("novel_share"), std::string::npos) << header;
}

TEST_F(FourLightings, PassesAreRangesOrPhases) {
  const RawlogPass whole = ParseRawlogPass(rawlog_, nullptr);
  EXPECT_EQ(whole.path, rawlog_);
  EXPECT_EQ(whole.last, 0);
  const RawlogPass range = ParseRawlogPass(rawlog_ + ":3-7", nullptr);
  EXPECT_EQ(range.first, 3);
  EXPECT_EQ(range.last, 7);
  const RawlogPass phase = ParseRawlogPass(rawlog_ + ":L2", truth_.get());
  EXPECT_EQ(phase.first, truth_->Phases()[1].first);
  EXPECT_EQ(phase.last, truth_->Phases()[1].last);
  EXPECT_THROW(ParseRawlogPass(rawlog_ + ":7-3", nullptr), std::invalid_argument);
  EXPECT_THROW(ParseRawlogPass(rawlog_ + ":L2", nullptr), std::invalid_argument);
  EXPECT_THROW(ParseRawlogPass(rawlog_ + ":L9", truth_.get()), std::invalid_argument);
  EXPECT_TRUE(ParseRawlogPass(dir_.string(), nullptr).folder);  // a fixed camera's images
  EXPECT_FALSE(whole.folder);
  EXPECT_THROW(ParseRawlogPass((dir_ / "none").string(), nullptr), std::invalid_argument);
}

TEST_F(FourLightings, OneLightingOrNoFrameIsAnErrorAndSavesNothing) {
  const std::string map = (dir_ / "never.illumination_invariant").string();
  EXPECT_THROW(LearnIlluminationMap({rawlog_ + ":L1"}, "", map, Options()), std::invalid_argument);
  IlluminationMapRunOptions no_poses = Options();
  no_poses.poses = "rawlog";  // the simulator's rawlog holds no pose observations
  try {
    LearnIlluminationMap(Lightings(), "", map, no_poses);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("novelty-poses"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(map));
}

// frames.csv's rows: (coverage, novel_share) per frame.
std::vector<std::pair<double, double>> MitFrameShares(const fs::path& csv_path) {
  std::ifstream csv(csv_path);
  std::vector<std::pair<double, double>> rows;
  std::string line;
  std::getline(csv, line);  // frame,coverage,regions,matched,mean_delta,max_delta,auc,novel_share
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
    rows.emplace_back(std::stod(f.at(1)), std::stod(f.at(7)));
  }
  return rows;
}

// Real photos, no ground truth, no rawlog: the MIT box's lightings 1-8 (a fixed camera's folder)
// make the map and its threshold; a folder of lightings 9 and 10, unchanged, and 9 again with a
// green square put on the box is judged. Unchanged, the share above τ is the false-alarm rate
// (target 1 %, room for two frames); the square is mostly above it.
TEST(IlluminationMapOnPhotos, TheMitBoxUnderNewLightsAlarmsNearTheRateAndFindsASquare) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const fs::path box = fs::path(shared ? shared : "") / "mit-intrinsic" / "box";
  if (!shared || !fs::exists(box)) GTEST_SKIP() << "mit-intrinsic/ of the shared data is absent";
  const fs::path dir = fs::temp_directory_path() / ("mit_photos_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "judge");
  IlluminationMapRunOptions o;
  o.fixed_camera.pick.include = {"light0[1-8].png"};
  const std::string map = (dir / "box.illumination_invariant").string();
  const LearnIlluminationMapResult learnt = LearnIlluminationMap({box.string()}, "", map, o);
  std::printf("%s\n", learnt.map_summary.c_str());
  EXPECT_EQ(learnt.frames, 8);
  for (const char* name : {"light09.png", "light10.png", "mask.png"})
    fs::copy_file(box / name, dir / "judge" / name);
  cv::Mat mask = cv::imread((box / "mask.png").string(), cv::IMREAD_GRAYSCALE) > 0;
  const cv::Rect bounds = cv::boundingRect(mask);
  const int side = bounds.width / 4;
  const cv::Rect square(bounds.x + bounds.width / 2 - side / 2,
                        bounds.y + bounds.height / 2 - side / 2, side, side);
  cv::Mat patched = cv::imread((box / "light09.png").string(), cv::IMREAD_UNCHANGED);
  patched(square).setTo(cv::Scalar(60, 180, 100) * (patched.depth() == CV_16U ? 257 : 1));
  ASSERT_TRUE(cv::imwrite((dir / "judge" / "light11_square.png").string(), patched));
  o.fixed_camera.pick.include = {};
  const JudgeIlluminationMapResult r =
      JudgeIlluminationMap(map, (dir / "judge").string(), (dir / "out").string(), 0, o);
  std::printf("%s\n", r.summary.c_str());
  ASSERT_EQ(r.frames, 3);
  const auto rows = MitFrameShares(dir / "out" / "frames.csv");
  ASSERT_EQ(rows.size(), 3u);
  const double unchanged = (rows[0].second + rows[1].second) / 2;
  std::printf("unchanged: %.2f %% above tau; with the square: %.2f %%\n", 100 * unchanged,
              100 * rows[2].second);
  EXPECT_LE(unchanged, 0.02);
  const double covered = rows[2].first * double(mask.total());
  const double square_share = cv::countNonZero(mask(square)) / covered;
  std::printf("the square: %.2f %% of the covered pixels, %.2f %% more above tau than unpatched\n",
              100 * square_share, 100 * (rows[2].second - rows[0].second));
  EXPECT_GE(rows[2].second - rows[0].second, 0.5 * square_share)
      << "the square is " << 100 * square_share << " % of the covered pixels";
  fs::remove_all(dir);
}

// A lighting folder imported into a rawlog (novelty-import --layout fixed-camera) and learnt
// with ":each" is the folder learnt directly: the same lightings, the same threshold.
TEST(IlluminationMapOnPhotos, AnImportedLightingFolderLearntEachFrameIsTheFolder) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const fs::path box = fs::path(shared ? shared : "") / "mit-intrinsic" / "box";
  if (!shared || !fs::exists(box)) GTEST_SKIP() << "mit-intrinsic/ of the shared data is absent";
  const fs::path dir = fs::temp_directory_path() / ("mit_each_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "lamps");
  for (const char* name :
       {"light01.png", "light03.png", "light05.png", "light07.png", "mask.png"}) {
    cv::Mat img = cv::imread((box / name).string(), cv::IMREAD_UNCHANGED), half;
    cv::resize(img, half, {}, 0.5, 0.5,
               std::string(name) == "mask.png" ? cv::INTER_NEAREST : cv::INTER_AREA);
    ASSERT_TRUE(cv::imwrite((dir / "lamps" / name).string(), half));
  }
  const sensors::FixedCameraFolder folder((dir / "lamps").string());
  EXPECT_EQ(sensors::ImportFixedCameraFolder(folder, (dir / "lamps.rawlog").string()).frames, 4);
  IlluminationMapRunOptions o;
  const auto tau = [&](const std::string& lightings, const std::string& map) {
    const LearnIlluminationMapResult r = LearnIlluminationMap({lightings}, "", map, o);
    EXPECT_EQ(r.frames, 4) << lightings;
    mrpt_plugins::CIlluminationInvariantMap m;
    m.LoadFromFile(map);
    return m.map().decision_threshold();
  };
  const double from_folder = tau((dir / "lamps").string(), (dir / "a.map").string());
  const double from_rawlog = tau((dir / "lamps.rawlog:each").string(), (dir / "b.map").string());
  EXPECT_GT(from_folder, 0.0);
  EXPECT_NEAR(from_rawlog, from_folder, 1e-3 * from_folder)
      << "the rawlog's images are the folder's, stored as 8-bit PNGs";
  // Either map judges either form: the camera is where the folder puts it.
  const auto coverage = [&](const std::string& map, const std::string& input) {
    const fs::path out = dir / ("judged_" + std::to_string(getpid()));
    fs::remove_all(out);
    const JudgeIlluminationMapResult r = JudgeIlluminationMap(map, input, out.string(), 0, o);
    EXPECT_EQ(r.frames, 4) << map << " judging " << input;
    std::ifstream csv(out / "frames.csv");
    std::string line;
    std::getline(csv, line);
    std::getline(csv, line);
    return std::stod(line.substr(line.find(',') + 1));
  };
  const double same = coverage((dir / "a.map").string(), (dir / "lamps").string());
  EXPECT_GT(same, 0.3) << "the box covers about 40 % of the image";
  EXPECT_NEAR(coverage((dir / "b.map").string(), (dir / "lamps").string()), same, 1e-6);
  EXPECT_NEAR(coverage((dir / "a.map").string(), (dir / "lamps.rawlog").string()), same, 1e-6);
  EXPECT_TRUE(ParseRawlogPass((dir / "lamps.rawlog:2-3:each").string(), nullptr).each);
  EXPECT_EQ(ParseRawlogPass((dir / "lamps.rawlog:2-3:each").string(), nullptr).first, 2);
  EXPECT_FALSE(ParseRawlogPass((dir / "lamps.rawlog").string(), nullptr).each);
  EXPECT_THROW(ParseRawlogPass((dir / "lamps").string() + ":each", nullptr), std::invalid_argument);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::experiments
