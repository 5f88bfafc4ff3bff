#include "maps/objects/photo_object_learner.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "maps/objects/feature_extractor.h"
#include "tests/maps/objects/blob_photo.h"

namespace novelty::objects {
namespace {

cv::Mat Blobs(unsigned seed) {
  return BlobPhoto({240, 180}, seed);
}

TEST(LearnObjectFromPhoto, FeaturesLieInTheMaskAndThePlane) {
  FeatureDatabase db;
  cv::Mat mask(180, 240, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(40, 30, 120, 100)).setTo(255);
  auto sift = CreateFeatureExtractor(FeatureExtractor::kSift);
  PhotoObjectOptions o;
  o.metres_per_pixel = 0.002;
  const LearntPhoto l = LearnObjectFromPhoto(db, "blobs", Blobs(1), mask, *sift, o);
  EXPECT_EQ(l.object, 0);
  EXPECT_EQ(db.features(), l.features);
  EXPECT_GE(l.features, 12);
  EXPECT_EQ(db.DisplayName(0), "blobs");
  // The outline is the mask's rectangle, its corner at the origin: 119 × 99 px spans between
  // the outermost pixel centres, × 2 mm.
  const std::vector<Eigen::Vector2d>& outline = db.Info(0).outline;
  ASSERT_EQ(outline.size(), 4u);
  Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
  for (const Eigen::Vector2d& p : outline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  EXPECT_NEAR(lo.norm(), 0.0, 1e-12);
  EXPECT_NEAR(hi.x(), 0.238, 1e-9);
  EXPECT_NEAR(hi.y(), 0.198, 1e-9);
  // The mask selects where a keypoint was detected; SIFT's sub-pixel refinement then moves it by
  // up to half a sample of its octave (2 px at the fourth).
  const double slack = 2 * o.metres_per_pixel;
  for (int h = 0; h < db.features(); ++h) {
    const Eigen::Vector3d& p = db.Position(h);
    EXPECT_EQ(p.z(), 0.0);
    EXPECT_TRUE(p.x() >= -slack && p.x() <= 0.238 + slack && p.y() >= -slack &&
                p.y() <= 0.198 + slack)
        << "feature " << h << " at " << p.transpose() << " outside the mask";
  }
}

TEST(LearnObjectFromPhoto, RefusalsLeaveTheDatabaseAsItWas) {
  FeatureDatabase db;
  auto sift = CreateFeatureExtractor(FeatureExtractor::kSift);
  const cv::Mat photo = Blobs(2);
  const cv::Mat none(180, 240, CV_8UC1, cv::Scalar(0));
  const cv::Mat flat(180, 240, CV_8UC1, cv::Scalar(90));
  EXPECT_THROW(LearnObjectFromPhoto(db, "a", photo, none, *sift), std::invalid_argument);
  EXPECT_THROW(LearnObjectFromPhoto(db, "a", photo, cv::Mat(10, 10, CV_8UC1), *sift),
               std::invalid_argument);
  try {
    LearnObjectFromPhoto(db, "flat", flat, cv::Mat(), *sift);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("object 'flat': 0 features"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(LearnObjectFromPhoto(db, "bad\nname", photo, cv::Mat(), *sift),
               std::invalid_argument);
  EXPECT_EQ(db.objects(), 0);
  EXPECT_EQ(db.features(), 0);
  // A database of M-SURF descriptors takes no SIFT ones.
  auto msurf = CreateFeatureExtractor(FeatureExtractor::kMSurf);
  LearnObjectFromPhoto(db, "m", photo, cv::Mat(), *msurf);
  const int features = db.features();
  EXPECT_THROW(LearnObjectFromPhoto(db, "s", photo, cv::Mat(), *sift), std::invalid_argument);
  EXPECT_EQ(db.objects(), 1);
  EXPECT_EQ(db.features(), features);
}

}  // namespace
}  // namespace novelty::objects
