#include "maps/illumination/illumination_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace novelty::illumination {
namespace {

TEST(IlluminationModel, InformationIsMinusTheLogOfTheQuantisationIntervalsProbability) {
  // Independent: integrate the gamma density over [x - Δ/2, x + Δ/2] by Simpson's rule, with
  // std::lgamma for the normaliser.
  stats::GammaFit fit;
  fit.alpha = 7.5;
  fit.beta = 6.0;
  const double lognorm = fit.alpha * std::log(fit.beta) - std::lgamma(fit.alpha);
  auto pdf = [&](double x) {
    return std::exp(lognorm + (fit.alpha - 1.0) * std::log(x) - fit.beta * x);
  };
  for (double x : {0.3, 0.9, 1.25, 2.7}) {
    for (double step : {0.002, 0.01}) {
      const int n = 64;
      const double lo = x - step / 2, h = step / n;
      double integral = pdf(lo) + pdf(lo + step);
      for (int k = 1; k < n; ++k) integral += (k % 2 ? 4.0 : 2.0) * pdf(lo + k * h);
      integral *= h / 3.0;
      const cv::Mat value(1, 1, CV_32F, cv::Scalar(x));
      EXPECT_NEAR(InformationMap(value, step, fit).at<float>(0, 0), -std::log(integral), 1e-3)
          << x << " " << step;
    }
  }
  // A value of 0 is taken as half its width: finite.
  const cv::Mat zero(1, 1, CV_32F, cv::Scalar(0.0)), half(1, 1, CV_32F, cv::Scalar(0.005));
  EXPECT_EQ(InformationMap(zero, 0.01, fit).at<float>(0, 0),
            InformationMap(half, 0.01, fit).at<float>(0, 0));
}

// Six lightings of a textured scene: uniform light of rising strength, and in image 4 a
// highlight (three times the light) on a disc; camera noise of ±0.5 grey levels.
struct Scene {
  std::vector<cv::Mat> images;
  cv::Mat highlight;
};

Scene MakeScene() {
  Scene s;
  cv::Mat reflectance(80, 100, CV_32FC3);
  cv::RNG(2).fill(reflectance, cv::RNG::UNIFORM, 30, 70);
  cv::GaussianBlur(reflectance, reflectance, {0, 0}, 2.0);
  s.highlight = cv::Mat::zeros(reflectance.size(), CV_8U);
  cv::circle(s.highlight, {60, 35}, 9, cv::Scalar(255), cv::FILLED);
  cv::RNG noise(3);
  for (int m = 0; m < 6; ++m) {
    const double light = 0.85 + 0.06 * m;
    cv::Mat lighting(reflectance.size(), CV_32FC3, cv::Scalar::all(light));
    if (m == 4) lighting.setTo(cv::Scalar::all(3.0 * light), s.highlight);
    cv::Mat lit = reflectance.mul(lighting), n(lit.size(), lit.type());
    noise.fill(n, cv::RNG::UNIFORM, -0.5, 0.5);
    s.images.push_back(lit + n);
  }
  return s;
}

double IoU(const cv::Mat& a, const cv::Mat& b) {
  return double(cv::countNonZero(a & b)) / std::max(1, cv::countNonZero(a | b));
}

TEST(IlluminationModel, TheThresholdSinglesOutAHighlightAndNothingElse) {
  const Scene scene = MakeScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.images);
  const IlluminationModel model = LearnIlluminationModel(invariant);
  EXPECT_NEAR(model.threshold, model.mean_information / (1.0 - 0.5), 1e-12);  // eq. 6.18
  EXPECT_GT(model.luminance.alpha, 0.0);
  EXPECT_GT(model.saturation.alpha, 0.0);
  ASSERT_EQ(model.shapes.size(), 6u);
  EXPECT_GT(IoU(model.shapes[4], scene.highlight), 0.8);
  for (int m : {0, 1, 2, 3, 5})
    EXPECT_LT(cv::countNonZero(model.shapes[m]), 0.01 * scene.highlight.total()) << m;
  // A smaller κ (specular scenes) lowers T_Y.
  IlluminationModelOptions specular;
  specular.kappa = 0.2;
  EXPECT_LT(LearnIlluminationModel(invariant, {}, specular).threshold, model.threshold);
}

TEST(IlluminationModel, ComponentsAreValueAndSaturationOfTheLinearLighting) {
  // One pixel: log lighting (0.2, 0.0, -0.3) → L = e^0.2, 1, e^-0.3: V = e^0.2, S = 1 - e^-0.5.
  const cv::Mat log_l(1, 1, CV_32FC3, cv::Scalar(0.2, 0.0, -0.3));
  const IlluminationComponents c = ComputeIlluminationComponents(log_l);
  EXPECT_NEAR(c.luminance.at<float>(0, 0), std::exp(0.2), 1e-5);
  EXPECT_NEAR(c.saturation.at<float>(0, 0), 1.0 - std::exp(-0.5), 1e-5);
}

TEST(IlluminationModel, IdenticalLightingsAndColourlessScenesAreNamedOrHandled) {
  // Six identical images: nothing varies, no model (the threshold would flag everything).
  const Scene scene = MakeScene();
  const std::vector<cv::Mat> same(4, scene.images[0]);
  try {
    LearnIlluminationModel(ComputeInvariantImage(same));
    FAIL() << "identical lightings accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lightings are identical"), std::string::npos) << e.what();
  }
  // Grey images stored as RGB: no saturation model, the luminance's still learnt.
  std::vector<cv::Mat> grey;
  for (const cv::Mat& im : scene.images) {
    cv::Mat g, rgb;
    cv::cvtColor(im, g, cv::COLOR_RGB2GRAY);
    cv::cvtColor(g, rgb, cv::COLOR_GRAY2RGB);
    grey.push_back(rgb);
  }
  const IlluminationModel model = LearnIlluminationModel(ComputeInvariantImage(grey));
  EXPECT_EQ(model.saturation.alpha, 0.0);
  EXPECT_GT(model.luminance.alpha, 0.0);
}

TEST(IlluminationModel, RejectsBadOptionsAndMismatchedCoverage) {
  const Scene scene = MakeScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.images);
  IlluminationModelOptions bad;
  bad.kappa = 1.0;
  EXPECT_THROW(LearnIlluminationModel(invariant, {}, bad), std::invalid_argument);
  bad.kappa = 0.5;
  bad.luminance_step = 0.0;
  EXPECT_THROW(LearnIlluminationModel(invariant, {}, bad), std::invalid_argument);
  EXPECT_THROW(LearnIlluminationModel(invariant, {cv::Mat(invariant.covered)}),
               std::invalid_argument);  // 1 mask, 6 images
}

}  // namespace
}  // namespace novelty::illumination
