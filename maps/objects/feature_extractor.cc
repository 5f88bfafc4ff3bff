#include "maps/objects/feature_extractor.h"

#include <iterator>
#include <stdexcept>

#include "maps/objects/msurf.h"

namespace novelty::objects {
namespace {

struct Extractor {
  int width;
  double window_per_size;
  int window_angle_sign;
};

// In FeatureExtractor's order.
constexpr Extractor kExtractors[] = {{64, 2.4, 1}, {128, 6.0, -1}, {64, 12.0, 1}};

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

int DescriptorWidth(FeatureExtractor e) { return Of(e).width; }

double DescriptorWindowPerSize(FeatureExtractor e) { return Of(e).window_per_size; }

int DescriptorWindowAngleSign(FeatureExtractor e) { return Of(e).window_angle_sign; }

}  // namespace novelty::objects
