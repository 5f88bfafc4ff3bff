#include "sensors/dataset/fixed_camera_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "sensors/dataset/rgbd_importer.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

fs::path FixedFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("novelty_fixed_camera_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string FixedFolderError(const std::string& folder, const FixedCameraOptions& o = {}) {
  try {
    const FixedCameraFolder f(folder, o);
    for (int k = 0; k < f.size(); ++k) f.Rgb(k);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// A colour and a 16-bit grey image of one size, a mask, and an image the patterns leave out.
TEST(FixedCameraFolder, ImagesBecomeObservationsOfOneCameraOnAPlane) {
  const fs::path dir = FixedFolder("good");
  cv::Mat bgr(6, 10, CV_8UC3, cv::Scalar(30, 20, 10));
  ASSERT_TRUE(cv::imwrite((dir / "a.png").string(), bgr));
  ASSERT_TRUE(cv::imwrite((dir / "b.png").string(), cv::Mat(6, 10, CV_16U, cv::Scalar(257 * 40))));
  ASSERT_TRUE(cv::imwrite((dir / "b_Ambient.png").string(), bgr));
  cv::Mat mask = cv::Mat::zeros(6, 10, CV_8U);
  mask(cv::Rect(2, 1, 5, 4)).setTo(255);
  ASSERT_TRUE(cv::imwrite((dir / "mask.png").string(), mask));
  FixedCameraOptions o;
  o.pick.exclude = {"*_Ambient*"};
  o.depth = 2.5;
  const FixedCameraFolder f(dir.string(), o);
  ASSERT_EQ(f.size(), 2);
  EXPECT_EQ(f.name(0), "a.png");
  EXPECT_EQ(f.listing().left_out, std::vector<std::string>{"b_Ambient.png"});
  EXPECT_EQ(f.camera().width, 10);
  EXPECT_EQ(f.camera().fx, 10.0);
  EXPECT_EQ(f.camera().cx, 4.5);
  EXPECT_EQ(f.camera().cy, 2.5);
  EXPECT_EQ(f.Rgb(0).at<cv::Vec3b>(3, 3), cv::Vec3b(10, 20, 30));  // R G B
  EXPECT_EQ(f.Rgb(1).at<cv::Vec3b>(0, 0), cv::Vec3b(40, 40, 40));  // 16-bit grey ÷ 257
  // Through MRPT's observation and back: the image, the plane inside the mask, unknown outside.
  const mrpt::obs::CObservation3DRangeScan obs = f.Observation(1);
  cv::Mat rgb, depth;
  core::PinholeCamera camera;
  DecodeRgbd(obs, rgb, depth, camera);
  EXPECT_EQ(rgb.at<cv::Vec3b>(5, 9), cv::Vec3b(40, 40, 40));
  EXPECT_NEAR(depth.at<float>(2, 3), 2.5f, kRgbdRangeUnits);
  EXPECT_EQ(depth.at<float>(0, 0), 0.0f);
  EXPECT_EQ(cv::countNonZero(depth), 20);
  EXPECT_EQ(camera.fx, 10.0);
  EXPECT_TRUE(CameraOnRobot(obs).isApprox(HandHeldMount(), 1e-9));
  fs::remove_all(dir);
}

TEST(FixedCameraFolder, BadFoldersAreErrorsNamingTheFile) {
  EXPECT_NE(FixedFolderError("/nonexistent/folder").find("/nonexistent/folder"), std::string::npos);
  const fs::path dir = FixedFolder("bad");
  EXPECT_NE(FixedFolderError(dir.string()).find("no image"), std::string::npos);
  ASSERT_TRUE(cv::imwrite((dir / "a.png").string(), cv::Mat(6, 10, CV_8UC3, cv::Scalar::all(9))));
  ASSERT_TRUE(cv::imwrite((dir / "b.png").string(), cv::Mat(7, 10, CV_8UC3, cv::Scalar::all(9))));
  const std::string sizes = FixedFolderError(dir.string());
  EXPECT_NE(sizes.find("b.png is 10x7"), std::string::npos) << sizes;
  FixedCameraOptions small;
  small.max_pixels = 50;
  EXPECT_NE(FixedFolderError(dir.string(), small).find("a.png"), std::string::npos);
  small.pick.include = {"z*"};
  EXPECT_NE(FixedFolderError(dir.string(), small).find("2 left out"), std::string::npos);
  FixedCameraOptions flat;
  flat.depth = 0.0;
  EXPECT_THROW(FixedCameraFolder(dir.string(), flat), std::invalid_argument);
  fs::remove_all(dir);
}

// A CDnet folder: input/in000001.jpg… as frames (groundtruth/ and a stray file left alone), its
// ROI.bmp as the mask; a folder without input/ is an error naming it.
TEST(FixedCameraFolder, ACdnetFolderIsAFixedCameraWithItsRoiAsMask) {
  const fs::path dir = FixedFolder("cdnet");
  fs::create_directories(dir / "input");
  fs::create_directories(dir / "groundtruth");
  for (const char* name : {"in000001.jpg", "in000002.jpg"})
    ASSERT_TRUE(cv::imwrite((dir / "input" / name).string(), cv::Mat(6, 10, CV_8UC3)));
  ASSERT_TRUE(cv::imwrite((dir / "groundtruth" / "gt000001.png").string(), cv::Mat(6, 10, CV_8U)));
  cv::Mat roi = cv::Mat::zeros(6, 10, CV_8U);
  roi.colRange(5, 10).setTo(255);
  ASSERT_TRUE(cv::imwrite((dir / "ROI.bmp").string(), roi));
  const FixedCameraFolder f = CdnetFixedCamera(dir.string());
  ASSERT_EQ(f.size(), 2);
  EXPECT_EQ(f.name(1), "in000002.jpg");
  EXPECT_EQ(cv::countNonZero(f.depth()), 30);
  EXPECT_EQ(f.depth().at<float>(0, 4), 0.0f);
  EXPECT_GT(f.depth().at<float>(0, 5), 0.0f);
  fs::remove(dir / "ROI.bmp");
  EXPECT_EQ(cv::countNonZero(CdnetFixedCamera(dir.string()).depth()), 60);
  fs::remove_all(dir / "input");
  try {
    CdnetFixedCamera(dir.string());
    ADD_FAILURE() << "no input/ accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sensors
