#include "mrpt_plugins/depth_source.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <random>

#include "mrpt_plugins/c_appearance_map.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::mrpt_plugins {
namespace {

// A stereo pair of a textured wall 2 m in front of the rig (left camera the reference, right
// camera 12 cm to its right), as a CObservationStereoImages.
const core::PinholeCamera kCam{160, 120, 140.0, 140.0, 79.5, 59.5};
constexpr double kBaseline = 0.12, kWall = 2.0;

mrpt::img::CImage ToImage(const cv::Mat& rgb) {
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return mrpt::img::CImage(bgr, mrpt::img::DEEP_COPY);
}

mrpt::obs::CObservationStereoImages WallPair(int right_width = kCam.width) {
  cv::Mat noise(kCam.height, kCam.width + 40, CV_8UC3);
  std::mt19937 rng(3);
  for (auto it = noise.begin<cv::Vec3b>(); it != noise.end<cv::Vec3b>(); ++it) {
    *it = cv::Vec3b(rng() % 256, rng() % 256, rng() % 256);
  }
  cv::GaussianBlur(noise, noise, cv::Size(5, 5), 1.2);
  const double disparity = kCam.fx * kBaseline / kWall;  // 8.4 px: u_right = u_left − d
  const cv::Mat left = noise(cv::Rect(0, 0, kCam.width, kCam.height)).clone();
  cv::Mat right;
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, -disparity, 0, 1, 0);
  cv::warpAffine(noise, right, shift, noise.size(), cv::INTER_CUBIC, cv::BORDER_REFLECT);
  right = right(cv::Rect(0, 0, right_width, kCam.height)).clone();
  mrpt::obs::CObservationStereoImages obs;
  obs.sensorLabel = "STEREO";
  obs.leftCamera = obs.rightCamera = sensors::ToMrpt(kCam);
  obs.rightCameraPose = mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(kBaseline, 0, 0, 0, 0, 0));
  obs.cameraPose = mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D());
  obs.imageLeft = ToImage(left);
  obs.imageRight = ToImage(right);
  obs.hasImageRight = true;
  return obs;
}

DepthSourceOptions Stereo() {
  DepthSourceOptions o;
  o.kind = DepthSourceOptions::Kind::kStereo;
  return o;
}

TEST(DepthSource, StereoPairsGiveFramesWithStereoDepth) {
  core::Frame f;
  ASSERT_TRUE(
      DecodeWithDepthSource(WallPair(), mrpt::poses::CPose3D(1, 2, 0, 0, 0, 0), Stereo(), f));
  ASSERT_EQ(f.depth.size(), cv::Size(kCam.width, kCam.height));
  // Interior pixels (away from the border the right image does not cover): the wall's depth.
  std::vector<float> d;
  for (int y = 10; y < kCam.height - 10; ++y)
    for (int x = 20; x < kCam.width - 10; ++x) d.push_back(f.depth.at<float>(y, x));
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  EXPECT_NEAR(d[d.size() / 2], kWall, 0.03 * kWall);
  const auto within =
      std::count_if(d.begin(), d.end(), [](float z) { return std::abs(z - kWall) < 0.03 * kWall; });
  EXPECT_GT(double(within) / d.size(), 0.9);
  EXPECT_NEAR(f.T_world_cam->translation().x(), 1.0, 1e-9);  // robot pose ⊕ camera pose
  EXPECT_NEAR(f.T_world_cam->translation().y(), 2.0, 1e-9);
  // Without a stereo source the pair is not used.
  EXPECT_FALSE(DecodeWithDepthSource(WallPair(), std::nullopt, DepthSourceOptions{}, f));
}

TEST(DepthSource, TheAppearanceMapTakesStereoPairsOnlyWhenConfigured) {
  CAppearanceMap plain;
  EXPECT_FALSE(plain.insertObservation(WallPair()));
  EXPECT_TRUE(plain.isEmpty());
  CAppearanceMap stereo;
  stereo.setDepthSource(Stereo());
  EXPECT_TRUE(stereo.insertObservation(WallPair()));
  EXPECT_EQ(stereo.map().store().size(), 1);
  EXPECT_EQ(stereo.lastProducts().surprise.size(), cv::Size(kCam.width, kCam.height));
  // A right image of another size: a clear error naming the sensor, the map unchanged.
  try {
    stereo.insertObservation(WallPair(kCam.width - 8));
    ADD_FAILURE() << "no error for images of different sizes";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("STEREO"), std::string::npos) << e.what();
  }
  EXPECT_EQ(stereo.map().store().size(), 1);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
