#include "maps/appearance/prior_alignment.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace novelty::appearance {

namespace {

void CheckOptions(const PriorAlignmentOptions& o) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("PriorAlignmentOptions: " + what);
  };
  if (o.max_iterations < 1) fail("max_iterations must be >= 1");
  if (!(o.blur_sigma_px >= 0.0 && std::isfinite(o.blur_sigma_px)))
    fail("blur_sigma_px must be >= 0");
  if (!(o.huber_levels > 0.0 && std::isfinite(o.huber_levels))) fail("huber_levels must be > 0");
  if (!(o.max_rotation_rad > 0.0 && o.max_rotation_rad < 0.5))
    fail("max_rotation_rad must be in (0, 0.5)");
  if (!(o.min_gradient >= 0.0 && std::isfinite(o.min_gradient))) fail("min_gradient must be >= 0");
  if (o.min_pixels < 4) fail("min_pixels must be >= 4");
  if (!(o.converged_px > 0.0)) fail("converged_px must be > 0");
}

cv::Mat Blurred(const cv::Mat& m, double sigma) {
  if (sigma == 0.0) return m.clone();
  cv::Mat out;
  cv::GaussianBlur(m, out, cv::Size(), sigma, sigma, cv::BORDER_REPLICATE);
  return out;
}

// x ↦ K·R(ω)·K⁻¹·x, the image motion of a pure camera rotation.
cv::Matx33d RotationHomography(const core::PinholeCamera& c, const Eigen::Vector3d& omega) {
  Eigen::Matrix3d K;
  K << c.fx, 0.0, c.cx, 0.0, c.fy, c.cy, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d H = K * RotationFromVector(omega) * K.inverse();
  cv::Matx33d h;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) h(r, k) = H(r, k);
  return h;
}

// d(u, v)/dω at ω = 0: how the normalised image point (u, v) of a ray moves under a small
// camera rotation ω, whatever the ray's depth.
Eigen::Matrix<double, 2, 3> RotationMotion(double u, double v) {
  Eigen::Matrix<double, 2, 3> m;
  m << -u * v, 1.0 + u * u, -v, -(1.0 + v * v), u * v, u;
  return m;
}

// The largest motion (px) a rotation by `step` gives a pixel of the frame: at its corners, to first
// order (the rotation's image motion grows towards the border).
double LargestMotionPx(const core::PinholeCamera& c, const Eigen::Vector3d& step) {
  double largest = 0.0;
  for (double x : {0.0, c.width - 1.0})
    for (double y : {0.0, c.height - 1.0}) {
      const Eigen::Vector2d d = RotationMotion((x - c.cx) / c.fx, (y - c.cy) / c.fy) * step;
      largest = std::max(largest, std::hypot(c.fx * d.x(), c.fy * d.y()));
    }
  return largest;
}

using Matrix5d = Eigen::Matrix<double, 5, 5>;
using Vector5d = Eigen::Matrix<double, 5, 1>;

// Gauss-Newton's normal equations in (ω, gain, bias) for r = gain·warped + bias − frame, Huber
// weighted, over the covered pixels; `textured` counts those textured in prior and frame.
struct NormalEquations {
  Matrix5d A = Matrix5d::Zero();
  Vector5d g = Vector5d::Zero();
  int textured = 0;
};

NormalEquations Accumulate(const cv::Mat& warped, const cv::Mat& warped_mask, const cv::Mat& frame,
                           const cv::Mat& frame_textured, const core::PinholeCamera& camera,
                           double gain, double bias, const PriorAlignmentOptions& options) {
  cv::Mat gx, gy;
  cv::Sobel(warped, gx, CV_32F, 1, 0, 1, 0.5);  // central differences
  cv::Sobel(warped, gy, CV_32F, 0, 1, 1, 0.5);
  NormalEquations n;
  const float min_g2 = float(options.min_gradient * options.min_gradient);
  for (int y = 1; y + 1 < warped.rows; ++y) {
    const float* w = warped.ptr<float>(y);
    const float* f = frame.ptr<float>(y);
    const float* dx = gx.ptr<float>(y);
    const float* dy = gy.ptr<float>(y);
    const uchar* m = warped_mask.ptr<uchar>(y);
    const uchar* ft = frame_textured.ptr<uchar>(y);
    const double v = (y - camera.cy) / camera.fy;
    for (int x = 1; x + 1 < warped.cols; ++x) {
      if (!m[x]) continue;
      const double u = (x - camera.cx) / camera.fx;
      // The intensity's gradient (per unit of u, v) times the pixel's motion under ω.
      const Eigen::RowVector2d i(gain * dx[x] * camera.fx, gain * dy[x] * camera.fy);
      Vector5d J;
      J << (i * RotationMotion(u, v)).transpose(), double(w[x]), 1.0;
      const double r = gain * double(w[x]) + bias - double(f[x]);
      const double wt =
          std::abs(r) <= options.huber_levels ? 1.0 : options.huber_levels / std::abs(r);
      n.A.noalias() += wt * J * J.transpose();
      n.g.noalias() += wt * r * J;
      if (ft[x] && dx[x] * dx[x] + dy[x] * dy[x] >= min_g2) ++n.textured;
    }
  }
  return n;
}

}  // namespace

