#include "experiments/object_finder_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "experiments/object_photo_learning.h"
#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rawlog_output.h"
#include "tests/maps/objects/blob_photo.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> Lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Two photographed objects (random-disc photos); scenes of 320 × 240 with the first pasted in
// through a known homography, and one with neither.
class ObjectFinderRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("object_finder_run_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "frames");
    const cv::Mat tin = objects::BlobPhoto({160, 120}, 21),
                  jar = objects::BlobPhoto({160, 120}, 22);
    cv::imwrite((dir_ / "tin.png").string(), tin);
    cv::imwrite((dir_ / "jar.png").string(), jar);
    ObjectPhotoLearningOptions learn;
    learn.objects = {ParseObjectPhotoSpec((dir_ / "tin.png").string()),
                     ParseObjectPhotoSpec((dir_ / "jar.png").string())};
    mrpt_plugins::CObjectDatabaseMap map;
    LearnObjectPhotos(map, learn);
    map.SaveToFile((dir_ / "db.object_database").string());
    h_ = (cv::Mat_<double>(3, 3) << 0.9, -0.15, 90, 0.12, 0.85, 60, 2e-4, -1e-4, 1);
    with_tin_ = objects::PastePhoto(objects::BlobPhoto({320, 240}, 23), tin, h_);
    cv::imwrite((dir_ / "frames" / "1.png").string(), with_tin_);
    cv::imwrite((dir_ / "frames" / "2.png").string(), objects::BlobPhoto({320, 240}, 24));
    o_.database = (dir_ / "db.object_database").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  cv::Mat h_, with_tin_;
  ObjectFinderRunOptions o_;
};

TEST_F(ObjectFinderRun, ListsTheObjectInTheFrameThatShowsIt) {
  o_.input = (dir_ / "frames").string();
  const fs::path out = dir_ / "out";
  const ObjectFinderRunResult r = RunObjectFinder(o_, out.string());
  EXPECT_EQ(r.frames, 2);
  ASSERT_EQ(r.objects.count("tin"), 1u);
  EXPECT_EQ(r.objects.at("tin").frames, 1);
  EXPECT_EQ(r.objects.at("tin").verified, 1);
  EXPECT_EQ(r.objects.at("tin").first, 1);
  EXPECT_EQ(r.objects.count("jar"), 0u);
  const std::vector<std::string> rows = Lines(out / "found.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].rfind("1,1.png,tin,yes,", 0), 0u) << rows[1];
  // The box column: where h puts the photo's corners.
  std::vector<cv::Point2f> corners = {{0, 0}, {159, 0}, {159, 119}, {0, 119}}, truth;
  cv::perspectiveTransform(corners, truth, h_);
  const cv::Rect b = cv::boundingRect(truth);
  std::stringstream row(rows[1]);
  std::vector<std::string> f;
  for (std::string cell; std::getline(row, cell, ',');) f.push_back(cell);
  ASSERT_GE(f.size(), 11u);
  EXPECT_NEAR(std::stoi(f[7]), b.x, 2);
  EXPECT_NEAR(std::stoi(f[8]), b.y, 2);
  EXPECT_NEAR(std::stoi(f[9]), b.width, 3);
  EXPECT_NEAR(std::stoi(f[10]), b.height, 3);
  EXPECT_TRUE(fs::exists(out / "panels" / "1.png"));
  EXPECT_FALSE(fs::exists(out / "panels" / "2.png")) << "nothing found there";
  EXPECT_EQ(Lines(out / "objects.csv").size(), 2u);
}

// From a rawlog of RGB-D frames with a pose: the object's place in the world.
TEST_F(ObjectFinderRun, ARawlogGivesThePlaceInTheWorld) {
  core::PinholeCamera camera;  // 320 × 240, f = 400
  const cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(0.8f));
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  world_from_camera.translation() = Eigen::Vector3d(1.0, 2.0, 0.5);
  cv::Mat rgb;
  cv::cvtColor(with_tin_, rgb, cv::COLOR_GRAY2RGB);
  {
    sensors::RawlogOutput log((dir_ / "clip.rawlog").string());
    log.Write(sensors::MakeCameraPoseObservation(1.0, world_from_camera,
                                                 Eigen::Isometry3d::Identity(), "POSE", 0, 0));
    log.WriteRgbd(1.0, rgb, depth, camera, Eigen::Isometry3d::Identity(), "000001");
    log.Close();
  }
  o_.input = (dir_ / "clip.rawlog").string();
  const ObjectFinderRunResult r = RunObjectFinder(o_, (dir_ / "out").string());
  ASSERT_EQ(r.frames, 1);
  ASSERT_EQ(r.objects.count("tin"), 1u);
  const std::vector<std::string> rows = Lines(dir_ / "out" / "found.csv");
  ASSERT_EQ(rows.size(), 2u);
  std::stringstream row(rows[1]);
  std::vector<std::string> f;
  for (std::string cell; std::getline(row, cell, ',');) f.push_back(cell);
  ASSERT_EQ(f.size(), 17u) << rows[1];
  // Camera z is the depth; the world place is the camera's plus (1, 2, 0.5).
  EXPECT_NEAR(std::stod(f[13]), 0.8, 1e-3);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(std::stod(f[14 + a]), std::stod(f[11 + a]) + world_from_camera.translation()[a],
                2e-4);
  // x, y inside the pasted photo's back-projection at 0.8 m.
  std::vector<cv::Point2f> corners = {{0, 0}, {159, 0}, {159, 119}, {0, 119}}, truth;
  cv::perspectiveTransform(corners, truth, h_);
  const cv::Rect2f b = cv::boundingRect(truth);
  EXPECT_GT(std::stod(f[11]), camera.Unproject(b.x, b.y, 0.8).x());
  EXPECT_LT(std::stod(f[11]), camera.Unproject(b.x + b.width, b.y, 0.8).x());
}

