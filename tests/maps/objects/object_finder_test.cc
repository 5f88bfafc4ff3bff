#include "maps/objects/object_finder.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "maps/objects/feature_extractor.h"
#include "maps/objects/photo_object_learner.h"
#include "tests/maps/objects/blob_photo.h"

namespace novelty::objects {
namespace {

std::string Shared(const std::string& file) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  return std::string(shared ? shared : "../shared/data") + "/" + file;
}

cv::Mat Grey(const std::string& file, cv::Size size = {}) {
  cv::Mat img = cv::imread(Shared(file), cv::IMREAD_GRAYSCALE);
  if (!img.empty() && size.area() > 0) cv::resize(img, img, size, 0, 0, cv::INTER_AREA);
  return img;
}

core::PinholeCamera Camera(const cv::Size& size) {
  core::PinholeCamera c;
  c.width = size.width, c.height = size.height;
  c.fx = c.fy = std::max(size.width, size.height);
  c.cx = 0.5 * (size.width - 1), c.cy = 0.5 * (size.height - 1);
  return c;
}

// The corners of a w × h photo (pixels) mapped by `h`.
std::vector<cv::Point2f> Corners(const cv::Mat& h, int w, int hgt) {
  std::vector<cv::Point2f> c = {{0, 0},
                                {float(w - 1), 0},
                                {float(w - 1), float(hgt - 1)},
                                {0, float(hgt - 1)}},
                           out;
  cv::perspectiveTransform(c, out, h);
  return out;
}

// Real photographs: the graffiti learnt from graf1 and found in graf3, 30° of viewpoint away, its
// outline where the dataset's true homography puts graf1's corners; two other photos learnt
// beside it are not found there.
TEST(FindObjects, FindsTheGraffitiWhereTheTrueHomographyPutsIt) {
  const cv::Mat graf1 = Grey("graf/graf1.png"), graf3 = Grey("graf/graf3.png");
  cv::FileStorage fs(Shared("graf/H1to3p.xml"), cv::FileStorage::READ);
  if (graf1.empty() || graf3.empty() || !fs.isOpened())
    GTEST_SKIP() << "graf/ of the shared test data is absent";
  cv::Mat h13;
  fs["H13"] >> h13;
  auto sift = CreateFeatureExtractor(FeatureExtractor::kSift);
  FeatureDatabase db;
  PhotoObjectOptions o;
  LearnObjectFromPhoto(db, "graffiti", graf1, cv::Mat(), *sift, o);
  LearnObjectFromPhoto(db, "cards", Grey("textures/cards.png"), cv::Mat(), *sift, o);
  LearnObjectFromPhoto(db, "fruits", Grey("textures/fruits.jpg"), cv::Mat(), *sift, o);
  const std::vector<FoundObject> found =
      FindObjects(ExtractFrameFeatures(graf3, *sift), cv::Mat(), db, Camera(graf3.size()));
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].name, "graffiti");
  ASSERT_TRUE(found[0].verified);
  EXPECT_GE(found[0].inliers, 50);
  // The outline is graf1's hull (its four corners) in the plane at 1 mm a pixel: map them back
  // to graf1's pixels and through the true homography.
  ASSERT_EQ(found[0].outline.size(), db.Info(0).outline.size());
  for (std::size_t c = 0; c < found[0].outline.size(); ++c) {
    const Eigen::Vector2d p = db.Info(0).outline[c] / o.metres_per_pixel;
    std::vector<cv::Point2f> truth;
    cv::perspectiveTransform(std::vector<cv::Point2f>{{float(p.x()), float(p.y())}}, truth, h13);
    EXPECT_LT(cv::norm(found[0].outline[c] - truth[0]), 4.0)
        << "corner " << c << " at " << found[0].outline[c] << ", truth " << truth[0];
  }
  for (const FoundObject& f : found) {
    if (f.name != "graffiti") {
      EXPECT_FALSE(f.verified) << f.name;
    }
  }
  EXPECT_FALSE(found[0].place.allFinite()) << "no depth, no place";
}