Eigen::Matrix3d RotationFromVector(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

PriorAlignment AlignRotationToPrior(const cv::Mat& observed_y, const cv::Mat& prior_y,
                                    const core::PinholeCamera& camera,
                                    const PriorAlignmentOptions& options) {
  CheckOptions(options);
  const cv::Size size(camera.width, camera.height);
  if (observed_y.type() != CV_32FC1 || prior_y.type() != CV_32FC1 || observed_y.size() != size ||
      prior_y.size() != size)
    throw std::invalid_argument(
        "AlignRotationToPrior: the planes must be CV_32FC1 of the camera's size");

  // Covered pixels, away from the uncovered ones by the blur's reach (their fill is no colour).
  cv::Mat covered = prior_y == prior_y;  // false for NaN
  cv::Mat prior_filled = prior_y.clone();
  prior_filled.setTo(0.0f, ~covered);
  const int reach = int(std::ceil(3.0 * options.blur_sigma_px)) + 1;
  cv::erode(covered, covered,
            cv::getStructuringElement(cv::MORPH_RECT, {2 * reach + 1, 2 * reach + 1}));
  const cv::Mat prior = Blurred(prior_filled, options.blur_sigma_px);
  const cv::Mat frame = Blurred(observed_y, options.blur_sigma_px);

  // Where the frame has texture: a pixel textured in the prior alone tells nothing of a rotation.
  cv::Mat fx_grad, fy_grad, frame_textured;
  cv::Sobel(frame, fx_grad, CV_32F, 1, 0, 1, 0.5);
  cv::Sobel(frame, fy_grad, CV_32F, 0, 1, 1, 0.5);
  cv::magnitude(fx_grad, fy_grad, frame_textured);
  frame_textured = frame_textured >= options.min_gradient;

  PriorAlignment out;
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  double gain = 1.0, bias = 0.0;
  cv::Mat warped, warped_mask;
  for (int it = 0; it < options.max_iterations; ++it) {
    // warped(x) = prior(H·x): the prior as the rotated camera would see it.
    const cv::Matx33d H = RotationHomography(camera, omega);
    cv::warpPerspective(prior, warped, H, size, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                        cv::BORDER_REPLICATE);
    cv::warpPerspective(covered, warped_mask, H, size, cv::INTER_NEAREST | cv::WARP_INVERSE_MAP,
                        cv::BORDER_CONSTANT, 0);
    const NormalEquations n =
        Accumulate(warped, warped_mask, frame, frame_textured, camera, gain, bias, options);
    out.pixels = n.textured;
    out.iterations = it + 1;
    // Refused (out.aligned false, no rotation): too little texture to tell a rotation, a solve
    // that fails or flips the colours, too large a rotation or no convergence — an unrelated
    // scene rather than a small pose error.
    if (n.textured < options.min_pixels) return out;
    const Vector5d step = -n.A.ldlt().solve(n.g);
    if (!step.allFinite() || !(gain + step[3] > 0.0)) return out;
    omega += step.head<3>();
    gain += step[3];
    bias += step[4];
    if (omega.norm() > options.max_rotation_rad) return out;
    if (LargestMotionPx(camera, step.head<3>()) < options.converged_px) {
      out.aligned = true;
      out.rotation = omega;
      return out;
    }
  }
  return out;
}

}  // namespace novelty::appearance
