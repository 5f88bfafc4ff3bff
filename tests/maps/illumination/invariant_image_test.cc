#include "maps/illumination/invariant_image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/float_image.h"
#include "eval/lmse.h"

namespace novelty::illumination {
namespace {

// A colour reflectance of random blocks (values 20…230).
cv::Mat BlockReflectance(cv::Size size, int seed) {
  cv::RNG rng(seed);
  cv::Mat r(size, CV_32FC3);
  for (int y = 0; y < size.height; y += 8)
    for (int x = 0; x < size.width; x += 8)
      r(cv::Rect(x, y, 8, 8) & cv::Rect({}, size))
          .setTo(cv::Scalar(rng.uniform(20.0, 230.0), rng.uniform(20.0, 230.0),
                            rng.uniform(20.0, 230.0)));
  return r;
}

// Lighting m: a shading ramp whose slopes over the five images are -2a, -a, 0, a, 2a (median 0)
// and a hard shadow (factor 0.3) at a place of its own.
cv::Mat RampLighting(cv::Size size, int m) {
  cv::Mat l(size, CV_32FC3);
  const double slope = 0.004 * (m - 2);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const float v = float(std::exp(slope * (x - size.width / 2)));
      l.at<cv::Vec3f>(y, x) = cv::Vec3f(v, v, v);
    }
  l(cv::Rect(5 + 14 * m, 10 + 9 * m, 17, 13)) *= 0.3;
  return l;
}

cv::Mat Log(const cv::Mat& m) {
  cv::Mat l;
  cv::log(m, l);
  return l;
}

// max |a - b - mean(a - b)| per channel: equality up to the free constant.
double ErrorUpToConstant(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d = a - b;
  d -= cv::mean(d);
  return cv::norm(d, cv::NORM_INF);
}

TEST(InvariantImage, RecoversReflectanceAndLightingOfASyntheticScene) {
  const cv::Size size(96, 72);
  const cv::Mat reflectance = BlockReflectance(size, 3);
  std::vector<cv::Mat> images, lightings;
  for (int m = 0; m < 5; ++m) {
    lightings.push_back(RampLighting(size, m));
    images.push_back(reflectance.mul(lightings.back()));
  }
  for (auto colour : {InvariantImageOptions::Colour::kPerChannel,
                      InvariantImageOptions::Colour::kLuminanceChromaticity}) {
    SCOPED_TRACE(int(colour));
    InvariantImageOptions options;
    options.colour = colour;
    const InvariantImage out = ComputeInvariantImage(images, {}, options);
    EXPECT_EQ(cv::countNonZero(out.covered), size.area());
    // Every shadow edge is in one image of five at any pixel, and the ramps' slopes have median 0;
    // where one image's shadow edge replaces its ramp slope, the median moves to a neighbouring
    // slope, at most a = 0.004 — the bound of the error in the log domain.
    const double a = 0.004;
    EXPECT_LT(ErrorUpToConstant(out.log_invariant, Log(reflectance)), a);
    ASSERT_EQ(out.log_illumination.size(), 5u);
    for (int m = 0; m < 5; ++m)
      EXPECT_LT(ErrorUpToConstant(out.log_illumination[m], Log(lightings[m])), a) << m;
    // The constant: the illumination images average 0 in the log domain.
    cv::Scalar sum;
    for (const cv::Mat& l : out.log_illumination) sum += cv::mean(l);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c] / 5.0, 0.0, 1e-5);
    // And i_m = r̂ + l̂_m (eq. 6.14).
    EXPECT_LT(cv::norm(out.log_invariant + out.log_illumination[2], Log(images[2]), cv::NORM_INF),
              1e-4);
  }
}

TEST(InvariantImage, AnEvenNumberOfLightingsTakesTheMeanOfTheTwoMiddleGradients) {
  // Two pixels; the four images' differences 0.1, 0.2, 0.4, 0.8 (log): median 0.3.
  std::vector<cv::Mat> images;
  for (double d : {0.4, 0.1, 0.8, 0.2}) {
    cv::Mat im(1, 2, CV_32FC1);
    im.at<float>(0, 0) = 50.0f;
    im.at<float>(0, 1) = float(50.0 * std::exp(d));
    images.push_back(im);
  }
  const InvariantImage out = ComputeInvariantImage(images);
  EXPECT_NEAR(out.log_invariant.at<float>(0, 1) - out.log_invariant.at<float>(0, 0), 0.3, 1e-5);
}

