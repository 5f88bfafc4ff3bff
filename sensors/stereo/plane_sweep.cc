#include "sensors/stereo/plane_sweep.h"

#include <cmath>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::sensors {
namespace {

Eigen::Matrix3d Intrinsics(const core::PinholeCamera& c) {
  Eigen::Matrix3d k;
  k << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1;
  return k;
}

// RGBA with an opaque alpha, so a bilinear warp marks pixels that took anything from outside
// the image (alpha < 255).
cv::Mat WithAlpha(const cv::Mat& image) {
  cv::Mat rgba;
  cv::cvtColor(image, rgba, image.channels() == 1 ? cv::COLOR_GRAY2RGBA : cv::COLOR_RGB2RGBA);
  return rgba;
}

void CheckInput(const cv::Mat& reference, const core::PinholeCamera& camera,
                const std::vector<SweepView>& others, const PlaneSweepOptions& o) {
  camera.Check();
  if (reference.type() != CV_8UC3 && reference.type() != CV_8UC1)
    throw std::invalid_argument("plane sweep: reference image must be 8-bit RGB or grey");
  if (reference.cols != camera.width || reference.rows != camera.height)
    throw std::invalid_argument("plane sweep: reference image size differs from its intrinsics");
  if (others.empty()) throw std::invalid_argument("plane sweep: no other view to match against");
  for (size_t i = 0; i < others.size(); ++i) {
    if (others[i].image.size() != reference.size() || others[i].image.type() != reference.type())
      throw std::invalid_argument("plane sweep: view " + std::to_string(i + 1) + " is " +
                                  std::to_string(others[i].image.cols) + "×" +
                                  std::to_string(others[i].image.rows) +
                                  " or of another type than the reference image");
    others[i].camera.Check();
  }
  if (!(o.near > 0 && o.far > o.near && std::isfinite(o.far)) || o.hypotheses < 2 ||
      o.hypotheses > kMaxHypotheses)
    throw std::invalid_argument("plane sweep: need 0 < near < far and 2…" +
                                std::to_string(kMaxHypotheses) + " hypotheses");
  if (o.window < 1 || o.window > 63)
    throw std::invalid_argument("plane sweep: window must be 1…63, got " + std::to_string(o.window));
  // Cost volumes, belief propagation's messages and their pyramid hold floats per pixel and
  // hypothesis: a 1282×1110 pair with 64 hypotheses peaked at 7.5 GB, 20 volumes' worth. Bounded
  // before anything is allocated.
  const double bytes = 20.0 * 4.0 * camera.width * camera.height * o.hypotheses;
  if (bytes > kMaxVolumeBytes) {
    throw std::invalid_argument(
        "plane sweep: " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
        " with " + std::to_string(o.hypotheses) + " hypotheses needs about " +
        std::to_string(int(bytes / (1 << 20))) + " MB, over " +
        std::to_string(int(kMaxVolumeBytes / (1 << 20))) + " MB: fewer hypotheses or smaller images");
  }
}

}  // namespace

double DepthOfLabel(const PlaneSweepOptions& o, double label) {
  const double inv_near = 1.0 / o.near, inv_far = 1.0 / o.far;
  return 1.0 / (inv_near + (inv_far - inv_near) * label / (o.hypotheses - 1));
}

CostVolume PlaneSweep(const cv::Mat& reference, const core::PinholeCamera& camera,
                      const std::vector<SweepView>& others, const PlaneSweepOptions& o) {
  CheckInput(reference, camera, others, o);
  const int w = reference.cols, h = reference.rows, labels = o.hypotheses;
  const cv::Mat ref = WithAlpha(reference);
  std::vector<cv::Mat> sides;
  for (const SweepView& v : others) sides.push_back(WithAlpha(v.image));
  const Eigen::Matrix3d k_ref_inv = Intrinsics(camera).inverse();

  CostVolume volume(w, h, labels);
  cv::parallel_for_(cv::Range(0, labels), [&](const cv::Range& range) {
    cv::Mat warped, slice(h, w, CV_32F);
    for (int l = range.start; l < range.end; ++l) {
      const double depth = DepthOfLabel(o, l);
      std::vector<cv::Mat> warps;
      for (size_t i = 0; i < others.size(); ++i) {
        // Plane Z = depth of the reference camera: x_view ~ K_v (R + t e3ᵀ / depth) K_ref⁻¹ x_ref.
        const Eigen::Isometry3d view_from_ref = others[i].ref_from_view.inverse();
        Eigen::Matrix3d m = view_from_ref.linear();
        m.col(2) += view_from_ref.translation() / depth;
        const Eigen::Matrix3d hom = Intrinsics(others[i].camera) * m * k_ref_inv;
        // The map sends reference pixels to view pixels: warp with WARP_INVERSE_MAP. A rectified
        // rig (no baseline along the optical axis) gives an affine map: the cheaper warp.
        const bool affine = std::abs(hom(2, 0)) < 1e-12 && std::abs(hom(2, 1)) < 1e-12;
        cv::Mat hcv(affine ? 2 : 3, 3, CV_64F);
        for (int r = 0; r < hcv.rows; ++r)
          for (int c = 0; c < 3; ++c) hcv.at<double>(r, c) = hom(r, c) / hom(2, 2);
        const int flags = cv::INTER_LINEAR | cv::WARP_INVERSE_MAP;
        if (affine)
          cv::warpAffine(sides[i], warped, hcv, ref.size(), flags, cv::BORDER_CONSTANT,
                         cv::Scalar::all(0));
        else
          cv::warpPerspective(sides[i], warped, hcv, ref.size(), flags, cv::BORDER_CONSTANT,
                              cv::Scalar::all(0));
        warps.push_back(warped.clone());
      }
      for (int y = 0; y < h; ++y) {
        const cv::Vec4b* r = ref.ptr<cv::Vec4b>(y);
        float* out = slice.ptr<float>(y);
        for (int x = 0; x < w; ++x) {
          float best = o.truncation;
          for (const cv::Mat& side : warps) {
            const cv::Vec4b s = side.ptr<cv::Vec4b>(y)[x];
            if (s[3] != 255) continue;  // (partly) outside this view
            // Σ|ΔRGB| (a grey image was replicated into three channels: the same scale).
            const float d = float(std::abs(r[x][0] - s[0]) + std::abs(r[x][1] - s[1]) +
                                  std::abs(r[x][2] - s[2]));
            best = std::min(best, d);
          }
          out[x] = best;
        }
      }
      cv::Mat out(h, w, CV_32F, volume.slice(l));
      if (o.window > 1) {
        cv::blur(slice, out, cv::Size(o.window, o.window));
      } else {
        slice.copyTo(out);
      }
    }
  });
  return volume;
}

}  // namespace novelty::sensors
