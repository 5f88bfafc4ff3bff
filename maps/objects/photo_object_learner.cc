#include "maps/objects/photo_object_learner.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace novelty::objects {

namespace {

// The mask's convex hull, simplified to at most FeatureDatabase::kMaxOutline corners, in pixels.
std::vector<cv::Point> Outline(const cv::Mat& mask) {
  std::vector<cv::Point> set, hull;
  cv::findNonZero(mask, set);
  cv::convexHull(set, hull);
  for (double epsilon = 0.5; hull.size() > FeatureDatabase::kMaxOutline; epsilon *= 2) {
    std::vector<cv::Point> fewer;
    cv::approxPolyDP(hull, fewer, epsilon, true);
    hull = fewer;
  }
  if (hull.size() < 3) {  // a line or a point of pixels: its box, one pixel wide at least
    const cv::Rect b = cv::boundingRect(set);
    hull = {b.tl(), {b.x + b.width, b.y}, b.br(), {b.x, b.y + b.height}};
  }
  return hull;
}

}  // namespace

LearntPhoto LearnObjectFromPhoto(FeatureDatabase& database, const std::string& name,
                                 const cv::Mat& image, const cv::Mat& mask,
                                 cv::Feature2D& extractor, const PhotoObjectOptions& options) {
  const auto fail = [&](const std::string& what) {
    throw std::invalid_argument("object '" + name + "': " + what);
  };
  if (image.type() != CV_8UC1 && image.type() != CV_8UC3)
    fail("the image is not 8-bit grey or BGR");
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != image.size()))
    fail("the mask is not an 8-bit grey image of the photo's size");
  if (!(std::isfinite(options.metres_per_pixel) && options.metres_per_pixel > 0))
    fail("metres_per_pixel must be positive");
  const cv::Mat area = mask.empty() ? cv::Mat(image.size(), CV_8UC1, cv::Scalar(255)) : mask;
  if (cv::countNonZero(area) == 0) fail("the mask selects no pixel");
  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor.detectAndCompute(grey, area, keypoints, descriptors);
  if (int(keypoints.size()) < options.min_features)
    fail(std::to_string(keypoints.size()) + " features, fewer than the " +
         std::to_string(options.min_features) + " an object needs");
  if (descriptors.type() != CV_32F) descriptors.convertTo(descriptors, CV_32F);

  const std::vector<cv::Point> hull = Outline(area);
  const cv::Rect box = cv::boundingRect(hull);
  const double s = options.metres_per_pixel;
  const auto plane = [&](double u, double v) {
    return Eigen::Vector2d((u - box.x) * s, (v - box.y) * s);
  };
  ObjectInfo info;
  info.name = name;
  for (const cv::Point& p : hull) info.outline.push_back(plane(p.x, p.y));
  std::vector<Eigen::Vector3d> places;
  for (const cv::KeyPoint& k : keypoints) {
    const Eigen::Vector2d p = plane(k.pt.x, k.pt.y);
    places.emplace_back(p.x(), p.y(), 0.0);  // the photo's plane is the object's z = 0
  }
  // Checked before the object is added, so that a failure leaves the database as it was.
  if (database.features() > 0 && descriptors.cols != database.descriptors().cols)
    fail("descriptors of width " + std::to_string(descriptors.cols) + ", the database's are " +
         std::to_string(database.descriptors().cols));
  LearntPhoto learnt;
  learnt.object = database.AddObject(info);
  database.AddFeatures(descriptors, learnt.object, places);
  learnt.features = int(keypoints.size());
  return learnt;
}

}  // namespace novelty::objects
