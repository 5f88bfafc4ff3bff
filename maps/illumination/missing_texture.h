// How much of the invariant image's texture a frame no longer shows. In the log domain a frame
// is i = r + l (eq. 6.5): lighting adds l, whose gradients — smooth shading, shadow and highlight
// borders — are not aligned with r's, so the frame's gradients still contain r's. An object
// put on a textured surface replaces r: there the frame's gradients no longer project onto r̂'s.
// Per pixel, over a block, the energy of r̂'s gradient that the frame's gradient lacks:
//   m = max(0, Σ|∇r̂|² - Σ ∇i·∇r̂) / N
// (per colour channel, summed). Lighting leaves m near 0 except where it clips the image (black
// shadows, saturated highlights); on plain surfaces m is 0 whatever happens.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::illumination {

/// Largest block a map accepts (from options and from files): 99 × 99 pixels.
inline constexpr int kMaxTextureBlock = 99;

struct MissingTextureOptions {
  /// Side of the square block (odd) over which the energies are summed.
  int block = 7;
};

/// (Σ|∇r̂|² - Σ ∇i·∇r̂) / N without the max: negative where the frame has more of r̂'s texture
/// than r̂ (stronger contrast). Arguments and errors as MissingTexture's.
cv::Mat TextureChange(const cv::Mat& log_image, const cv::Mat& log_invariant,
                      const cv::Mat& covered = cv::Mat(),
                      const MissingTextureOptions& options = {});

/// Σ|∇x|² / N over the block (per channel, summed): the texture energy of a log image. Arguments
/// and errors as MissingTexture's.
cv::Mat GradientEnergy(const cv::Mat& log_image, const cv::Mat& covered = cv::Mat(),
                       const MissingTextureOptions& options = {});

/// `log_image`: the frame's clipped log image (LogIllumination + r̂), `log_invariant`: r̂, both
/// CV_32FC1 or CV_32FC3 of one size; `covered`: CV_8UC1, r̂'s coverage (empty: all). Returns m,
/// CV_32FC1, 0 where a gradient's support leaves the covered pixels.
cv::Mat MissingTexture(const cv::Mat& log_image, const cv::Mat& log_invariant,
                       const cv::Mat& covered = cv::Mat(),
                       const MissingTextureOptions& options = {});

/// The share of r̂'s texture the frame lacks, m / (Σ|∇r̂|² / N + floor), in [-1, 1] (negative: more
/// contrast than r̂; below -1 and above 1 only where the frame reverses r̂'s contrast, which is
/// not more hidden than all of it). `floor` > 0, an energy: where r̂'s texture is weaker than it
/// nothing can be hidden.
cv::Mat HiddenTextureShare(const cv::Mat& log_image, const cv::Mat& log_invariant,
                           const cv::Mat& covered, double floor,
                           const MissingTextureOptions& options = {});

}  // namespace novelty::illumination
