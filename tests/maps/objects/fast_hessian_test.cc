#include "maps/objects/fast_hessian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "maps/objects/box_filters.h"

namespace novelty::objects {
namespace {

// Bay et al.'s box filters written out pixel by pixel (fig. 1 of the paper, scaled to side L):
// an independent check of the integral-image arithmetic.
double ExplicitDeterminant(const cv::Mat& img, int row, int col, int size) {
  const int b = (size - 1) / 2, l = size / 3;
  double dxx = 0, dyy = 0, dxy = 0;
  for (int dy = -b; dy <= b; ++dy) {
    for (int dx = -b; dx <= b; ++dx) {
      const double v = img.at<double>(row + dy, col + dx);
      if (std::abs(dy) <= l - 1) dxx += v * (std::abs(dx) <= l / 2 ? -2.0 : 1.0);
      if (std::abs(dx) <= l - 1) dyy += v * (std::abs(dy) <= l / 2 ? -2.0 : 1.0);
      if (dx != 0 && dy != 0 && std::abs(dx) <= l && std::abs(dy) <= l)
        dxy += v * ((dx > 0) == (dy > 0) ? 1.0 : -1.0);
    }
  }
  const double a = double(size) * size;
  return (dxx * dyy - 0.81 * dxy * dxy) / (a * a);
}

TEST(FastHessian, BoxFiltersEqualTheFiltersWrittenOut) {
  cv::Mat img(120, 120, CV_64F);
  cv::RNG rng(7);
  rng.fill(img, cv::RNG::UNIFORM, 0.0, 1.0);
  const cv::Mat integral = UnitIntegral(img);
  for (int size : {9, 15, 21, 27, 39, 51}) {
    for (int k = 0; k < 20; ++k) {
      const int row = rng.uniform(30, 90), col = rng.uniform(30, 90);
      const double expected = ExplicitDeterminant(img, row, col, size);
      EXPECT_NEAR(HessianDeterminant(integral, row, col, size, nullptr), expected,
                  1e-6 * std::abs(expected) + 1e-12)
          << "L = " << size << " at " << row << ", " << col;
    }
  }
}

// A Gaussian blob of σ_b: the scale-normalised determinant of the Hessian peaks at its centre
// at a scale proportional to σ_b (with Gaussian derivatives at σ = σ_b exactly: t²·det H ∝
// t²/(t_b + t)⁴ is largest at t = t_b; the boxes smooth more than the Gaussian of σ = 1.2·L/9
// they stand for, so s comes out smaller — about 0.75·σ_b — but in proportion, which is what
// scale invariance needs).
cv::Mat Blob(double cx, double cy, double sigma, double contrast) {
  cv::Mat img(160, 160, CV_64F);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x)
      img.at<double>(y, x) =
          0.5 + contrast * std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) /
                                    (2 * sigma * sigma));
  return img;
}

TEST(FastHessian, FindsABlobAtItsCentreAtAScaleInProportionToItsSize) {
  const std::vector<double> sigmas = {2.5, 4.0, 7.0};
  for (double contrast : {-0.4, 0.4}) {
    std::vector<double> scales;
    for (double sigma : sigmas) {
      const double cx = 80.3, cy = 76.6;
      const std::vector<HessianPoint> points =
          DetectFastHessian(UnitIntegral(Blob(cx, cy, sigma, contrast)));
      ASSERT_FALSE(points.empty()) << "σ " << sigma;
      const HessianPoint& p = *std::max_element(
          points.begin(), points.end(),
          [](const HessianPoint& a, const HessianPoint& b) { return a.response < b.response; });
      EXPECT_NEAR(p.pt.x, cx, 0.5) << "σ " << sigma;
      EXPECT_NEAR(p.pt.y, cy, 0.5) << "σ " << sigma;
      EXPECT_EQ(p.laplacian, contrast < 0 ? 1 : -1) << "a dark blob has a positive trace";
      scales.push_back(p.scale);
    }
    for (std::size_t i = 1; i < sigmas.size(); ++i) {
      EXPECT_NEAR(scales[i] / scales[0], sigmas[i] / sigmas[0], 0.1 * sigmas[i] / sigmas[0])
          << "s(σ " << sigmas[i] << ") / s(σ " << sigmas[0] << ")";
    }
  }
}

TEST(FastHessian, AFlatImageHasNoKeypointsAndBadInputIsRejected) {
  EXPECT_TRUE(DetectFastHessian(UnitIntegral(cv::Mat(100, 100, CV_64F, cv::Scalar(0.5)))).empty());
  EXPECT_THROW(DetectFastHessian(cv::Mat(10, 10, CV_32F)), std::invalid_argument);
  FastHessianOptions o;
  o.octaves = 0;
  EXPECT_THROW(DetectFastHessian(UnitIntegral(cv::Mat(100, 100, CV_64F, cv::Scalar(0.5))), o),
               std::invalid_argument);
  o = {};
  o.threshold = std::nan("");
  EXPECT_THROW(DetectFastHessian(UnitIntegral(cv::Mat(100, 100, CV_64F, cv::Scalar(0.5))), o),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