TEST(InvariantImage, ClipsDarkPixelsAndStaysFiniteOnBlackImages) {
  const std::vector<cv::Mat> black(3, cv::Mat::zeros(10, 12, CV_8UC3));
  const InvariantImage out = ComputeInvariantImage(black);
  EXPECT_TRUE(cv::checkRange(out.log_invariant));
  // All pixels clipped to 3: the invariant image is log 3 everywhere, the lightings 0.
  EXPECT_LT(cv::norm(out.log_invariant - cv::Scalar::all(std::log(3.0)), cv::NORM_INF), 1e-5);
  for (const cv::Mat& l : out.log_illumination) EXPECT_LT(cv::norm(l, cv::NORM_INF), 1e-5);
}

TEST(InvariantImage, PixelsThatTooFewImagesCoverAreLeftOut) {
  const cv::Size size(40, 30);
  const cv::Mat reflectance = BlockReflectance(size, 4);
  std::vector<cv::Mat> images, coverage;
  for (int m = 0; m < 3; ++m) {
    images.push_back(reflectance * (0.5 + 0.2 * m));
    cv::Mat c(size, CV_8U, cv::Scalar(255));
    if (m < 2) c.colRange(0, 10).setTo(0);  // only image 2 sees the left quarter
    coverage.push_back(c);
  }
  images[0].colRange(0, 10).setTo(cv::Scalar::all(1e6));  // garbage where not covered
  const InvariantImage out = ComputeInvariantImage(images, coverage);
  EXPECT_EQ(cv::countNonZero(out.covered), 30 * 30);
  EXPECT_EQ(cv::countNonZero(out.covered.colRange(0, 10)), 0);
  const cv::Rect seen(10, 0, 30, 30);
  EXPECT_LT(ErrorUpToConstant(out.log_invariant(seen), Log(reflectance)(seen)), 1e-4);
  EXPECT_EQ(cv::norm(out.log_invariant.colRange(0, 10), cv::NORM_INF), 0.0);
}

TEST(InvariantImage, PrimaryColouredLightingsGiveNoNaN) {
  // One pixel lit pure red, then pure green, then pure blue: no channel's share has a positive
  // median; the colour is left neutral instead of 0/0.
  std::vector<cv::Mat> images;
  for (int c = 0; c < 3; ++c) {
    cv::Mat im = cv::Mat::zeros(4, 4, CV_32FC3);
    im.setTo(cv::Scalar(c == 0 ? 200 : 0, c == 1 ? 200 : 0, c == 2 ? 200 : 0));
    images.push_back(im);
  }
  InvariantImageOptions options;
  options.colour = InvariantImageOptions::Colour::kLuminanceChromaticity;
  const InvariantImage out = ComputeInvariantImage(images, {}, options);
  EXPECT_TRUE(cv::checkRange(out.log_invariant));
  for (const cv::Mat& l : out.log_illumination) EXPECT_TRUE(cv::checkRange(l));
}

TEST(InvariantImage, EachCoveredPartHasItsOwnConstant) {
  // Two covered squares, apart, of different reflectance under the same lightings: each
  // part's illumination images average 0, so each square's r̂ is its own mean log intensity.
  std::vector<cv::Mat> images;
  for (int m = 0; m < 3; ++m) {
    cv::Mat im(20, 40, CV_32FC1, cv::Scalar(10.0 * (m + 1)));
    im(cv::Rect(25, 5, 10, 10)) *= 5.0;
    images.push_back(im);
  }
  cv::Mat mask = cv::Mat::zeros(20, 40, CV_8U);
  mask(cv::Rect(5, 5, 10, 10)).setTo(255);
  mask(cv::Rect(25, 5, 10, 10)).setTo(255);
  const InvariantImage out = ComputeInvariantImage(images, std::vector<cv::Mat>(3, mask));
  const double mean_log = (std::log(10.0) + std::log(20.0) + std::log(30.0)) / 3.0;
  EXPECT_NEAR(out.log_invariant.at<float>(10, 10), mean_log, 1e-5);
  EXPECT_NEAR(out.log_invariant.at<float>(10, 30), mean_log + std::log(5.0), 1e-5);
}

TEST(InvariantImage, RejectsOneLightingMismatchedSizesAndNaN) {
  const cv::Mat a = cv::Mat::ones(8, 8, CV_8UC3);
  try {
    ComputeInvariantImage({a});
    FAIL() << "one image accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("single lighting"), std::string::npos) << e.what();
  }
  try {
    ComputeInvariantImage({a, a, cv::Mat::ones(8, 9, CV_8UC3)});
    FAIL() << "mismatched sizes accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("image 2"), std::string::npos) << e.what();
  }
  cv::Mat nan = cv::Mat::ones(8, 8, CV_32FC3);
  nan.at<cv::Vec3f>(2, 2)[1] = std::nanf("");
  EXPECT_THROW(ComputeInvariantImage({nan, nan}), std::invalid_argument);
  InvariantImageOptions no_floor;
  no_floor.min_intensity = 0.0;
  EXPECT_THROW(ComputeInvariantImage({a, a}, {}, no_floor), std::invalid_argument);
  EXPECT_THROW(ComputeInvariantImage({a, a}, {cv::Mat()}), std::invalid_argument);
}

