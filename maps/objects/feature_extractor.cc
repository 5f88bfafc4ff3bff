#include "maps/objects/feature_extractor.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "maps/objects/msurf.h"

namespace novelty::objects {
namespace {

struct Extractor {
  int width;
  double window_per_size;
  int window_angle_sign;
  bool searches_near_mask;  // pays only for the mask's surroundings on the whole image
};

// In FeatureExtractor's order.
constexpr Extractor kExtractors[] = {
    {64, 2.4, 1, true}, {128, 6.0, -1, false}, {64, 12.0, 1, false}};

const Extractor& Of(FeatureExtractor e) {
  const int i = int(e);
  if (i < 0 || i >= int(std::size(kExtractors)))
    throw std::invalid_argument("feature extractor " + std::to_string(i) +
                                ": expected 0 (msurf), 1 (sift) or 2 (akaze)");
  return kExtractors[i];
}

}  // namespace

const std::vector<std::string>& FeatureExtractorNames() {
  static const std::vector<std::string> names = {"msurf", "sift", "akaze"};
  return names;
}

const std::string& FeatureExtractorName(FeatureExtractor e) {
  Of(e);
  return FeatureExtractorNames()[std::size_t(e)];
}

FeatureExtractor ParseFeatureExtractor(const std::string& name) {
  const std::vector<std::string>& names = FeatureExtractorNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (name == names[i]) return FeatureExtractor(i);
  throw std::invalid_argument("feature extractor '" + name +
                              "': expected one of msurf, sift, akaze");
}

cv::Ptr<cv::Feature2D> CreateFeatureExtractor(FeatureExtractor e) {
  Of(e);
  switch (e) {
    case FeatureExtractor::kMSurf:
      return MSurf::create();
    case FeatureExtractor::kSift:
      return cv::SIFT::create();
    case FeatureExtractor::kAkaze:
      break;
  }
  return cv::AKAZE::create(cv::AKAZE::DESCRIPTOR_KAZE);
}

namespace {

// Whether the descriptor window of `k` (side window_per_size · size, turned by its angle; any
// angle when it has none) lies inside `crop` (in the crop's coordinates), or leaves it only where
// the image ends too.
bool WindowInCrop(const cv::KeyPoint& k, double window_per_size, const cv::Rect& crop,
                  const cv::Size& image) {
  const double a = k.angle * CV_PI / 180.0;
  const double turn = k.angle < 0 ? std::sqrt(2.0) : std::abs(std::cos(a)) + std::abs(std::sin(a));
  const double h = 0.5 * window_per_size * k.size * turn;  // half the window's extent along x, y
  return (k.pt.x - h >= 0 || crop.x == 0) && (k.pt.y - h >= 0 || crop.y == 0) &&
         (k.pt.x + h <= crop.width || crop.br().x == image.width) &&
         (k.pt.y + h <= crop.height || crop.br().y == image.height);
}

}  // namespace

void DetectAndComputeInBox(FeatureExtractor e, cv::Feature2D& f, const cv::Mat& rgb,
                           const cv::Rect& box, int margin, std::vector<cv::KeyPoint>& keypoints,
                           cv::Mat& descriptors) {
  const Extractor& x = Of(e);
  const cv::Rect image(0, 0, rgb.cols, rgb.rows);
  if (rgb.type() != CV_8UC3)
    throw std::invalid_argument("DetectAndComputeInBox: the image must be CV_8UC3, is type " +
                                std::to_string(rgb.type()));
  if (box.empty() || (box & image) != box)
    throw std::invalid_argument("DetectAndComputeInBox: the box is empty or not inside the " +
                                std::to_string(rgb.cols) + "x" + std::to_string(rgb.rows) +
                                " image");
  cv::Rect crop = image;
  if (margin >= 0 && !x.searches_near_mask) {
    constexpr int kAlign = 8;  // SIFT halves the image per octave: octaves to 1/8 line up
    margin = std::min(margin, std::max(rgb.cols, rgb.rows));
    const int x0 = std::max(0, box.x - margin) / kAlign * kAlign;
    const int y0 = std::max(0, box.y - margin) / kAlign * kAlign;
    crop = cv::Rect(cv::Point(x0, y0), box.br() + cv::Point(margin, margin)) & image;
  }
  cv::Mat grey, mask = cv::Mat::zeros(crop.size(), CV_8UC1);
  cv::cvtColor(rgb(crop), grey, cv::COLOR_RGB2GRAY);
  mask(box - crop.tl()).setTo(255);
  std::vector<cv::KeyPoint> found;
  cv::Mat all;
  f.detectAndCompute(grey, mask, found, all);
  keypoints.clear();
  descriptors = cv::Mat(0, all.cols, all.type());
  for (std::size_t i = 0; i < found.size(); ++i) {
    if (!WindowInCrop(found[i], x.window_per_size, crop, rgb.size())) continue;
    keypoints.push_back(found[i]);
    keypoints.back().pt += cv::Point2f(crop.tl());
    descriptors.push_back(all.row(int(i)));
  }
}

int DescriptorWidth(FeatureExtractor e) { return Of(e).width; }

double DescriptorWindowPerSize(FeatureExtractor e) { return Of(e).window_per_size; }

int DescriptorWindowAngleSign(FeatureExtractor e) { return Of(e).window_angle_sign; }

}  // namespace novelty::objects