// A photo pasted into another through a known homography, with a depth image: the outline where
// the homography puts the photo's corners, and the place the median of the depth's
// back-projections at the matched keypoints (all at 1.2 m).
TEST(FindObjects, OutlineAndPlaceOfAPastedPhoto) {
  const cv::Mat fruits = Grey("textures/fruits.jpg", {300, 220}),
                room = Grey("textures/building.jpg", {640, 480});
  if (fruits.empty() || room.empty()) GTEST_SKIP() << "textures/ of the shared test data is absent";
  const cv::Mat h = (cv::Mat_<double>(3, 3) << 0.75, -0.18, 220, 0.2, 0.7, 150, 1e-4, 2e-4, 1);
  const cv::Mat scene = PastePhoto(room, fruits, h);
  auto sift = CreateFeatureExtractor(FeatureExtractor::kSift);
  FeatureDatabase db;
  LearnObjectFromPhoto(db, "fruits", fruits, cv::Mat(), *sift);
  LearnObjectFromPhoto(db, "cards", Grey("textures/cards.png"), cv::Mat(), *sift);
  const core::PinholeCamera camera = Camera(scene.size());
  const cv::Mat depth(scene.size(), CV_32FC1, cv::Scalar(1.2f));
  const std::vector<FoundObject> found =
      FindObjects(ExtractFrameFeatures(scene, *sift), depth, db, camera);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].name, "fruits");
  ASSERT_TRUE(found[0].verified);
  const std::vector<cv::Point2f> truth = Corners(h, fruits.cols, fruits.rows);
  ASSERT_EQ(found[0].outline.size(), 4u);
  for (std::size_t c = 0; c < 4; ++c) {  // the outline is the photo's hull, from any corner
    double nearest = 1e9;
    for (const cv::Point2f& p : found[0].outline)
      nearest = std::min(nearest, cv::norm(p - truth[c]));
    EXPECT_LT(nearest, 2.0) << "corner " << c << " at " << truth[c];
  }
  EXPECT_FLOAT_EQ(found[0].place.z(), 1.2f);
  // x, y: within the pasted photo's back-projection at 1.2 m.
  const cv::Rect2f box = cv::boundingRect(truth);
  const Eigen::Vector3d lo = camera.Unproject(box.x, box.y, 1.2),
                        hi = camera.Unproject(box.x + box.width, box.y + box.height, 1.2);
  EXPECT_TRUE(found[0].place.x() > lo.x() && found[0].place.x() < hi.x());
  EXPECT_TRUE(found[0].place.y() > lo.y() && found[0].place.y() < hi.y());
  for (const FoundObject& f : found) {
    if (f.name != "fruits") {
      EXPECT_FALSE(f.verified) << f.name;
    }
  }
}

// Two photos of one name: listed once, with the better view.
TEST(FindObjects, OneEntryPerName) {
  const cv::Mat fruits = Grey("textures/fruits.jpg", {300, 220});
  if (fruits.empty()) GTEST_SKIP() << "textures/ of the shared test data is absent";
  auto sift = CreateFeatureExtractor(FeatureExtractor::kSift);
  FeatureDatabase db;
  cv::Mat left(fruits.size(), CV_8UC1, cv::Scalar(0)), right = left.clone();
  left(cv::Rect(0, 0, 150, 220)).setTo(255);
  right(cv::Rect(150, 0, 150, 220)).setTo(255);
  LearnObjectFromPhoto(db, "fruits", fruits, left, *sift);
  LearnObjectFromPhoto(db, "fruits", fruits, right, *sift);
  const std::vector<FoundObject> found =
      FindObjects(ExtractFrameFeatures(fruits, *sift), cv::Mat(), db, Camera(fruits.size()));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].name, "fruits");
  EXPECT_TRUE(found[0].verified);
  ObjectFinderOptions o;
  o.recognition.verify_nearest = 2;
  EXPECT_THROW(
      FindObjects(ExtractFrameFeatures(fruits, *sift), cv::Mat(), db, Camera(fruits.size()), o),
      std::invalid_argument);
  o.recognition.verify_nearest = 0;
  o.min_matches = 0;
  EXPECT_THROW(
      FindObjects(ExtractFrameFeatures(fruits, *sift), cv::Mat(), db, Camera(fruits.size()), o),
      std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
