#include "sensors/localization/photometric_alignment.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "sensors/localization/bilinear_sample.h"

namespace novelty::sensors {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

core::PinholeCamera AtLevel(core::PinholeCamera c, int level) {
  const double s = std::ldexp(1.0, -level);
  c.fx *= s, c.fy *= s, c.cx *= s, c.cy *= s;
  c.width = int(std::ceil(c.width * s)), c.height = int(std::ceil(c.height * s));
  return c;
}

// exp(ξ) for ξ = (v, ω): rotation by Rodrigues, translation v (first order, enough for the
// small steps of Gauss–Newton).
Eigen::Isometry3d Exp(const Vector6d& xi) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d w = xi.tail<3>();
  if (w.norm() > 1e-12) t.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
  t.translation() = xi.head<3>();
  return t;
}

struct Normal {
  Matrix6d h = Matrix6d::Zero();
  Vector6d b = Vector6d::Zero();
  double cost = 0;
  int visible = 0;    // points inside the first (reference) view
  int residuals = 0;  // over all views
  int inliers = 0;
  int textured = 0;
  double sq = 0;
};

// Adds the Huber-weighted residuals of `points` (T·p in the reference camera) seen in one view
// at one pyramid level to the normal equations of T ← exp(ξ)·T.
void Accumulate(const std::vector<Eigen::Vector3d>& points, const std::vector<float>& reference,
                const cv::Mat& image, const cv::Mat& gx, const cv::Mat& gy,
                const core::PinholeCamera& c, const Eigen::Isometry3d& view_from_reference,
                const Eigen::Isometry3d& t, double huber, double textured_gradient,
                bool count_visible, Normal& n) {
  const float max_x = float(image.cols - 2), max_y = float(image.rows - 2);
  const Eigen::Matrix3d r_vt = view_from_reference.linear().transpose();
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d q = t * points[i];  // reference camera
    const Eigen::Vector3d p = view_from_reference * q;
    if (p.z() <= 1e-3) continue;
    const double iz = 1.0 / p.z();
    const float u = float(c.fx * p.x() * iz + c.cx), v = float(c.fy * p.y() * iz + c.cy);
    if (!(u >= 1 && v >= 1 && u < max_x && v < max_y)) continue;
    const double r = SampleBilinear(image, u, v) - reference[i];
    const double gu = SampleBilinear(gx, u, v), gv = SampleBilinear(gy, u, v);
    // ∂I/∂p through the projection, rotated back into the reference camera, then
    // ∂q/∂ξ = [I | −[q]×] for T ← exp(ξ)·T.
    const Eigen::Vector3d dq =
        r_vt * Eigen::Vector3d(gu * c.fx * iz, gv * c.fy * iz,
                               -(gu * c.fx * p.x() + gv * c.fy * p.y()) * iz * iz);
    Vector6d j;
    j << dq, q.cross(dq);
    const double a = std::abs(r);
    const double w = a <= huber ? 1.0 : huber / a;
    n.h.selfadjointView<Eigen::Upper>().rankUpdate(j, w);
    n.b += w * r * j;
    n.cost += a <= huber ? 0.5 * r * r : huber * (a - 0.5 * huber);
    n.sq += r * r;
    ++n.residuals;
    if (count_visible) ++n.visible;
    n.inliers += a <= huber;
    n.textured += gu * gu + gv * gv >= textured_gradient * textured_gradient;
  }
}

// The normal equations over all views at level `l`.
Normal AccumulateViews(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<float>& reference, const std::vector<AlignmentView>& views,
                       int l, const Eigen::Isometry3d& t, const PhotometricAlignmentOptions& o) {
  Normal n;
  for (size_t v = 0; v < views.size(); ++v) {
    const GradientPyramid& p = *views[v].pyramid;
    Accumulate(points, reference, p.image[l], p.gx[l], p.gy[l], AtLevel(views[v].camera, l),
               views[v].view_from_reference, t, o.huber, o.textured_gradient, v == 0, n);
  }
  n.h = n.h.selfadjointView<Eigen::Upper>();
  return n;
}

}  // namespace

