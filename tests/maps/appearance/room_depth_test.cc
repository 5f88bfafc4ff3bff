#include "maps/appearance/room_depth.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::appearance {
namespace {

const core::PinholeCamera kRoomCamera = core::PinholeCamera::FromFov(32, 24, 1.0);

cv::Mat FlatDepth(float metres) {
  return cv::Mat(kRoomCamera.height, kRoomCamera.width, CV_32FC1, cv::Scalar(metres));
}
cv::Mat FlatPlane(float value) {
  return cv::Mat(kRoomCamera.height, kRoomCamera.width, CV_32FC3, cv::Scalar::all(value));
}

Eigen::Isometry3d RoomAt(double x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  return T;
}

// Over the pixels some view covers: the smallest nearest and the largest farthest depth, and how
// many pixels are covered.
struct SpanSummary {
  float nearest = INFINITY, farthest = 0;
  int covered = 0;
};
SpanSummary Summarise(const cv::Mat& span) {
  SpanSummary s;
  for (int v = 0; v < span.rows; ++v)
    for (int u = 0; u < span.cols; ++u) {
      const cv::Vec2f d = span.at<cv::Vec2f>(v, u);
      if (d[0] <= 0) continue;
      ++s.covered;
      s.nearest = std::min(s.nearest, d[0]);
      s.farthest = std::max(s.farthest, d[1]);
    }
  return s;
}

// A wall 2 m ahead, parallel to the image: seen from anywhere on the x axis its depth is 2 m at
// every pixel. The robot then sees an object 1 m ahead from beside the first view, and the map
// replaces that view's depth with it; the snapshot taken before still predicts the wall.
TEST(RoomDepth, KeepsTheRoomsDepthWhereTheMapHasTakenInANearerObject) {
  ViewBasedMap map;
  map.Update(kRoomCamera, RoomAt(0.0), FlatDepth(2.0), {{"p", FlatPlane(1)}}, {});
  map.Update(kRoomCamera, RoomAt(0.2), FlatDepth(2.0), {{"p", FlatPlane(1)}}, {0});
  ASSERT_EQ(map.store().size(), 2);
  RoomDepth room(map);
  EXPECT_EQ(room.views(), 2);
  EXPECT_FALSE(
      map.Update(kRoomCamera, RoomAt(0.001), FlatDepth(1.0), {{"p", FlatPlane(2)}}, {0}).added);

  const SpanSummary now = Summarise(map.Predict(kRoomCamera, RoomAt(0.01), {}, true).depth_span);
  ASSERT_GT(now.covered, 32 * 24 / 2);
  EXPECT_NEAR(now.nearest, 1.0f, 1e-4) << "the map predicts the object it has taken in";

  const cv::Mat span = room.DepthSpan(kRoomCamera, RoomAt(0.01));
  ASSERT_EQ(span.type(), CV_32FC2);
  ASSERT_EQ(span.size(), cv::Size(32, 24));
  const SpanSummary before = Summarise(span);
  EXPECT_GT(before.covered, 32 * 24 / 2);
  EXPECT_NEAR(before.nearest, 2.0f, 1e-4);
  EXPECT_NEAR(before.farthest, 2.0f, 1e-4);
}

// A compact map holds most views encoded: the snapshot decodes them (depth within the codec's
// 2^-15 relative error) and predicts from every view, not only the decoded ones.
TEST(RoomDepth, DecodesTheViewsACompactMapHoldsEncoded) {
  ViewBasedMapOptions options;
  options.storage.decoded_views = 1;
  ViewBasedMap map(options);
  for (int i = 0; i < 4; ++i) {
    const float wall = 2.0f + 0.5f * float(i);
    map.Update(kRoomCamera, RoomAt(0.1 * i), FlatDepth(wall), {{"p", FlatPlane(1)}}, {});
    map.Predict(kRoomCamera, RoomAt(0.1 * i), {{"p", 3}});  // evicts all but the view used
  }
  ASSERT_EQ(map.store().size(), 4);
  ASSERT_FALSE(map.store().decoded(0));
  RoomDepth room(map);
  for (int i = 0; i < 4; ++i) {
    // The camera at a view's pose reads that view alone (no warp).
    const SpanSummary s = Summarise(room.DepthSpan(kRoomCamera, RoomAt(0.1 * i)));
    const float wall = 2.0f + 0.5f * float(i);
    EXPECT_EQ(s.covered, 32 * 24) << "view " << i;
    EXPECT_NEAR(s.nearest, wall, wall * 1e-4) << "view " << i;
    EXPECT_NEAR(s.farthest, wall, wall * 1e-4) << "view " << i;
  }
}

TEST(RoomDepth, AnEmptyMapPredictsNoDepth) {
  RoomDepth room{ViewBasedMap{}};
  EXPECT_EQ(room.views(), 0);
  const cv::Mat span = room.DepthSpan(kRoomCamera, RoomAt(0.0));
  ASSERT_EQ(span.type(), CV_32FC2);
  ASSERT_EQ(span.size(), cv::Size(32, 24));
  EXPECT_EQ(cv::countNonZero(span.reshape(1)), 0);
}

// Known answers: both known, one known (0 or NaN in the other), none.
TEST(UnionOfDepthSpans, NearestOfTheNearestFarthestOfTheFarthestOverTheKnown) {
  const float nan = std::nanf("");
  const cv::Mat a = (cv::Mat_<cv::Vec2f>(1, 5) << cv::Vec2f(1, 2), cv::Vec2f(1, 2), cv::Vec2f(0, 0),
                     cv::Vec2f(nan, nan), cv::Vec2f(0, 0));
  const cv::Mat b = (cv::Mat_<cv::Vec2f>(1, 5) << cv::Vec2f(1.5, 3), cv::Vec2f(0, 0),
                     cv::Vec2f(4, 5), cv::Vec2f(4, 5), cv::Vec2f(nan, nan));
  const cv::Mat u = UnionOfDepthSpans(a, b);
  ASSERT_EQ(u.type(), CV_32FC2);
  const std::vector<cv::Vec2f> expected = {{1, 3}, {1, 2}, {4, 5}, {4, 5}, {0, 0}};
  for (int x = 0; x < 5; ++x) EXPECT_EQ(u.at<cv::Vec2f>(0, x), expected[std::size_t(x)]) << x;
  EXPECT_THROW(UnionOfDepthSpans(a, b.colRange(0, 4)), std::invalid_argument);
  EXPECT_THROW(UnionOfDepthSpans(a, cv::Mat(1, 5, CV_32FC1)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::appearance
