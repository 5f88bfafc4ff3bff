#include "sensors/localization/sequence_registration.h"

#include <gtest/gtest.h>

#include <random>

namespace novelty::sensors {
namespace {

// A sequence of 120 frames on a quarter circle in the common frame (truth T_j). Its own frame is
// the common frame moved by Q_true, and its visual localization drifts: M_j = Q_true⁻¹·E_j·T_j with
// E_j turning up to 8° about a tilted axis and shifting up to 15 cm, non-linearly in j.
struct DriftingSequence {
  static constexpr int kFrames = 120;
  double kDriftAngle = 0.14;
  Eigen::Isometry3d q_true = Eigen::Isometry3d::Identity();

  DriftingSequence() {
    q_true.linear() =
        Eigen::AngleAxisd(0.6, Eigen::Vector3d(0.2, 0.3, 1).normalized()).toRotationMatrix();
    q_true.translation() = Eigen::Vector3d(0.5, -0.3, 0.1);
  }
  Eigen::Isometry3d Truth(int j) const {
    const double a = M_PI / 2 * j / (kFrames - 1);
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    t.translation() = Eigen::Vector3d(1.5 * std::cos(a), 1.5 * std::sin(a), 1.1);
    return t;
  }
  Eigen::Isometry3d Drift(int j) const {
    const double s = double(j) / (kFrames - 1);
    Eigen::Isometry3d e = Eigen::Isometry3d::Identity();
    e.linear() = Eigen::AngleAxisd(kDriftAngle * s * s, Eigen::Vector3d(0.3, -0.2, 1).normalized())
                     .toRotationMatrix();
    e.translation() = Eigen::Vector3d(0.15 * s, -0.05 * s * s, 0.02 * s);
    return e;
  }
  Eigen::Isometry3d Own(int j) const { return q_true.inverse() * Drift(j) * Truth(j); }
  SupportView Support(int j, std::mt19937_64& rng, double noise) const {
    std::normal_distribution<double> n(0, noise);
    Eigen::Isometry3d s = Truth(j);
    s.translation() += Eigen::Vector3d(n(rng), n(rng), n(rng));
    return {double(j), s, Own(j)};
  }
};

struct RegistrationErrors {
  double worst_mm = 0, worst_deg = 0;
};

template <typename QAt>
RegistrationErrors Measure(const DriftingSequence& seq, QAt q_at) {
  RegistrationErrors e;
  for (int j = 0; j < DriftingSequence::kFrames; ++j) {
    const Eigen::Matrix4d s = RegisterPose(q_at(j), seq.Own(j));
    Eigen::Matrix3d r = s.block<3, 3>(0, 0);
    // Angle of the nearest rotation to the (possibly non-orthogonal) registered matrix.
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
    r = svd.matrixU() * svd.matrixV().transpose();
    e.worst_deg = std::max(
        e.worst_deg, Eigen::AngleAxisd(r.transpose() * seq.Truth(j).linear()).angle() * 180 / M_PI);
    e.worst_mm =
        std::max(e.worst_mm, 1000 * (s.block<3, 1>(0, 3) - seq.Truth(j).translation()).norm());
  }
  return e;
}

TEST(SequenceRegistration, BothMeetTheBudgetAndTheFitStaysARotation) {
  const DriftingSequence seq;
  std::mt19937_64 rng(1);
  const double noise = 0.001;  // support views localized to 1 mm
  const std::vector<SupportView> three = {seq.Support(0, rng, noise), seq.Support(60, rng, noise),
                                          seq.Support(119, rng, noise)};
  std::vector<SupportView> five = three;
  five.push_back(seq.Support(30, rng, noise));
  five.push_back(seq.Support(90, rng, noise));

  const RegistrationErrors lagrange = Measure(seq, [&](int j) { return LagrangeFrameTransform(three, j); });
  const FittedFrameTransform fit3(three), fit5(five);
  const RegistrationErrors ceres3 = Measure(seq, [&](int j) { return fit3.At(j).matrix(); });
  const RegistrationErrors ceres5 = Measure(seq, [&](int j) { return fit5.At(j).matrix(); });
  std::printf(
      "worst over the sequence: Lagrange (eq. 6.2) %.1f mm %.3f°, Ceres 3 views %.1f mm "
      "%.3f°, Ceres 5 views %.1f mm %.3f°\n",
      lagrange.worst_mm, lagrange.worst_deg, ceres3.worst_mm, ceres3.worst_deg, ceres5.worst_mm,
      ceres5.worst_deg);
  EXPECT_LT(ceres5.worst_mm, 5.0);  // the sensors issue's budget
  EXPECT_LT(ceres5.worst_deg, 0.5);
  EXPECT_LT(ceres3.worst_mm, lagrange.worst_mm + 0.2);  // equal here: a smooth, moderate drift
  EXPECT_LT(ceres3.worst_deg, lagrange.worst_deg);
  // Lagrange-interpolated columns are not orthogonal between the support views.
  const Eigen::Matrix3d r = LagrangeFrameTransform(three, 30).block<3, 3>(0, 0);
  EXPECT_GT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-4);
  EXPECT_LT((fit5.At(30).linear().transpose() * fit5.At(30).linear() - Eigen::Matrix3d::Identity())
                .norm(),
            1e-12);
}

// With strong rotational drift (29° over the sequence) the normalised Lagrange columns drift
// away from a rotation; the fit on SO(3) does not.
TEST(SequenceRegistration, StrongRotationalDriftFavoursTheFitOnSo3) {
  DriftingSequence seq;
  seq.kDriftAngle = 0.5;
  std::mt19937_64 rng(3);
  const std::vector<SupportView> three = {seq.Support(0, rng, 0), seq.Support(60, rng, 0),
                                          seq.Support(119, rng, 0)};
  const RegistrationErrors lagrange = Measure(seq, [&](int j) { return LagrangeFrameTransform(three, j); });
  const FittedFrameTransform fit(three);
  const RegistrationErrors ceres = Measure(seq, [&](int j) { return fit.At(j).matrix(); });
  std::printf("29° drift: Lagrange %.1f mm %.3f°, Ceres %.1f mm %.3f°\n", lagrange.worst_mm,
              lagrange.worst_deg, ceres.worst_mm, ceres.worst_deg);
  // Measured: Lagrange 6.1 mm 0.120°, Ceres 6.7 mm 0.000°. The translation of Q is not a
  // quadratic in j when the rotation drifts this much, for either method.
  EXPECT_LT(ceres.worst_deg, 0.1 * lagrange.worst_deg);
  EXPECT_LT(ceres.worst_mm, 10.0);
  EXPECT_LT(lagrange.worst_mm, 10.0);
}

// Twelve support views localized to 1 mm, one of them 3 cm off (it aligned wrongly): the robust
// fit keeps near the eleven, plain least squares is pulled towards the one.
TEST(SequenceRegistration, ASupportViewFarOffPullsTheRobustFitLittle) {
  const DriftingSequence seq;
  std::mt19937_64 rng(4);
  std::vector<SupportView> support;
  for (int j = 0; j < DriftingSequence::kFrames; j += 10) support.push_back(seq.Support(j, rng, 0.001));
  support[5].common_from_camera.translation() += Eigen::Vector3d(0.03, 0.0, -0.01);
  FrameFitOptions plain;
  plain.robust_scale = 0;
  plain.outlier_scale = 0;
  const FittedFrameTransform robust(support), least_squares(support, plain);
  const RegistrationErrors r = Measure(seq, [&](int j) { return robust.At(j).matrix(); });
  const RegistrationErrors l = Measure(seq, [&](int j) { return least_squares.At(j).matrix(); });
  std::printf("one support view 32 mm off: Huber %.1f mm, least squares %.1f mm\n", r.worst_mm,
              l.worst_mm);
  EXPECT_LT(r.worst_mm, 5.0);
  EXPECT_LT(r.worst_mm, 0.6 * l.worst_mm);
}

// Under another lighting several support views align wrongly alike: phase I5 of the stereo
// scenario has 5 of 12 off by 12–15 mm, sideways in the camera (the shift the images tell
// least from a turn). Here 4 of 12, each 13 mm along its camera's x axis. The Huber fit still
// pulls linearly towards all four; the Cauchy refit from it lets them go.
TEST(SequenceRegistration, SupportViewsBiasedAlikeAreOutweighedByTheCauchyRefit) {
  const DriftingSequence seq;
  std::mt19937_64 rng(7);
  std::vector<SupportView> support;
  for (int j = 0; j < DriftingSequence::kFrames; j += 10)
    support.push_back(seq.Support(j, rng, 0.001));
  const FittedFrameTransform unbiased(support);  // the floor: the fit's own model error
  for (int n : {3, 4, 7, 10}) {
    Eigen::Isometry3d& s = support[std::size_t(n)].common_from_camera;
    s.translation() += s.linear() * Eigen::Vector3d(-0.013, 0, 0);
  }
  FrameFitOptions huber_only;
  huber_only.outlier_scale = 0;
  const FittedFrameTransform refit(support), huber(support, huber_only);
  const RegistrationErrors r = Measure(seq, [&](int j) { return refit.At(j).matrix(); });
  const RegistrationErrors h = Measure(seq, [&](int j) { return huber.At(j).matrix(); });
  const RegistrationErrors u = Measure(seq, [&](int j) { return unbiased.At(j).matrix(); });
  std::printf(
      "4 of 12 support views 13 mm off alike: Cauchy refit %.1f mm, Huber %.1f mm "
      "(none off: %.1f mm)\n",
      r.worst_mm, h.worst_mm, u.worst_mm);
  // What the biased views add to the error, the refit keeps to less than half.
  EXPECT_LT(r.worst_mm - u.worst_mm, 0.5 * (h.worst_mm - u.worst_mm));
}

TEST(SequenceRegistration, RefusesTooFewOrCoincidentSupportViews) {
  const DriftingSequence seq;
  std::mt19937_64 rng(2);
  std::vector<SupportView> two = {seq.Support(0, rng, 0), seq.Support(50, rng, 0)};
  EXPECT_THROW(LagrangeFrameTransform(two, 10), std::invalid_argument);
  EXPECT_THROW(FittedFrameTransform{two}, std::invalid_argument);
  two.push_back(seq.Support(50, rng, 0));
  EXPECT_THROW(FittedFrameTransform{two}, std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sensors