GradientPyramid GradientPyramid::Build(const cv::Mat& grey, int levels) {
  CV_Assert(grey.type() == CV_32F && levels >= 1);
  GradientPyramid p;
  p.image.push_back(grey);
  for (int l = 1; l < levels; ++l) {
    cv::Mat down;
    cv::pyrDown(p.image.back(), down);
    p.image.push_back(down);
  }
  for (const cv::Mat& m : p.image) {
    cv::Mat gx, gy;
    cv::Sobel(m, gx, CV_32F, 1, 0, 3, 1.0 / 8);
    cv::Sobel(m, gy, CV_32F, 0, 1, 3, 1.0 / 8);
    p.gx.push_back(gx);
    p.gy.push_back(gy);
  }
  return p;
}

AlignmentResult AlignPhotometric(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<cv::Point2f>& intensity_px,
                                 const GradientPyramid& keyframe, const GradientPyramid& current,
                                 const core::PinholeCamera& camera,
                                 const Eigen::Isometry3d& initial,
                                 const PhotometricAlignmentOptions& o) {
  return AlignPhotometric(points, intensity_px, keyframe, {{&current, camera}}, initial, o);
}

AlignmentResult AlignPhotometric(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<cv::Point2f>& intensity_px,
                                 const GradientPyramid& keyframe,
                                 const std::vector<AlignmentView>& views,
                                 const Eigen::Isometry3d& initial,
                                 const PhotometricAlignmentOptions& o) {
  // Isometry3d::inverse() transposes the rotation: a start that is not quite orthonormal
  // (rounding, compounded by the caller's prediction) would grow at every frame.
  Eigen::Isometry3d t = initial;
  t.linear() = Eigen::Quaterniond(initial.linear()).normalized().toRotationMatrix();
  int levels = std::min<int>(o.levels, int(keyframe.image.size()));
  for (const AlignmentView& v : views) levels = std::min<int>(levels, int(v.pyramid->image.size()));
  Normal last;
  for (int l = levels - 1; l >= 0; --l) {
    const float s = float(std::ldexp(1.0, -l));
    const cv::Mat& kf = keyframe.image[l];
    std::vector<Eigen::Vector3d> pts;
    std::vector<float> reference;
    for (size_t i = 0; i < points.size(); ++i) {
      const float u = intensity_px[i].x * s, v = intensity_px[i].y * s;
      if (u < 0 || v < 0 || u >= kf.cols - 1 || v >= kf.rows - 1) continue;
      pts.push_back(points[i]);
      reference.push_back(SampleBilinear(kf, u, v));
    }
    double lambda = 1e-4;
    Normal n = AccumulateViews(pts, reference, views, l, t, o);
    for (int it = 0; it < o.max_iterations && n.visible >= 6; ++it) {
      Matrix6d h = n.h;
      h.diagonal() *= 1.0 + lambda;
      const Vector6d xi = h.ldlt().solve(-n.b);
      if (!xi.allFinite()) break;
      const Eigen::Isometry3d candidate = Exp(xi) * t;
      const Normal m = AccumulateViews(pts, reference, views, l, candidate, o);
      // Compare mean costs: the number of visible points may change with the pose.
      if (m.visible >= 6 && m.cost / m.residuals <= n.cost / n.residuals) {
        t = candidate, n = m, lambda = std::max(1e-6, lambda / 4);
        if (xi.tail<3>().norm() < o.convergence && xi.head<3>().norm() < o.convergence) break;
      } else {
        lambda *= 8;
        if (lambda > 1e4) break;
      }
    }
    last = n;
  }
  AlignmentResult r;
  r.current_from_keyframe = t;
  r.visible = last.visible;
  r.rms = last.residuals ? std::sqrt(last.sq / last.residuals) : 0.0;
  r.inlier_fraction = last.residuals ? double(last.inliers) / last.residuals : 0.0;
  r.textured_fraction = last.residuals ? double(last.textured) / last.residuals : 0.0;
  return r;
}

}  // namespace novelty::sensors
