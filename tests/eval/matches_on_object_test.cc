#include "eval/matches_on_object.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::eval {
namespace {

// Object 0 learnt as A = e0, object 1 as B = e1 (descriptors of width 4).
objects::FeatureDatabase TwoObjects() {
  objects::FeatureDatabase db;
  db.AddFeatures((cv::Mat_<float>(1, 4) << 1, 0, 0, 0), db.AddObject());
  db.AddFeatures((cv::Mat_<float>(1, 4) << 0, 1, 0, 0), db.AddObject());
  return db;
}

void Add(objects::FrameFeatures& f, float x, float y, cv::Mat descriptor) {
  f.keypoints.emplace_back(cv::Point2f(x, y), 12.0f);
  f.descriptors.push_back(descriptor);
}

cv::Mat ObjectMask() {  // the object covers x, y in [10, 30)
  cv::Mat m(60, 80, CV_8UC1, cv::Scalar(0));
  m(cv::Rect(10, 10, 20, 20)).setTo(1);
  return m;
}

TEST(MatchOnObject, ClutterThatSpoilsTheWholeFramesRatioTestIsLeftOut) {
  const objects::FeatureDatabase db = TwoObjects();
  objects::FrameFeatures f;
  Add(f, 15, 15, (cv::Mat_<float>(1, 4) << 1, 0.3f, 0, 0));   // on the object, 0.3 from A
  Add(f, 60, 40, (cv::Mat_<float>(1, 4) << 1, 0, 0.35f, 0));  // clutter, 0.35 from A
  Add(f, 20, 25, (cv::Mat_<float>(1, 4) << 0, 0, 0, 1));      // on the object, √2 from A
  Add(f, 60, 45, (cv::Mat_<float>(1, 4) << 0, 1, 0, 0.1f));   // clutter, 0.1 from B, 1.42 from A
  // The whole frame: 0.3 / 0.35 > 0.65, no match.
  EXPECT_EQ(db.Match(f.descriptors, 0.65).matches_per_object[0], 0);
  // The object's own keypoints: 0.3 / √2 < 0.65.
  const MatchesOnObject a = MatchOnObject(db, 0, f, ObjectMask(), 0, 0.65);
  EXPECT_EQ(a.keypoints, 2);
  EXPECT_EQ(a.matches, 1);
  EXPECT_NEAR(a.mean_nearest_distance, 0.3, 1e-6);
  // B's nearest on the object is the first keypoint, √1.49 away (in the frame, the clutter
  // 0.1 away); √1.49 / √2 > 0.65.
  const MatchesOnObject b = MatchOnObject(db, 1, f, ObjectMask(), 0, 0.65);
  EXPECT_EQ(b.matches, 0);
  EXPECT_NEAR(b.mean_nearest_distance, std::sqrt(1.49), 1e-6);
}

TEST(MatchOnObject, AKeypointWithinTheMarginCountsAsOnTheObject) {
  const objects::FeatureDatabase db = TwoObjects();
  objects::FrameFeatures f;
  Add(f, 15, 15, (cv::Mat_<float>(1, 4) << 1, 0, 0, 0));
  Add(f, 33, 15, (cv::Mat_<float>(1, 4) << 0, 0, 1, 0));  // 4 px right of the last column, 29
  EXPECT_EQ(MatchOnObject(db, 0, f, ObjectMask(), 3, 0.65).keypoints, 1);
  EXPECT_EQ(MatchOnObject(db, 0, f, ObjectMask(), 4, 0.65).keypoints, 2);
  // 4 px right of and below the corner (29, 29): 5.7 px away, out at 4 px (a square would take
  // it in), in at 6.
  Add(f, 33, 33, (cv::Mat_<float>(1, 4) << 0, 0, 1, 0));
  EXPECT_EQ(MatchOnObject(db, 0, f, ObjectMask(), 4, 0.65).keypoints, 2);
  EXPECT_EQ(MatchOnObject(db, 0, f, ObjectMask(), 6, 0.65).keypoints, 3);
}

TEST(MatchOnObject, AnObjectWithoutKeypointsHasNoDistance) {
  const objects::FeatureDatabase db = TwoObjects();
  objects::FrameFeatures f;
  Add(f, 60, 40, (cv::Mat_<float>(1, 4) << 1, 0, 0, 0));
  const MatchesOnObject m = MatchOnObject(db, 0, f, ObjectMask(), 2, 0.65);
  EXPECT_EQ(m.keypoints, 0);
  EXPECT_EQ(m.matches, 0);
  EXPECT_TRUE(std::isnan(m.mean_nearest_distance));
}

TEST(MatchOnObject, BadInputIsAClearError) {
  const objects::FeatureDatabase db = TwoObjects();
  objects::FrameFeatures f;
  Add(f, 15, 15, (cv::Mat_<float>(1, 4) << 1, 0, 0, 0));
  EXPECT_THROW(MatchOnObject(db, 0, f, cv::Mat(60, 80, CV_32SC1, cv::Scalar(1)), 0, 0.65),
               std::invalid_argument);
  EXPECT_THROW(MatchOnObject(db, 2, f, ObjectMask(), 0, 0.65), std::invalid_argument);
  EXPECT_THROW(MatchOnObject(db, 0, f, ObjectMask(), -1, 0.65), std::invalid_argument);
  objects::FrameFeatures wide;
  Add(wide, 15, 15, cv::Mat::ones(1, 5, CV_32F));
  EXPECT_THROW(MatchOnObject(db, 0, wide, ObjectMask(), 0, 0.65), std::invalid_argument);
  f.keypoints.pop_back();
  EXPECT_THROW(MatchOnObject(db, 0, f, ObjectMask(), 0, 0.65), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
