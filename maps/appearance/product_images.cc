#include "maps/appearance/product_images.h"

#include <cstdio>

#include "core/false_color.h"

namespace novelty::appearance {

namespace {

cv::Mat Picture(const cv::Mat& product, double max_value, bool log_scale = false) {
  return product.empty() ? cv::Mat() : core::FalseColor(product, max_value, log_scale);
}

std::string Caption(const char* name, double max_value, const char* how = "") {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s (%s0-%g)", name, how, max_value);
  return buf;
}

}  // namespace

cv::Mat SurpriseImage(const AppearanceProducts& p, const ProductScales& scales) {
  return Picture(p.surprise, scales.surprise);
}
cv::Mat UncertaintyImage(const AppearanceProducts& p, const ProductScales& scales) {
  return Picture(p.uncertainty, scales.uncertainty, true);
}
cv::Mat DifferenceImage(const DifferencingProducts& p, const ProductScales& scales) {
  return Picture(p.difference, scales.differencing);
}

std::string SurpriseCaption(const ProductScales& scales) {
  return Caption("surprise", scales.surprise);
}
std::string UncertaintyCaption(const ProductScales& scales) {
  return Caption("uncertainty", scales.uncertainty, "log, ");
}
std::string DifferenceCaption(const ProductScales& scales) {
  return Caption("differencing", scales.differencing);
}

}  // namespace novelty::appearance
