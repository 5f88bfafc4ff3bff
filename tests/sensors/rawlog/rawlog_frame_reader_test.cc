#include "sensors/rawlog/rawlog_frame_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "core/frame_stem.h"
#include "sim/output/ground_truth_reader.h"
#include "tests/sensors/rawlog/tiny_run.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

TEST(RawlogFrameReader, ReadsEveryRgbdFrameWithDepthAndIntrinsics) {
  const fs::path dir = SimulateTinyRun("complete");
  RawlogFrameReader reader((dir / "tiny.rawlog").string());
  const sim::GroundTruthReader truth_reader((dir / "groundtruth").string());
  int n = 0;
  for (core::Frame f; reader.Next(f);) {
    ++n;
    EXPECT_EQ(f.index, n);
    EXPECT_EQ(f.label, "RGBD");
    EXPECT_EQ(f.rgb.type(), CV_8UC3);
    EXPECT_EQ(f.camera.width, 64);
    EXPECT_NEAR(f.camera.fx, 32.0 / std::tan(M_PI / 6), 1e-6);
    // Depth equals the ground truth's (metres × 5000 in a PNG) to its 0.2 mm step.
    const std::string name = core::FrameStem(n) + ".png";
    EXPECT_LT(cv::norm(f.depth, truth_reader.Depth(n), cv::NORM_INF), 0.00021);
    // The colour image is the one stored beside the rawlog.
    const cv::Mat stored = cv::imread((dir / "tiny_Images" / name).string());
    cv::Mat stored_rgb;
    cv::cvtColor(stored, stored_rgb, cv::COLOR_BGR2RGB);
    EXPECT_EQ(cv::norm(f.rgb, stored_rgb, cv::NORM_INF), 0.0);
    EXPECT_TRUE(truth_reader.CameraPoses().count(n));
  }
  EXPECT_EQ(n, 6);
  EXPECT_EQ(reader.skipped(), 0);
}

TEST(RawlogFrameReader, MissingImagesAreSkippedAndCountedNotFatal) {
  const fs::path dir = SimulateTinyRun("missing_image");
  fs::remove(dir / "tiny_Images" / "000003.png");
  RawlogFrameReader reader((dir / "tiny.rawlog").string());
  int n = 0;
  for (core::Frame f; reader.Next(f);) ++n;
  EXPECT_EQ(n, 5);
  ASSERT_EQ(reader.skipped(), 1);
  EXPECT_NE(reader.skip_reasons()[0].find("RGB-D frame 3"), std::string::npos)
      << reader.skip_reasons()[0];
}

TEST(RawlogFrameReader, AMissingImageFolderStopsTheReadNamingIt) {
  const fs::path dir = SimulateTinyRun("missing_folder");
  fs::remove_all(dir / "tiny_Images");
  RawlogFrameReader reader((dir / "tiny.rawlog").string());
  core::Frame f;
  try {
    reader.Next(f);
    ADD_FAILURE() << "read a frame without its images";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("tiny_Images is missing"), std::string::npos) << e.what();
  }
  EXPECT_EQ(reader.skipped(), 0);
}

TEST(RawlogFrameReader, BadFilesAreNamed) {
  EXPECT_THROW(RawlogFrameReader("/nonexistent/x.rawlog"), std::runtime_error);
}

}  // namespace
}  // namespace novelty::sensors
