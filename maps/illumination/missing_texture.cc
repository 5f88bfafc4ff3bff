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

struct Gradients {
  cv::Mat x, y;  // Sobel / 8, the channels of the image
};

Gradients GradientsOf(const cv::Mat& a) {
  Gradients g;
  cv::Sobel(a, g.x, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(a, g.y, CV_32F, 0, 1, 3, 1.0 / 8);
  return g;
}

// 255 where a pixel's 3×3 support lies in `covered` (a gradient reaching outside would compare
// against the 0 there); empty when everything is covered. The image border is not a coverage
// border (Sobel reflects there): an all-covered mask equals none.
cv::Mat Inside(const cv::Mat& covered) {
  cv::Mat inside;
  if (!covered.empty()) cv::erode(covered, inside, cv::Mat(), {-1, -1}, 1, cv::BORDER_REPLICATE);
  return inside;
}

// The block mean of Σ over the channels of ∇a·∇b, counting only pixels `inside`.
cv::Mat BlockDot(const Gradients& a, const Gradients& b, const cv::Mat& inside, int block) {
  cv::Mat dot = a.x.mul(b.x) + a.y.mul(b.y);
  if (dot.channels() > 1) {
    const int rows = dot.rows;
    dot = dot.reshape(1, int(dot.total()));
    cv::reduce(dot, dot, 1, cv::REDUCE_SUM);
    dot = dot.reshape(1, rows);
  }
  if (!inside.empty()) dot.setTo(0.0f, inside == 0);
  cv::boxFilter(dot, dot, CV_32F, {block, block});
  return dot;
}

// Σ|∇r̂|² / N and Σ ∇i·∇r̂ / N.
struct BlockEnergies {
  cv::Mat invariant, cross;
};

BlockEnergies Energies(const cv::Mat& log_image, const cv::Mat& log_invariant,
                       const cv::Mat& covered, const MissingTextureOptions& options) {
  Check(log_image, log_invariant, covered, options);
  const cv::Mat inside = Inside(covered);
  const Gradients r = GradientsOf(log_invariant), i = GradientsOf(log_image);
  return {BlockDot(r, r, inside, options.block), BlockDot(i, r, inside, options.block)};
}

}  // namespace

cv::Mat TextureChange(const cv::Mat& log_image, const cv::Mat& log_invariant,
                      const cv::Mat& covered, const MissingTextureOptions& options) {
  const BlockEnergies e = Energies(log_image, log_invariant, covered, options);
  return e.invariant - e.cross;
}

cv::Mat GradientEnergy(const cv::Mat& log_image, const cv::Mat& covered,
                       const MissingTextureOptions& options) {
  Check(log_image, log_image, covered, options);
  const Gradients g = GradientsOf(log_image);
  return BlockDot(g, g, Inside(covered), options.block);
}

cv::Mat MissingTexture(const cv::Mat& log_image, const cv::Mat& log_invariant,
                       const cv::Mat& covered, const MissingTextureOptions& options) {
  return cv::max(TextureChange(log_image, log_invariant, covered, options), 0.0f);
}

cv::Mat HiddenTextureShare(const cv::Mat& log_image, const cv::Mat& log_invariant,
                           const cv::Mat& covered, double floor,
                           const MissingTextureOptions& options) {
  if (!(floor > 0.0)) throw std::invalid_argument("HiddenTextureShare: the floor must be > 0");
  const BlockEnergies e = Energies(log_image, log_invariant, covered, options);
  cv::Mat share;
  cv::divide(e.invariant - e.cross, e.invariant + floor, share);
  return cv::min(cv::max(share, -1.0f), 1.0f);
}

}  // namespace novelty::illumination
