#include "sim/render/object_insertion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::sim {
namespace {

// A camera at the origin looking along +z at a wall 3 m away (160×120, f = 100 px).
struct Wall {
  core::PinholeCamera camera;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  cv::Mat rgb, depth;
  Wall() {
    camera.width = 160;
    camera.height = 120;
    camera.fx = camera.fy = 100;
    camera.cx = 79.5;
    camera.cy = 59.5;
    rgb = cv::Mat(120, 160, CV_8UC3, cv::Scalar(90, 90, 90));
    depth = cv::Mat(120, 160, CV_32FC1, cv::Scalar(3.0f));
  }
};

InsertedBoxOptions CubeBefore(const Wall& w, double standoff) {
  InsertedBoxOptions o;
  o.size = {0.3, 0.3, 0.3};
  o.pose = ObjectInserter::StandInFrontOf(w.depth, w.camera, w.pose, standoff, o.size);
  return o;
}

// 0.5 m before the wall the cube's front face is at 3 − 0.5 − 0.3 = 2.2 m: a square of
// 0.3·100/2.2 = 13.6 px a side, 186 px, centred on the principal point, at depth 2.2 m; the cube's
// sides are hidden behind its face seen from the centre.
TEST(ObjectInserter, AFaceOnCubeCoversItsProjectedSquareAtItsDepth) {
  Wall w;
  const cv::Mat before = w.rgb.clone();
  const InsertedBoxOptions o = CubeBefore(w, 0.5);
  EXPECT_NEAR(o.pose.translation().z(), 2.35, 1e-9);
  EXPECT_NEAR(o.pose.translation().x(), 0.0, 1e-9);
  const cv::Mat mask = ObjectInserter(o).Insert(w.rgb, w.depth, w.camera, w.pose, 1);
  const double side = 0.3 * 100 / 2.2;
  EXPECT_NEAR(cv::countNonZero(mask), side * side, 2 * side);  // within a pixel along its rim
  const cv::Rect box = cv::boundingRect(mask);
  EXPECT_NEAR(box.x + box.width / 2.0, 80.0, 1.0);
  EXPECT_NEAR(box.y + box.height / 2.0, 60.0, 1.0);
  double lo, hi;
  cv::minMaxLoc(w.depth, &lo, &hi, nullptr, nullptr, mask);
  EXPECT_NEAR(lo, 2.2, 1e-3);
  EXPECT_NEAR(hi, 2.2, 1e-3);
  // Outside the mask the frame is as it was, depth and colour.
  cv::Mat outside;
  cv::bitwise_not(mask, outside);
  EXPECT_EQ(cv::norm(w.rgb, before, cv::NORM_INF, outside), 0.0);
  cv::minMaxLoc(w.depth, &lo, &hi, nullptr, nullptr, outside);
  EXPECT_EQ(lo, 3.0);
  EXPECT_EQ(hi, 3.0);
  // The checkerboard shows: the face is not one colour.
  cv::Scalar mean, stddev;
  cv::meanStdDev(w.rgb, mean, stddev, mask);
  EXPECT_GT(stddev[0] + stddev[1] + stddev[2], 30.0);
}

// What stands in front hides the box; where the frame has no depth the box shows.
TEST(ObjectInserter, TheRealSceneOccludesItAndUnknownDepthDoesNot) {
  Wall w;
  const InsertedBoxOptions o = CubeBefore(w, 0.5);
  w.depth.colRange(0, 80).setTo(1.0f);                    // a nearer surface over the left half
  w.depth.rowRange(0, 60).colRange(80, 160).setTo(0.0f);  // top right: no depth
  const cv::Mat mask = ObjectInserter(o).Insert(w.rgb, w.depth, w.camera, w.pose, 1);
  EXPECT_EQ(cv::countNonZero(mask.colRange(0, 80)), 0);
  const double side = 0.3 * 100 / 2.2;
  EXPECT_NEAR(cv::countNonZero(mask.colRange(80, 160)), side * side / 2, side);
  EXPECT_GT(cv::countNonZero(mask.rowRange(0, 60).colRange(80, 160)), 0);
}

// Seen from 1 m to the right, the cube's centre projects 100·(−1)/2.35 = −42.6 px from the
// principal point, and its +x face (nearest that camera) shows as well.
TEST(ObjectInserter, SeenFromElsewhereItIsWhereItStands) {
  Wall w;
  const InsertedBoxOptions o = CubeBefore(w, 0.5);
  Eigen::Isometry3d right = w.pose;
  right.translation().x() = 1.0;
  const cv::Mat mask = ObjectInserter(o).Insert(w.rgb, w.depth, w.camera, right, 2);
  ASSERT_GT(cv::countNonZero(mask), 0);
  const cv::Moments m = cv::moments(mask, true);
  EXPECT_NEAR(m.m10 / m.m00, 79.5 - 100 * 1.0 / 2.35, 4.0);  // the side face moves it a little
  EXPECT_NEAR(m.m01 / m.m00, 59.5, 1.0);
}

TEST(ObjectInserter, BadInputsAreErrors) {
  Wall w;
  cv::Mat none(120, 160, CV_32FC1, cv::Scalar(0.0f));
  EXPECT_THROW(ObjectInserter::StandInFrontOf(none, w.camera, w.pose, 0.5, {0.3, 0.3, 0.3}),
               std::invalid_argument);
  EXPECT_THROW(ObjectInserter::StandInFrontOf(w.depth, w.camera, w.pose, 2.8, {0.3, 0.3, 0.3}),
               std::invalid_argument);  // it would stand behind the camera
  InsertedBoxOptions o;
  o.size = {0.3, -1, 0.3};
  EXPECT_THROW(ObjectInserter{o}, std::invalid_argument);
  o = CubeBefore(w, 0.5);
  const ObjectInserter inserter(o);
  cv::Mat small(10, 10, CV_8UC3);
  EXPECT_THROW(inserter.Insert(small, w.depth, w.camera, w.pose, 1), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sim
