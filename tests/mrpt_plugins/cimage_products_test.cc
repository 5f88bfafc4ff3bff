#include "mrpt_plugins/cimage_products.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::mrpt_plugins {
namespace {

// An RGB picture becomes an MRPT image with the same colours (CImage holds BGR), and as an
// observation it survives a rawlog round trip with its label, time, pose and camera.
TEST(ProductImages, ReachARawlogAsCObservationImage) {
  cv::Mat rgb(4, 5, CV_8UC3, cv::Scalar(10, 20, 30));  // R, G, B
  rgb.at<cv::Vec3b>(2, 3) = cv::Vec3b(250, 0, 5);
  const mrpt::img::CImage image = ToCImage(rgb);
  ASSERT_EQ(image.getWidth(), 5u);
  ASSERT_TRUE(image.isColor());
  EXPECT_EQ(cv::norm(sensors::RgbFromImage(image), rgb, cv::NORM_INF), 0.0);
  EXPECT_TRUE(ToCImage(cv::Mat()).isEmpty());
  EXPECT_THROW(ToCImage(cv::Mat(2, 2, CV_32FC1)), std::invalid_argument);

  mrpt::img::TCamera camera;
  camera.ncols = 5;
  camera.nrows = 4;
  camera.fx(100.0);
  const auto t = mrpt::Clock::fromDouble(1234.5);
  const mrpt::poses::CPose3D pose(0.1, 0.2, 1.0, 0.3, -0.2, 0.1);
  const auto path = std::filesystem::temp_directory_path() / "product_images_test.rawlog";
  {
    mrpt::io::CFileGZOutputStream out(path.string());
    mrpt::serialization::archiveFrom(out)
        << *ProductObservation(image, "SURPRISE", t, pose, camera);
  }
  mrpt::io::CFileGZInputStream in(path.string());
  const auto object = mrpt::serialization::archiveFrom(in).ReadObject();
  const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(object);
  ASSERT_TRUE(obs);
  EXPECT_EQ(obs->sensorLabel, "SURPRISE");
  EXPECT_EQ(obs->timestamp, t);
  EXPECT_NEAR((obs->cameraPose.asVectorVal() - pose.asVectorVal()).norm(), 0.0, 1e-12);
  EXPECT_EQ(obs->cameraParams.fx(), 100.0);
  EXPECT_EQ(cv::norm(sensors::RgbFromImage(obs->image), rgb, cv::NORM_INF), 0.0);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
