#include "maps/illumination/lighting_threshold.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace novelty::illumination {

HeldOutNovelty HeldOutLightingNovelty(const std::vector<cv::Mat>& images,
                                      const std::vector<cv::Mat>& coverage,
                                      const InvariantImageOptions& invariant,
                                      const IlluminationModelOptions& model,
                                      const IlluminationNoveltyOptions& novelty,
                                      const ZernikeMoments& zernike) {
  const int m_count = int(images.size());
  if (m_count - 1 < std::max(2, invariant.min_lightings))
    throw std::invalid_argument(
        "leave one lighting out: " + std::to_string(m_count) + " lightings leave " +
        std::to_string(m_count - 1) + ", fewer than min_lightings " +
        std::to_string(std::max(2, invariant.min_lightings)) + " (acquire one lighting more)");
  if (!coverage.empty() && coverage.size() != images.size())
    throw std::invalid_argument("leave one lighting out: " + std::to_string(coverage.size()) +
                                " coverage masks for " + std::to_string(m_count) + " lightings");
  HeldOutNovelty out;
  for (int held = 0; held < m_count; ++held) {
    std::vector<cv::Mat> rest, rest_coverage;
    for (int m = 0; m < m_count; ++m) {
      if (m == held) continue;
      rest.push_back(images[std::size_t(m)]);
      if (!coverage.empty()) rest_coverage.push_back(coverage[std::size_t(m)]);
    }
    InvariantImage inv = ComputeInvariantImage(rest, rest_coverage, invariant);
    IlluminationModel learnt = LearnIlluminationModel(inv, rest_coverage, model);
    // Judged only where the held-out lighting has an image: elsewhere its black would make
    // regions of its own and move ê for the rest (a frame is judged where the map covers it).
    if (!coverage.empty()) inv.covered &= coverage[std::size_t(held)] != 0;
    const ViewpointIllumination viewpoint =
        MakeViewpoint(inv, std::move(learnt), novelty.min_region_pixels, &zernike);
    const IlluminationNovelty n =
        DetectIlluminationNovelty(images[std::size_t(held)], viewpoint, zernike, novelty);
    const cv::Mat& judged = viewpoint.covered;
    std::vector<float>& mine = out.per_lighting.emplace_back();
    for (int y = 0; y < judged.rows; ++y)
      for (int x = 0; x < judged.cols; ++x)
        if (judged.at<uchar>(y, x)) mine.push_back(n.novelty.at<float>(y, x));
    out.values.insert(out.values.end(), mine.begin(), mine.end());
  }
  return out;
}

double ThresholdAtFalseAlarmRate(std::vector<float> values, double rate) {
  if (values.empty()) throw std::invalid_argument("a false-alarm threshold needs values");
  if (!(rate > 0.0 && rate < 1.0))
    throw std::invalid_argument("false_alarm_rate must be in (0, 1), got " + std::to_string(rate));
  // At most floor(rate · n) values may lie above τ: τ is the value of rank n − 1 − that.
  const std::size_t above = std::size_t(std::floor(rate * double(values.size())));
  const auto k = values.begin() + long(values.size() - 1 - std::min(above, values.size() - 1));
  std::nth_element(values.begin(), k, values.end());
  return *k;
}

double ShareAbove(const std::vector<float>& values, double threshold) {
  if (values.empty()) return 0.0;
  const auto n =
      std::count_if(values.begin(), values.end(), [threshold](float v) { return v > threshold; });
  return double(n) / double(values.size());
}

}  // namespace novelty::illumination
