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

namespace novelty::sensors {
namespace {

// A real sequence without its poses file (the first 8 keyframes of TUM fr3/cabinet, linked into a
// folder of rgb.txt and depth.txt only): the importer places the frames by visual odometry
// ("POSE_VO"), from the origin. With the poses file and ImportPoses::kVisual it starts at the
// first true pose, and its positions stay within 5 cm RMS of motion capture over 1.2 m of path —
// the appearance map's depth tolerance.
TEST(RgbdImporter, ASequenceWithoutPosesIsPlacedByVisualOdometry) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const fs::path data = fs::path(shared ? shared : "") / "tum-fr3-cabinet";
  if (!shared || !fs::exists(data)) GTEST_SKIP() << "tum-fr3-cabinet/ of the shared data is absent";
  const fs::path dir =
      fs::temp_directory_path() / ("novelty_vo_import_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "seq");
  fs::create_directory_symlink(data / "rgb", dir / "seq" / "rgb");
  fs::create_directory_symlink(data / "depth", dir / "seq" / "depth");
  for (const char* list : {"rgb.txt", "depth.txt"}) {
    std::ifstream in(data / list);
    std::ofstream out(dir / "seq" / list);
    int kept = 0;
    for (std::string line; std::getline(in, line) && kept < 8;) {
      out << line << '\n';
      kept += line[0] != '#';
    }
  }
  RgbdSequenceOptions so;
  so.camera_name = "fr3";
  const RgbdSequence poseless = ReadRgbdSequence((dir / "seq").string(), so);
  ASSERT_EQ(poseless.frames.size(), 8u);
  const RgbdImportResult r = ImportRgbdSequence(poseless, (dir / "vo.rawlog").string());
  EXPECT_TRUE(r.visual_odometry);
  EXPECT_EQ(r.posed, 8);
  EXPECT_EQ(r.odometry_lost, 0);
  EXPECT_TRUE(std::isnan(r.odometry_rms_error)) << "nothing to compare with";
  RawlogFrameReader reader((dir / "vo.rawlog").string());
  core::Frame f;
  ASSERT_TRUE(reader.Next(f));
  EXPECT_EQ(f.pose_source, "POSE_VO");
  ASSERT_TRUE(f.T_world_cam);
  EXPECT_LT((f.T_world_cam->matrix() - Eigen::Matrix4d::Identity()).norm(), 1e-6);

  RgbdSequence posed = ReadRgbdSequence(data.string());
  RgbdImportOptions o;
  o.last = 8;
  o.poses = ImportPoses::kVisual;
  const RgbdImportResult v = ImportRgbdSequence(posed, (dir / "vo2.rawlog").string(), o);
  std::printf("visual odometry over 8 keyframes: RMS %.1f cm from motion capture\n",
              100 * v.odometry_rms_error);
  EXPECT_EQ(v.odometry_lost, 0);
  EXPECT_LT(v.odometry_rms_error, 0.05);
  o.poses = ImportPoses::kAuto;
  EXPECT_FALSE(ImportRgbdSequence(posed, (dir / "auto.rawlog").string(), o).visual_odometry)
      << "the dataset's poses, where it has them";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sensors
