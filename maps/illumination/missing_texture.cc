#include "maps/illumination/missing_texture.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::illumination {

namespace {

void Check(const cv::Mat& a, const cv::Mat& b, const cv::Mat& covered,
           const MissingTextureOptions& options) {
  if (a.empty() || a.size() != b.size() || a.type() != b.type() || a.depth() != CV_32F)
    throw std::invalid_argument(
        "MissingTexture: the log images must be float images of one size and type");
  if (!covered.empty() && (covered.size() != a.size() || covered.type() != CV_8UC1))
    throw std::invalid_argument("MissingTexture: the coverage must be CV_8UC1 of the image's size");
  if (options.block < 1 || options.block % 2 == 0)
    throw std::invalid_argument("MissingTexture: block must be odd and >= 1");
}

// Σ over the channels of ∇a·∇b (Sobel / 8), 0 where the 3×3 support leaves `covered` (it would
// compare against the 0 outside).
cv::Mat GradientDot(const cv::Mat& a, const cv::Mat& b, const cv::Mat& covered) {
  cv::Mat ax, ay, bx, by;
  cv::Sobel(a, ax, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(a, ay, CV_32F, 0, 1, 3, 1.0 / 8);
  cv::Sobel(b, bx, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(b, by, CV_32F, 0, 1, 3, 1.0 / 8);
  cv::Mat dot = ax.mul(bx) + ay.mul(by);
  if (dot.channels() > 1) {
    dot = dot.reshape(1, int(dot.total()));
    cv::reduce(dot, dot, 1, cv::REDUCE_SUM);
    dot = dot.reshape(1, a.rows);
  }
  if (!covered.empty()) {
    cv::Mat inside;
    cv::erode(covered, inside, cv::Mat(), {-1, -1}, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    dot.setTo(0.0f, inside == 0);
  }
  return dot;
}

cv::Mat BlockMean(const cv::Mat& values, int block) {
  cv::Mat out;
  cv::boxFilter(values, out, CV_32F, {block, block});
  return out;
}

}  // namespace

cv::Mat TextureChange(const cv::Mat& log_image, const cv::Mat& log_invariant,
                      const cv::Mat& covered, const MissingTextureOptions& options) {
  Check(log_image, log_invariant, covered, options);
  return BlockMean(GradientDot(log_invariant, log_invariant, covered) -
                       GradientDot(log_image, log_invariant, covered),
                   options.block);
}

cv::Mat GradientEnergy(const cv::Mat& log_image, const cv::Mat& covered,
                       const MissingTextureOptions& options) {
  Check(log_image, log_image, covered, options);
  return BlockMean(GradientDot(log_image, log_image, covered), options.block);
}

cv::Mat MissingTexture(const cv::Mat& log_image, const cv::Mat& log_invariant,
                       const cv::Mat& covered, const MissingTextureOptions& options) {
  return cv::max(TextureChange(log_image, log_invariant, covered, options), 0.0f);
}

cv::Mat HiddenTextureShare(const cv::Mat& log_image, const cv::Mat& log_invariant,
                           const cv::Mat& covered, double floor,
                           const MissingTextureOptions& options) {
  if (!(floor > 0.0)) throw std::invalid_argument("HiddenTextureShare: the floor must be > 0");
  cv::Mat share;
  cv::divide(TextureChange(log_image, log_invariant, covered, options),
             GradientEnergy(log_invariant, covered, options) + floor, share);
  return cv::min(cv::max(share, -1.0f), 1.0f);
}

}  // namespace novelty::illumination