// --- Real data: the MIT Intrinsic Images objects of the shared data --------------------------

std::string SharedData(const std::string& name) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const std::string path = std::string(shared ? shared : "") + "/" + name;
  return shared && std::filesystem::exists(path) ? path : "";
}

// R G B (or grey) as float on the 0…255 scale.
cv::Mat ReadRgb(const std::string& path) {
  cv::Mat bgr = cv::imread(path, cv::IMREAD_UNCHANGED), rgb;
  if (bgr.empty()) throw std::runtime_error("cannot read " + path);
  if (bgr.channels() == 3)
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  else
    rgb = bgr;
  return core::ToFloat255(rgb);
}

cv::Mat Grey(const cv::Mat& rgb) {
  return core::ChannelMean(rgb);
}

struct MitScores {
  eval::IntrinsicScore grey, per_channel, luminance_chromaticity;
};

// The benchmark's protocol: the object's mask as every image's coverage, shading = diffuse
// image / estimated reflectance (per channel, then averaged), reflectance truth in grey for the
// grey estimator.
MitScores ScoreMitObject(const std::string& dir) {
  std::vector<cv::Mat> lights, grey_lights;
  for (int i = 1; i <= 10; ++i) {
    lights.push_back(ReadRgb(dir + cv::format("/light%02d.png", i)));
    grey_lights.push_back(Grey(lights.back()));
  }
  const cv::Mat mask = Grey(ReadRgb(dir + "/mask.png")) > 0;
  const cv::Mat diffuse = ReadRgb(dir + "/diffuse.png");
  const cv::Mat true_shading = Grey(ReadRgb(dir + "/shading.png"));
  const cv::Mat true_reflectance = ReadRgb(dir + "/reflectance.png");
  const std::vector<cv::Mat> coverage(10, mask);
  auto score = [&](const std::vector<cv::Mat>& images, const cv::Mat& image, const cv::Mat& truth,
                   InvariantImageOptions::Colour colour) {
    InvariantImageOptions options;
    options.colour = colour;
    const InvariantImage out = ComputeInvariantImage(images, coverage, options);
    const cv::Mat reflectance = LinearImage(out.log_invariant, mask);
    cv::Mat shading;
    cv::divide(image, reflectance, shading);
    shading.setTo(cv::Scalar::all(0), mask == 0);
    return eval::ScoreIntrinsic(true_shading, truth, Grey(shading), reflectance, mask);
  };
  using Colour = InvariantImageOptions::Colour;
  return {score(grey_lights, Grey(diffuse), Grey(true_reflectance), Colour::kPerChannel),
          score(lights, diffuse, true_reflectance, Colour::kPerChannel),
          score(lights, diffuse, true_reflectance, Colour::kLuminanceChromaticity)};
}

TEST(InvariantImage, MitIntrinsicObjectsMatchOrBeatTheGreyReferenceEstimator) {
  const std::string root = SharedData("mit-intrinsic");
  if (root.empty()) GTEST_SKIP() << "mit-intrinsic/ of the shared test data is absent";
  double grey = 0.0, per_channel = 0.0, luminance_chromaticity = 0.0;
  for (const char* object : {"box", "cup1", "panther", "sun"}) {
    const MitScores s = ScoreMitObject(root + "/" + object);
    std::cout << object << ": LMSE grey " << s.grey.lmse << ", colour per channel "
              << s.per_channel.lmse << ", colour luminance + chromaticity "
              << s.luminance_chromaticity.lmse << " (shading " << s.luminance_chromaticity.shading
              << ", reflectance " << s.luminance_chromaticity.reflectance << ")\n";
    grey += s.grey.lmse / 4.0;
    per_channel += s.per_channel.lmse / 4.0;
    luminance_chromaticity += s.luminance_chromaticity.lmse / 4.0;
  }
  std::cout << "mean LMSE: grey " << grey << ", colour per channel " << per_channel
            << ", colour luminance + chromaticity " << luminance_chromaticity << "\n";
  // Our grey estimator is the reference's formulation (median, clip at 3, least squares in the
  // mask), so it must reproduce the reference's mean of 0.0127 on these four crops closely.
  EXPECT_NEAR(grey, 0.0127, 0.0015);
  // The target: in colour, match or beat that reference.
  EXPECT_LE(luminance_chromaticity, 0.0127);
  // The thesis's per-channel colour must not fall far behind the grey one (its channels are
  // noisier than their mean; measured 0.0128).
  EXPECT_LE(per_channel, 0.0127 * 1.05);
}

}  // namespace
}  // namespace novelty::illumination