// An image that cannot be read is skipped and counted; the others are searched.
TEST_F(ObjectFinderRun, AnUnreadableImageIsSkippedAndCounted) {
  std::ofstream((dir_ / "frames" / "0.png").string()) << "not an image";
  o_.input = (dir_ / "frames").string();
  const ObjectFinderRunResult r = RunObjectFinder(o_, (dir_ / "out").string());
  EXPECT_EQ(r.frames, 2);
  ASSERT_EQ(r.skipped, 1);
  EXPECT_NE(r.skip_reasons[0].find("0.png"), std::string::npos) << r.skip_reasons[0];
  EXPECT_EQ(r.objects.count("tin"), 1u);
}

// A rawlog without camera frames is an error; one cut short keeps what was read before the cut.
TEST_F(ObjectFinderRun, ARawlogWithoutFramesIsAnErrorACutOneEndsEarly) {
  core::PinholeCamera camera;
  cv::Mat rgb;
  cv::cvtColor(with_tin_, rgb, cv::COLOR_GRAY2RGB);
  {
    sensors::RawlogOutput poses((dir_ / "poses.rawlog").string());
    poses.Write(sensors::MakeCameraPoseObservation(1.0, Eigen::Isometry3d::Identity(),
                                                   Eigen::Isometry3d::Identity(), "POSE", 0, 0));
    poses.Close();
    sensors::RawlogOutput two((dir_ / "two.rawlog").string());
    for (int k = 1; k <= 2; ++k)
      two.WriteRgbd(k, rgb, cv::Mat(240, 320, CV_32FC1, cv::Scalar(1.0f)), camera,
                    Eigen::Isometry3d::Identity(), "00000" + std::to_string(k));
    two.Close();
  }
  o_.input = (dir_ / "poses.rawlog").string();
  try {
    RunObjectFinder(o_, (dir_ / "out").string());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no frame could be used (no camera frame in it)"),
              std::string::npos)
        << e.what();
  }
  // The second frame cut in half (its images stay beside the rawlog).
  const auto size = fs::file_size(dir_ / "two.rawlog");
  fs::copy(dir_ / "two_Images", dir_ / "cut_Images", fs::copy_options::recursive);
  {
    std::ifstream in(dir_ / "two.rawlog", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream((dir_ / "cut.rawlog").string(), std::ios::binary)
        << bytes.substr(0, std::size_t(size * 3 / 4));
  }
  o_.input = (dir_ / "cut.rawlog").string();
  const ObjectFinderRunResult r = RunObjectFinder(o_, (dir_ / "out2").string());
  EXPECT_EQ(r.frames, 1);
  EXPECT_FALSE(r.stopped_by.empty());
  EXPECT_EQ(r.objects.count("tin"), 1u);
}

TEST_F(ObjectFinderRun, AnEmptyDatabaseIsAnErrorNamingIt) {
  mrpt_plugins::CObjectDatabaseMap().SaveToFile((dir_ / "empty.object_database").string());
  o_.database = (dir_ / "empty.object_database").string();
  o_.input = (dir_ / "frames").string();
  try {
    RunObjectFinder(o_, (dir_ / "out").string());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("empty.object_database: the database holds no object"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace novelty::experiments
