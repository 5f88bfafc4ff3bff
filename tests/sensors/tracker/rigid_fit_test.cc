#include "sensors/tracker/rigid_fit.h"

#include <gtest/gtest.h>

#include <random>

namespace novelty::sensors {
namespace {

Eigen::Isometry3d SomeTransform() {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.3, -1.2, 2.0);
  return t;
}

std::vector<Eigen::Vector3d> SomePoints(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) p.emplace_back(u(rng), u(rng), u(rng));
  return p;
}

TEST(FitRigid, RecoversAnExactTransform) {
  const auto model = SomePoints(6, 1);
  std::vector<Eigen::Vector3d> measured;
  for (const auto& p : model) measured.push_back(SomeTransform() * p);
  std::string why;
  const auto fit = FitRigid(model, measured, {}, &why);
  ASSERT_TRUE(fit) << why;
  EXPECT_LT((fit->transform.matrix() - SomeTransform().matrix()).norm(), 1e-12);
  EXPECT_LT(fit->rms, 1e-12);
  EXPECT_FALSE(fit->reflection_corrected);
}

TEST(FitRigid, ThreePointsSuffice) {
  const std::vector<Eigen::Vector3d> model = {{0.2, 0, 0}, {0, 0.12, 0}, {0, 0, 0}};
  std::vector<Eigen::Vector3d> measured;
  for (const auto& p : model) measured.push_back(SomeTransform() * p);
  const auto fit = FitRigid(model, measured, {}, nullptr);
  ASSERT_TRUE(fit);
  EXPECT_LT((fit->transform.matrix() - SomeTransform().matrix()).norm(), 1e-12);
}

TEST(FitRigid, AZeroWeightRemovesAnOutlier) {  // eq. 3.4
  const auto model = SomePoints(8, 2);
  std::vector<Eigen::Vector3d> measured;
  for (const auto& p : model) measured.push_back(SomeTransform() * p);
  measured[3] += Eigen::Vector3d(0.5, 0, 0);
  const auto plain = FitRigid(model, measured, {}, nullptr);
  std::vector<double> w(8, 1.0);
  w[3] = 0.0;
  const auto weighted = FitRigid(model, measured, w, nullptr);
  ASSERT_TRUE(plain && weighted);
  EXPECT_GT((plain->transform.translation() - SomeTransform().translation()).norm(), 0.01);
  EXPECT_LT((weighted->transform.matrix() - SomeTransform().matrix()).norm(), 1e-12);
}

TEST(FitRigid, AMirroredSetGivesTheNearestRotationNotAReflection) {
  const auto model = SomePoints(5, 3);
  std::vector<Eigen::Vector3d> measured;
  for (const auto& p : model) measured.emplace_back(-p.x(), p.y(), p.z());  // a mirror image
  const auto fit = FitRigid(model, measured, {}, nullptr);
  ASSERT_TRUE(fit);
  EXPECT_TRUE(fit->reflection_corrected);
  EXPECT_NEAR(fit->transform.linear().determinant(), 1.0, 1e-12);
  EXPECT_GT(fit->rms, 0.1);  // a mirror image cannot be fitted by a rotation
}

TEST(FitRigid, NoiseGivesTheExpectedResidual) {
  const auto model = SomePoints(2000, 4);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0, 0.001);
  std::vector<Eigen::Vector3d> measured;
  for (const auto& p : model)
    measured.push_back(SomeTransform() * p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  const auto fit = FitRigid(model, measured, {}, nullptr);
  ASSERT_TRUE(fit);
  // 3 coordinates × 1 mm noise, minus the 6 fitted parameters' share.
  EXPECT_NEAR(fit->rms, std::sqrt(3.0) * 0.001, 0.00005);
  EXPECT_LT(
      Eigen::AngleAxisd(fit->transform.linear().transpose() * SomeTransform().linear()).angle(),
      0.0003);
}

TEST(FitRigid, RefusesDegenerateInput) {
  std::string why;
  EXPECT_FALSE(FitRigid({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}}, {}, &why));
  EXPECT_NE(why.find("3 needed"), std::string::npos) << why;
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_FALSE(FitRigid(line, line, {}, &why));
  EXPECT_NE(why.find("collinear"), std::string::npos) << why;
  EXPECT_FALSE(FitRigid(line, {{0, 0, 0}}, {}, &why));
  EXPECT_FALSE(FitRigid(line, line, {1.0, -1.0, 1.0}, &why));
}

}  // namespace
}  // namespace novelty::sensors
