#include "experiments/invariant_image_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "mrpt_plugins/illumination_invariant_map_options.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

fs::path FreshFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The MIT Intrinsic Images box (10 lightings, ground truth) with the map's defaults: the LMSE of
// docs/illumination.md's table for the box with luminance + chromaticity (0.01884), within 2 %,
// and every file the report links.
TEST(InvariantImageRun, TheMitBoxScoresItsLmseAndWritesEveryPicture) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const fs::path box = fs::path(shared ? shared : "") / "mit-intrinsic" / "box";
  if (!shared || !fs::exists(box)) GTEST_SKIP() << "mit-intrinsic/ of the shared data is absent";
  const fs::path out = FreshFolder("invariant_image_run_box");
  const mrpt_plugins::IlluminationInvariantMapConfig defaults;
  const InvariantImageRunResult r = RunInvariantImage(box.string(), defaults.map, out.string());
  std::printf("%s\n", r.summary.c_str());
  EXPECT_EQ(r.lightings, 10);
  ASSERT_TRUE(r.lmse);
  EXPECT_NEAR(r.lmse->lmse, 0.01884, 0.02 * 0.01884);
  EXPECT_GT(r.threshold, 0.0);
  for (const char* file : {"invariant.png", "invariant_display.png", "model.csv", "findings.csv",
                           "report.html", "panels/light01.png", "shapes/light10.png",
                           "information/light05.png", "illumination/light05.png"})
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  EXPECT_EQ(cv::imread((out / "invariant.png").string(), cv::IMREAD_UNCHANGED).size(),
            cv::imread((box / "light01.png").string(), cv::IMREAD_UNCHANGED).size());
  fs::remove_all(out);
}

// Three flat lightings of a 16 × 12 gradient; more asked for than there are is an error naming
// the option and the folder.
TEST(InvariantImageRun, MoreLightingsAskedThanGivenIsNamed) {
  const fs::path in = FreshFolder("invariant_image_run_in");
  for (int m = 0; m < 3; ++m) {
    cv::Mat image(12, 16, CV_8UC3);
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 16; ++x)
        image.at<cv::Vec3b>(y, x) = cv::Vec3b::all(uchar(40 + 5 * x + 20 * m));
    ASSERT_TRUE(cv::imwrite((in / ("l" + std::to_string(m) + ".png")).string(), image));
  }
  mrpt_plugins::IlluminationInvariantMapConfig config;
  config.map.invariant.min_lightings = 5;
  const fs::path out = FreshFolder("invariant_image_run_out");
  try {
    RunInvariantImage(in.string(), config.map, out.string());
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("min_lightings 5 exceeds the 3 lightings"), std::string::npos) << what;
    EXPECT_NE(what.find(in.string()), std::string::npos) << what;
  }
  fs::remove_all(in);
  fs::remove_all(out);
}

}  // namespace
}  // namespace novelty::experiments
