// Recognition in a whole frame against a learnt database: a print learnt on a plane 1 m in front
// of the camera is found again after the camera moved (its matches and, verified, the camera's
// move as the object's pose), and a different print is not.
#include "maps/objects/object_recognition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "maps/objects/feature_extractor.h"

namespace novelty::objects {
namespace {

const core::PinholeCamera kCamera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);

cv::Mat Print(int seed) {  // blurred noise: blobs a few pixels wide, like a photograph's detail
  cv::Mat t(kCamera.height, kCamera.width, CV_8UC1);
  cv::RNG(seed).fill(t, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(t, t, cv::Size(0, 0), 3.0);
  cv::normalize(t, t, 0, 255, cv::NORM_MINMAX);
  return t;
}

// The database: every M-SURF feature of print 1 seen on the plane z = 1 m, as object 0, and of
// print 2 as object 1 where `two_objects`.
FeatureDatabase Learn(cv::Feature2D& extractor, bool two_objects) {
  FeatureDatabase db;
  for (int seed : {1, 2}) {
    if (seed == 2 && !two_objects) break;
    std::vector<cv::KeyPoint> k;
    cv::Mat d;
    extractor.detectAndCompute(Print(seed), cv::noArray(), k, d);
    std::vector<Eigen::Vector3d> places;
    for (const cv::KeyPoint& p : k) places.push_back(kCamera.RayCam(p.pt.x, p.pt.y));  // z = 1
    db.AddFeatures(d, db.AddObject(), places);
  }
  return db;
}

TEST(ObjectRecognition, FindsALearntPrintAfterTheCameraMovedAndVerifiesItsPose) {
  cv::Ptr<cv::Feature2D> extractor = CreateFeatureExtractor(FeatureExtractor::kMSurf);
  const FeatureDatabase db = Learn(*extractor, false);
  ASSERT_GE(db.features(), 30);
  // The camera moved 1 cm to the left: the plane at 1 m shifts by fx * 0.01 px to the right.
  const double shift = kCamera.fx * 0.01;
  cv::Mat moved;
  const cv::Mat M = (cv::Mat_<double>(2, 3) << 1, 0, shift, 0, 1, 0);
  cv::warpAffine(Print(1), moved, M, Print(1).size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  ObjectRecognitionOptions verify;
  verify.verify = true;
  const FrameRecognition r = RecognizeObjects(moved, *extractor, db, kCamera, verify);
  ASSERT_EQ(r.per_object.size(), 1u);
  EXPECT_GE(r.per_object[0].matches, db.features() / 2);
  ASSERT_TRUE(r.per_object[0].pose.verified);
  EXPECT_GE(r.per_object[0].pose.inliers, r.per_object[0].matches * 3 / 4);
  // The pose puts the plane where the moved camera sees it: each of its points shifted by
  // `shift` px. (A frontal plane's pose is ambiguous between a small tilt and a shift of a few
  // mm; where its points land is not.)
  const Eigen::Isometry3d& T = r.per_object[0].pose.T_cam_object;
  EXPECT_NEAR(T.translation().x(), 0.01, 5e-3);
  for (double u = 20; u < kCamera.width; u += 60)
    for (double v = 20; v < kCamera.height; v += 50) {
      const Eigen::Vector2d seen = kCamera.Project(T * kCamera.RayCam(u, v));
      EXPECT_NEAR(seen.x(), u + shift, 1.0) << u << "," << v;
      EXPECT_NEAR(seen.y(), v, 1.0) << u << "," << v;
    }
  // The database is not changed by recognising (the robot no longer learns).
  for (int h = 0; h < db.features(); ++h) ASSERT_EQ(db.Count(h, 0), 1) << h;
}

TEST(ObjectRecognition, AnotherPrintIsNotRecognised) {
  cv::Ptr<cv::Feature2D> extractor = CreateFeatureExtractor(FeatureExtractor::kMSurf);
  const FeatureDatabase db = Learn(*extractor, true);
  ObjectRecognitionOptions verify;
  verify.verify = true;
  const FrameRecognition r = RecognizeObjects(Print(3), *extractor, db, kCamera, verify);
  ASSERT_EQ(r.per_object.size(), 2u);
  for (const ObjectEvidence& e : r.per_object) {
    // Chance ratio-test matches between unrelated prints are rare; a pose never agrees.
    EXPECT_LE(e.matches, 3);
    EXPECT_FALSE(e.pose.verified);
  }
  // Print 2 itself: object 1, not object 0.
  const FrameRecognition two = RecognizeObjects(Print(2), *extractor, db, kCamera);
  EXPECT_GE(two.per_object[1].matches, 20);
  EXPECT_LE(two.per_object[0].matches, 3);
}

TEST(ObjectRecognition, ADatabaseOfAnotherWidthIsAClearError) {
  FeatureDatabase db;
  db.AddFeatures(cv::Mat::ones(3, 128, CV_32F), db.AddObject());
  cv::Ptr<cv::Feature2D> msurf = CreateFeatureExtractor(FeatureExtractor::kMSurf);
  EXPECT_THROW(RecognizeObjects(Print(1), *msurf, db, kCamera), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
