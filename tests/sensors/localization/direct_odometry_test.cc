#include "sensors/localization/direct_odometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "sensors/localization/sequence_registration.h"
#include "sensors/localization/support_views.h"
#include "tests/sensors/localization/quarter_circle.h"

namespace novelty::sensors {
namespace {

using Clip = std::vector<std::pair<StereoPair, Eigen::Isometry3d>>;

// Frames [first, first + count) of the stereo scenario (0-based), rendered once per process.
const Clip& Rendered(int first, int count) {
  static std::map<std::pair<int, int>, Clip> cache;
  Clip& clip = cache[{first, count}];
  if (clip.empty()) {
    QuarterCircle run;
    for (int k = first; k < first + count; ++k) clip.push_back(run.Frame(k));
  }
  return clip;
}
const Clip& PhaseI1() { return Rendered(0, 95); }    // frames 1–95
const Clip& PhaseI2() { return Rendered(200, 95); }  // frames 201–295, after the lamps moved

double AngleDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return AngleBetween(a, b) * 180 / M_PI;
}

// Phase I1 of the stereo scenario: frames 1–95, 90° of a 1.5 m circle, 2.3 m of path. The
// sensors issue's budget is < 1 % of the path length; measured: worst 0.33 % (7.7 mm), worst
// angle 0.26°, against 2.0 % / 1.8° for the feature-based odometry on the same frames. Over all
// nine quarter circles I1–I9 (measured outside the tests): mean 0.49 %, worst 0.67 %.
TEST(DirectOdometry, DriftOnAQuarterCircleStaysBelowOnePercentOfThePath) {
  const Clip& clip = PhaseI1();
  DirectOdometry vo({}, clip[0].second);
  double path = 0, worst = 0, worst_angle = 0;
  int keyframes = 0;
  for (size_t k = 0; k < clip.size(); ++k) {
    const auto& [pair, truth] = clip[k];
    std::string why;
    const auto r = vo.Track(pair, &why);
    ASSERT_TRUE(r) << "frame " << k + 1 << ": " << why;
    EXPECT_FALSE(r->relocalized);
    keyframes += r->new_keyframe;
    if (k > 0) path += (truth.translation() - clip[k - 1].second.translation()).norm();
    worst = std::max(worst, (r->world_from_camera.translation() - truth.translation()).norm());
    worst_angle = std::max(worst_angle, AngleDeg(r->world_from_camera, truth));
  }
  std::printf("path %.2f m: worst error %.1f mm (%.2f %%), worst angle %.2f°, %d keyframes\n",
              path, 1000 * worst, 100 * worst / path, worst_angle, keyframes);
  EXPECT_GT(path, 2.0);
  EXPECT_LT(worst, 0.01 * path);
  EXPECT_LT(worst_angle, 0.5);
  EXPECT_GT(keyframes, 5);  // drift is measured across keyframe hand-overs, not within one
}

// The lamps move between frames 200 and 201 (scenario event at 49.81 s): the shading of the
// whole scene changes while the camera drives on. Alignment after local contrast normalization
// keeps tracking (measured: worst 3.2 mm over 0.47 m); with raw grey levels it is lost there.
TEST(DirectOdometry, KeepsTrackingThroughAChangeOfLighting) {
  const Clip& clip = Rendered(190, 25);  // frames 191–215
  auto track = [&](const DirectOdometryOptions& options, double* worst) {
    DirectOdometry vo(options, clip[0].second);
    int relocalized = 0;
    *worst = 0;
    for (const auto& [pair, truth] : clip) {
      std::string why;
      const auto r = vo.Track(pair, &why);
      if (!r) return -1;
      relocalized += r->relocalized;
      *worst = std::max(*worst, (r->world_from_camera.translation() - truth.translation()).norm());
    }
    return relocalized;
  };
  double worst = 0, worst_raw = 0;
  EXPECT_EQ(track({}, &worst), 0);
  EXPECT_LT(worst, 0.01);  // m
  DirectOdometryOptions raw;
  raw.normalization.window = 0;
  EXPECT_NE(track(raw, &worst_raw), 0);  // lost: failed or re-localized
  std::printf("across the lamp move: worst error %.1f mm normalized, %.1f mm raw\n", 1000 * worst,
              1000 * worst_raw);
}

// Position (mm) and angle (°) differences of pairs of poses: RMS and worst.
struct Errors {
  double worst_mm = 0, worst_deg = 0, sum_sq_mm = 0;
  int n = 0;
  void Add(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
    const double mm = 1000 * (a.translation() - b.translation()).norm();
    worst_mm = std::max(worst_mm, mm);
    worst_deg = std::max(worst_deg, AngleDeg(a, b));
    sum_sq_mm += mm * mm;
    ++n;
  }
  double RmsMm() const { return n ? std::sqrt(sum_sq_mm / n) : 0.0; }
};

// Where the common frame (a sequence's odometry) puts a camera whose true pose is given: the
// odometry's error D_k = estimate_k · truth_k⁻¹ at the sequence frame nearest in position,
// linearly interpolated towards the next one, applied to the true pose. Registration can at
// best reproduce this; the rest of its error against the ground truth is the common frame's drift.
class CommonFrameDistortion {
 public:
  CommonFrameDistortion(const Clip& clip, const std::vector<Eigen::Isometry3d>& estimates) {
    for (size_t k = 0; k < clip.size(); ++k) {
      truth_.push_back(clip[k].second.translation());
      error_.push_back(estimates[k] * clip[k].second.inverse());
    }
  }
  Eigen::Isometry3d At(const Eigen::Isometry3d& truth) const {
    const Eigen::Vector3d p = truth.translation();
    size_t k = 0;
    for (size_t i = 1; i < truth_.size(); ++i) {
      if ((truth_[i] - p).norm() < (truth_[k] - p).norm()) k = i;
    }
    // The neighbour on p's side, and p's fraction of the way to it (clamped to the segment).
    const size_t n = k + 1 < truth_.size() && (k == 0 || (truth_[k + 1] - p).norm() <
                                                            (truth_[k - 1] - p).norm())
                         ? k + 1
                         : k - 1;
    const Eigen::Vector3d d = truth_[n] - truth_[k];
    const double s = d.squaredNorm() > 0 ? std::clamp(d.dot(p - truth_[k]) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    Eigen::Isometry3d error = Eigen::Isometry3d::Identity();
    const Eigen::Quaterniond qk(error_[k].linear()), qn(error_[n].linear());
    error.linear() = qk.slerp(s, qn).toRotationMatrix();
    error.translation() = (1 - s) * error_[k].translation() + s * error_[n].translation();
    return error * truth;
  }

 private:
  std::vector<Eigen::Vector3d> truth_;
  std::vector<Eigen::Isometry3d> error_;
};

// Registration of a second sequence (6.1.1): the phase is localized by its own odometry from
// the identity; support views of it (every 8th frame) are localized against the keyframes of
// I1's odometry (the common frame, started at the true pose), the first without a prior (ORB
// matches, or where they fail alignment from every keyframe's pose), the others from the pose the
// previous support view predicts; eq. 6.1 gives Q at each, and every
// pose of the phase is registered by eq. 6.3 with Q interpolated (Lagrange, first, middle and
// last support view) or fitted (Ceres, all; also with the Huber fit alone).
//
// Registration error is measured against where the common frame puts each camera
// (CommonFrameDistortion): that is what registration is for (virtual views at the same place
// from different sequences) and all it can reach; the common frame's own error is its drift,
// which the drift test bounds.
struct PhaseRegistration {
  SupportViews found;
  std::vector<Errors> support;  // each support view against the common frame
  Errors ceres, huber_only, lagrange, floor, ceres_truth, lagrange_truth;
};

PhaseRegistration Register(const Clip& second) {
  const Clip& common = PhaseI1();
  DirectOdometry reference({}, common[0].second);
  std::string why;
  std::vector<Eigen::Isometry3d> common_poses;
  for (const auto& [pair, truth] : common) {
    const auto r = reference.Track(pair, &why);
    EXPECT_TRUE(r) << why;
    common_poses.push_back(r ? r->world_from_camera : truth);
  }
  const CommonFrameDistortion distortion(common, common_poses);
  DirectOdometry own_odometry({}, Eigen::Isometry3d::Identity());
  std::vector<Eigen::Isometry3d> own;
  std::vector<StereoPair> frames;
  for (const auto& [pair, truth] : second) {
    const auto r = own_odometry.Track(pair, &why);
    EXPECT_TRUE(r) << why;
    own.push_back(r ? r->world_from_camera : Eigen::Isometry3d::Identity());
    frames.push_back(pair);
  }
  PhaseRegistration out;
  out.found = LocalizeSupportViews(reference, frames, own);  // every 8th frame
  for (const std::string& s : out.found.skipped) std::printf("skipped %s\n", s.c_str());
  const std::vector<SupportView>& support = out.found.views;
  if (support.size() < 3) return out;
  for (const SupportView& s : support) {
    out.support.emplace_back();
    out.support.back().Add(s.common_from_camera,
                           distortion.At(second[std::size_t(s.index)].second));
  }
  std::vector<SupportView> ideal;
  const std::vector<SupportView> three = {support.front(), support[support.size() / 2],
                                          support.back()};
  for (size_t j = 0; j < second.size(); ++j)
    ideal.push_back({double(j), distortion.At(second[j].second), own[j]});
  FrameFitOptions least_squares;  // the floor in RMS
  least_squares.robust_scale = least_squares.outlier_scale = 0;
  FrameFitOptions huber;
  huber.outlier_scale = 0;
  const FittedFrameTransform fitted(support), huber_fit(support, huber), best(ideal, least_squares);
  for (size_t j = 0; j < second.size(); ++j) {
    const Eigen::Isometry3d& truth = second[j].second;
    const Eigen::Isometry3d in_common = distortion.At(truth);
    const Eigen::Matrix4d l = RegisterPose(LagrangeFrameTransform(three, double(j)), own[j]);
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(l.topLeftCorner<3, 3>(),
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Isometry3d l_pose = Eigen::Isometry3d::Identity();  // nearest rotation, to compare
    l_pose.linear() = svd.matrixU() * svd.matrixV().transpose();
    l_pose.translation() = l.topRightCorner<3, 1>();
    const Eigen::Isometry3d c_pose = fitted.At(double(j)) * own[j];
    out.lagrange.Add(l_pose, in_common);
    out.ceres.Add(c_pose, in_common);
    out.huber_only.Add(huber_fit.At(double(j)) * own[j], in_common);
    out.floor.Add(best.At(double(j)) * own[j], in_common);
    out.lagrange_truth.Add(l_pose, truth);
    out.ceres_truth.Add(c_pose, truth);
  }
  auto print = [](const char* what, const Errors& e) {
    std::printf("%-34s RMS %.1f mm, worst %.1f mm %.2f°\n", what, e.RmsMm(), e.worst_mm,
                e.worst_deg);
  };
  print("Ceres vs common frame:", out.ceres);
  print("Ceres, Huber fit alone:", out.huber_only);
  print("Lagrange vs common frame:", out.lagrange);
  print("best smooth Q vs common frame:", out.floor);
  print("Ceres vs ground truth:", out.ceres_truth);
  print("Lagrange vs ground truth:", out.lagrange_truth);
  return out;
}

// Phase I2 (frames 201–295, after the lamps moved). Measured (RMS / worst): Ceres 2.8 / 6.8 mm,
// Lagrange 3.2 / 6.6 mm, worst 0.25°; the best smooth Q possible — fitted to the common
// frame's own poses at every frame — reaches 2.0 / 7.5 mm: the worst cases are the odometries'
// frame-to-frame jitter (2–3 mm per frame against the keyframe), not the registration. Against
// the ground truth: RMS 5.5 mm, worst 7.9–8.2 mm.
TEST(DirectOdometry, RegistersASecondSequenceThroughSupportViews) {
  const PhaseRegistration r = Register(PhaseI2());
  EXPECT_GE(r.found.views.size(), 11u);  // of 12
  for (size_t n = 0; n < r.support.size(); ++n)
    EXPECT_LT(r.support[n].worst_mm, 6.0) << "support view " << r.found.views[n].index;
  // The sensors issue's budget: 5 mm / 0.5°.
  EXPECT_LT(r.ceres.RmsMm(), 5.0);
  EXPECT_LT(r.lagrange.RmsMm(), 5.0);
  EXPECT_LT(r.ceres.worst_deg, 0.5);
  EXPECT_LT(r.lagrange.worst_deg, 0.5);
  EXPECT_LT(r.ceres.RmsMm(), r.floor.RmsMm() + 1.5);  // close to the best any smooth Q can do
  EXPECT_LT(r.ceres_truth.worst_mm, 12.0);            // common-frame drift included
  EXPECT_LT(r.lagrange_truth.worst_mm, 12.0);
}

// Phase I5 (frames 798–892), the lighting that biases support views most: both lamps moved to
// the far side of the table, so the shadows fall the other way. Several support views align
// 1–1.5 cm off, alike (sideways in the camera, with a turn that hides it); before the Cauchy
// refit and the wider RMS bound for support views, I5 could not be registered at all (10 of 12
// support views refused). ORB finds no match under this lighting (8–10 of ~370 features pass
// the ratio test), so the first support view is found by aligning it to every keyframe from the
// keyframe's own pose. Measured (RMS / worst): Ceres 3.7 / 7.2 mm, 0.28°; the Huber fit alone 5.4
// / 10.8 mm; Lagrange (three support views, two of them among the biased) 10.9 / 19.1 mm; best
// smooth Q 2.3 / 5.5 mm.
TEST(DirectOdometry, RegistersASequenceWhoseLightingBiasesSupportViews) {
  const PhaseRegistration r = Register(Rendered(797, 95));
  EXPECT_GE(r.found.views.size(), 11u);  // of 12
  EXPECT_LT(r.ceres.RmsMm(), 5.0);
  EXPECT_LT(r.ceres.worst_deg, 0.5);
  EXPECT_LT(r.ceres.RmsMm(), r.huber_only.RmsMm() - 1.0);
}

// After a blackout (tracking lost) the pose comes back from the keyframes, and tracking goes on.
TEST(DirectOdometry, RelocalizesAfterTrackingIsLost) {
  const Clip& clip = Rendered(0, 23);
  DirectOdometry vo({}, clip[0].second);
  std::string why;
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(vo.Track(clip[k].first, &why)) << why;
  StereoPair dark = clip[0].first;
  dark.reference = cv::Mat::zeros(dark.reference.size(), dark.reference.type());
  dark.other = dark.reference.clone();
  EXPECT_FALSE(vo.Track(dark, &why));
  EXPECT_NE(why.find("lost"), std::string::npos) << why;
  const auto& [pair, truth] = clip[21];
  const auto r = vo.Track(pair, &why);
  ASSERT_TRUE(r) << why;
  EXPECT_TRUE(r->relocalized);
  std::printf("re-localized %.1f mm, %.2f° off\n",
              1000 * (r->world_from_camera.translation() - truth.translation()).norm(),
              AngleDeg(r->world_from_camera, truth));
  EXPECT_LT((r->world_from_camera.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(AngleDeg(r->world_from_camera, truth), 0.5);
  const auto& [next_pair, next_truth] = clip[22];
  const auto next = vo.Track(next_pair, &why);
  ASSERT_TRUE(next) << why;
  EXPECT_FALSE(next->relocalized);
  EXPECT_LT((next->world_from_camera.translation() - next_truth.translation()).norm(), 0.01);
}

TEST(DirectOdometry, ImagesOfDifferentSizesAreRejectedWithAReason) {
  StereoPair pair;
  pair.reference = cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 120, 60));
  pair.other = cv::Mat(120, 160, CV_8UC3, cv::Scalar(90, 120, 60));
  DirectOdometry vo;
  std::string why;
  EXPECT_FALSE(vo.Track(pair, &why));
  EXPECT_NE(why.find("different sizes"), std::string::npos) << why;
  EXPECT_FALSE(vo.Localize(pair, &why));
}

}  // namespace
}  // namespace novelty::sensors
