// The learnt-keypoint check of a match (keypoint_consistency.h): metric size as size · depth / fx,
// orientation differences taken round the circle, tolerances either way, unknowns passing.
#include "maps/objects/keypoint_consistency.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::objects {
namespace {

const core::PinholeCamera kConsistencyCamera;  // fx = 400

cv::KeyPoint At(float x, float y, float size, float angle) {
  return cv::KeyPoint(cv::Point2f(x, y), size, angle);
}

TEST(KeypointConsistency, MetricSizeIsSizeTimesDepthOverFocalLength) {
  // A 20 px blob at 2 m with fx = 400 spans 0.1 m.
  EXPECT_DOUBLE_EQ(MetricSize(At(10, 10, 20, 0), 2.0, kConsistencyCamera), 0.1);
  core::PinholeCamera mirrored = kConsistencyCamera;
  mirrored.fx = -400;  // a mirrored image: the size is still positive
  EXPECT_DOUBLE_EQ(MetricSize(At(10, 10, 20, 0), 2.0, mirrored), 0.1);
  for (double bad : {0.0, -1.0, std::nan(""), double(INFINITY)})
    EXPECT_TRUE(std::isnan(MetricSize(At(10, 10, 20, 0), bad, kConsistencyCamera))) << bad;
}

TEST(KeypointConsistency, MetricSizesReadTheDepthAtTheRoundedPixel) {
  cv::Mat depth(4, 5, CV_32FC1, cv::Scalar(1.0f));
  depth.at<float>(2, 3) = 4.0f;  // row 2, column 3
  depth.at<float>(0, 0) = 0.0f;  // unknown
  depth.at<float>(3, 4) = 2.0f;  // the last pixel
  const std::vector<cv::KeyPoint> k = {At(2.6f, 1.6f, 40, 0), At(0.2f, 0.3f, 40, 0),
                                       At(9, 1, 40, 0), At(1, 1, 40, 0), At(4.6f, 3.7f, 40, 0)};
  const std::vector<double> s = MetricSizes(k, depth, kConsistencyCamera);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_DOUBLE_EQ(s[0], 40 * 4.0 / 400);  // (2.6, 1.6) rounds to column 3, row 2
  EXPECT_TRUE(std::isnan(s[1]));           // depth 0
  EXPECT_TRUE(std::isnan(s[2]));           // outside the image
  EXPECT_DOUBLE_EQ(s[3], 0.1);
  EXPECT_DOUBLE_EQ(s[4], 40 * 2.0 / 400);  // rounds one past the edge: the border pixel
  for (double v : MetricSizes(k, cv::Mat(), kConsistencyCamera)) EXPECT_TRUE(std::isnan(v));
  EXPECT_THROW(MetricSizes(k, cv::Mat(4, 5, CV_64FC1), kConsistencyCamera), std::invalid_argument);
}

TEST(KeypointConsistency, OrientationIsComparedRoundTheCircle) {
  KeypointConsistencyOptions o;
  o.enabled = true;  // 20°, 1.3
  const LearntKeypoint learnt =
      ToLearntKeypoint(At(0, 0, 20, 355), MetricSize(At(0, 0, 20, 355), 1.0, kConsistencyCamera));
  EXPECT_DOUBLE_EQ(learnt.angle_deg, 355);
  EXPECT_DOUBLE_EQ(learnt.size_m, 0.05);
  EXPECT_TRUE(ConsistentKeypoint(learnt, At(0, 0, 20, 10), 0.05, o));     // 15° across 0
  EXPECT_TRUE(ConsistentKeypoint(learnt, At(0, 0, 20, 335.5), 0.05, o));  // 19.5°
  EXPECT_FALSE(ConsistentKeypoint(learnt, At(0, 0, 20, 20), 0.05, o));    // 25°
  EXPECT_FALSE(ConsistentKeypoint(learnt, At(0, 0, 20, 175), 0.05, o));   // 180°
  o.enabled = false;
  EXPECT_TRUE(ConsistentKeypoint(learnt, At(0, 0, 20, 175), 0.05, o));
}

TEST(KeypointConsistency, MetricSizeMayDifferByTheRatioEitherWay) {
  KeypointConsistencyOptions o;
  o.enabled = true;
  LearntKeypoint learnt;
  learnt.angle_deg = 90;
  learnt.size_m = 0.1;
  const cv::KeyPoint seen = At(0, 0, 20, 90);
  EXPECT_TRUE(ConsistentKeypoint(learnt, seen, 0.129, o));
  EXPECT_TRUE(ConsistentKeypoint(learnt, seen, 0.1 / 1.29, o));
  EXPECT_FALSE(ConsistentKeypoint(learnt, seen, 0.131, o));
  EXPECT_FALSE(ConsistentKeypoint(learnt, seen, 0.1 / 1.31, o));
  // Unknowns pass: no depth where seen, none when learnt, no orientation (OpenCV's −1).
  EXPECT_TRUE(ConsistentKeypoint(learnt, seen, std::nan(""), o));
  EXPECT_TRUE(ConsistentKeypoint(LearntKeypoint(), At(0, 0, 20, 300), 0.5, o));
  EXPECT_TRUE(ConsistentKeypoint(learnt, At(0, 0, 20, -1), 0.1, o));
  EXPECT_TRUE(std::isnan(ToLearntKeypoint(At(0, 0, 20, -1), 0.1).angle_deg));
  EXPECT_EQ(ToLearntKeypoint(At(0, 0, 20, 360.0f), 0.1).angle_deg, 0.0) << "kept in [0, 360)";
  // Exactly at the tolerances: still consistent.
  LearntKeypoint at;
  at.angle_deg = 0;
  at.size_m = 1.0;
  EXPECT_TRUE(ConsistentKeypoint(at, At(0, 0, 20, 20), 1.0, o));
  EXPECT_TRUE(ConsistentKeypoint(at, At(0, 0, 20, 0), 1.3, o));
  EXPECT_DOUBLE_EQ(TurnDeg(at, At(0, 0, 20, 350)), 10.0);
  EXPECT_TRUE(std::isnan(TurnDeg(LearntKeypoint(), At(0, 0, 20, 350))));
  EXPECT_DOUBLE_EQ(SizeRatio(at, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(SizeRatio(at, 2.0), 2.0);
  EXPECT_TRUE(std::isnan(SizeRatio(at, 0.0)));
}

TEST(KeypointConsistency, BadTolerancesAreNamed) {
  KeypointConsistencyOptions o;
  CheckKeypointConsistencyOptions(o);
  for (double angle : {0.0, -5.0, 181.0, std::nan("")}) {
    o = {};
    o.max_angle_deg = angle;
    EXPECT_THROW(CheckKeypointConsistencyOptions(o), std::invalid_argument) << angle;
  }
  for (double ratio : {0.9, std::nan(""), double(INFINITY)}) {
    o = {};
    o.max_size_ratio = ratio;
    try {
      CheckKeypointConsistencyOptions(o);
      ADD_FAILURE() << ratio;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("max_size_ratio"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace novelty::objects
