#include "sensors/dataset/rgbd_importer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "sensors/rawlog/rawlog_frame_reader.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

// A TUM-layout folder of three 64 × 48 frames with noise images, depth in 1/5000 m steps and a
// pose each, given its intrinsics.
struct TinyTum {
  fs::path dir;
  RgbdSequence sequence;
  std::vector<cv::Mat> rgb, depth16;
  TinyTum() {
    dir = fs::temp_directory_path() / ("novelty_rgbd_importer_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "rgb");
    fs::create_directories(dir / "depth");
    std::ofstream rgb_txt(dir / "rgb.txt"), depth_txt(dir / "depth.txt"),
        truth(dir / "groundtruth.txt");
    cv::RNG rng(7);
    for (int k = 0; k < 3; ++k) {
      cv::Mat c(48, 64, CV_8UC3), d(48, 64, CV_16UC1);
      rng.fill(c, cv::RNG::UNIFORM, 0, 256);
      rng.fill(d, cv::RNG::UNIFORM, 2500, 20000);  // 0.5–4 m
      d(cv::Rect(0, 0, 8, 8)).setTo(0);            // unknown
      cv::Mat bgr;
      cv::cvtColor(c, bgr, cv::COLOR_RGB2BGR);
      cv::imwrite((dir / "rgb" / (std::to_string(k) + ".png")).string(), bgr);
      cv::imwrite((dir / "depth" / (std::to_string(k) + ".png")).string(), d);
      rgb.push_back(c), depth16.push_back(d);
      const double t = 200.0 + k * 0.5;
      rgb_txt << cv::format("%.4f rgb/%d.png\n", t, k);
      depth_txt << cv::format("%.4f depth/%d.png\n", t, k);
      truth << cv::format("%.4f %.3f 0.2 1.1 0.1830127 0.1830127 0.6830127 0.6830127\n", t,
                          0.1 * k);
    }
    rgb_txt.close(), depth_txt.close(), truth.close();
    RgbdSequenceOptions o;
    o.camera = core::PinholeCamera::FromFov(64, 48, 1.0);
    o.camera_name = "fr1";  // the intrinsics given win; the name only stops the guess
    sequence = ReadRgbdSequence(dir.string(), o);
  }
  ~TinyTum() { fs::remove_all(dir); }
};

// Imported and read back as the maps read rawlogs: colour exact, depth exact (its 1/5000 m steps
// are the rawlog's 0.2 mm), unknown depth 0, the camera pose exact through the mounting.
TEST(RgbdImporter, FramesAndPosesRoundTripThroughTheRawlog) {
  const TinyTum t;
  const std::string rawlog = (t.dir / "out" / "tiny.rawlog").string();
  fs::create_directories(t.dir / "out");
  int progressed = 0;
  RgbdImportOptions o;
  o.progress = [&](int done, int total) {
    EXPECT_EQ(total, 3);
    progressed = done;
  };
  const RgbdImportResult r = ImportRgbdSequence(t.sequence, rawlog, o);
  EXPECT_EQ(r.frames, 3);
  EXPECT_EQ(r.posed, 3);
  EXPECT_EQ(progressed, 3);
  EXPECT_NEAR(r.depth_coverage, 1.0 - 64.0 / (64 * 48), 1e-9);
  RawlogFrameReader reader(rawlog);
  core::Frame f;
  for (int k = 0; k < 3; ++k) {
    ASSERT_TRUE(reader.Next(f)) << k;
    EXPECT_EQ(cv::norm(f.rgb, t.rgb[std::size_t(k)], cv::NORM_INF), 0.0);
    cv::Mat expected;
    t.depth16[std::size_t(k)].convertTo(expected, CV_32F, 1.0 / 5000);
    EXPECT_LT(cv::norm(f.depth, expected, cv::NORM_INF), 1e-6);
    ASSERT_TRUE(f.T_world_cam);
    EXPECT_EQ(f.pose_source, "POSE_DATASET");
    EXPECT_LT(
        (f.T_world_cam->matrix() - t.sequence.frames[std::size_t(k)].T_world_cam->matrix()).norm(),
        1e-9);
    EXPECT_NEAR(f.time, 200.0 + 0.5 * k, 1e-3);
  }
  EXPECT_FALSE(reader.Next(f));
}

// A depth image of another size is named before anything is decoded, and no rawlog appears.
TEST(RgbdImporter, AFrameOfAnotherSizeIsNamedAndNothingIsPublished) {
  const TinyTum t;
  cv::imwrite((t.dir / "depth" / "2.png").string(), cv::Mat(96, 128, CV_16UC1, cv::Scalar(5000)));
  const std::string rawlog = (t.dir / "bad.rawlog").string();
  try {
    ImportRgbdSequence(t.sequence, rawlog);
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("depth/2.png: 128x96, the sequence's images are 64x48"), std::string::npos)
        << what;
  }
  EXPECT_FALSE(fs::exists(rawlog));
  cv::imwrite((t.dir / "depth" / "2.png").string(), cv::Mat(48, 64, CV_8UC1, cv::Scalar(50)));
  EXPECT_THROW(ImportRgbdSequence(t.sequence, rawlog), std::runtime_error) << "8-bit depth";
  RgbdImportOptions o;
  o.first = 4;
  EXPECT_THROW(ImportRgbdSequence(t.sequence, rawlog, o), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sensors
