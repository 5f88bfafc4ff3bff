#include "maps/illumination/gradient_integration.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <opencv2/core.hpp>

namespace novelty::illumination {
namespace {

cv::Mat RandomImage(int rows, int cols, int seed, double amplitude = 1.0) {
  cv::RNG rng(seed);
  cv::Mat m(rows, cols, CV_32F);
  rng.fill(m, cv::RNG::UNIFORM, -amplitude, amplitude);
  return m;
}

// Forward differences with the last column of gx and the last row of gy 0.
void ForwardDifferences(const cv::Mat& r, cv::Mat& gx, cv::Mat& gy) {
  gx = cv::Mat::zeros(r.size(), CV_32F);
  gy = cv::Mat::zeros(r.size(), CV_32F);
  for (int y = 0; y < r.rows; ++y)
    for (int x = 0; x < r.cols; ++x) {
      if (x + 1 < r.cols) gx.at<float>(y, x) = r.at<float>(y, x + 1) - r.at<float>(y, x);
      if (y + 1 < r.rows) gy.at<float>(y, x) = r.at<float>(y + 1, x) - r.at<float>(y, x);
    }
}

cv::Mat MinusMean(const cv::Mat& m) {
  return m - cv::mean(m)[0];
}

// Independent reference: the least-squares problem written out as a dense constraint matrix D
// (one row per pixel pair, r(q) - r(p) = g) and solved in double precision by complete
// orthogonal decomposition (minimum-norm solution, which has mean 0 on a connected image).
cv::Mat DenseLeastSquares(const cv::Mat& gx, const cv::Mat& gy) {
  const int w = gx.cols, h = gx.rows, n = w * h;
  const int m = (w - 1) * h + w * (h - 1);
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(m, n);
  Eigen::VectorXd g(m);
  int row = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x + 1 < w) {
        d(row, y * w + x + 1) = 1.0, d(row, y * w + x) = -1.0, g[row] = gx.at<float>(y, x);
        ++row;
      }
      if (y + 1 < h) {
        d(row, (y + 1) * w + x) = 1.0, d(row, y * w + x) = -1.0, g[row] = gy.at<float>(y, x);
        ++row;
      }
    }
  const Eigen::VectorXd r = d.completeOrthogonalDecomposition().solve(g);
  cv::Mat out(h, w, CV_32F);
  for (int i = 0; i < n; ++i) out.at<float>(i / w, i % w) = float(r[i]);
  return MinusMean(out);
}

TEST(GradientIntegration, RecoversAnImageFromItsExactGradientsEvenAndOddSizes) {
  // Even sizes go through the DCT, odd ones through the mirrored FFT: both must be exact.
  for (cv::Size size : {cv::Size(32, 24), cv::Size(33, 25), cv::Size(32, 25), cv::Size(1, 7)}) {
    const cv::Mat r = RandomImage(size.height, size.width, 1 + size.area());
    cv::Mat gx, gy;
    ForwardDifferences(r, gx, gy);
    const cv::Mat recovered = IntegrateGradients(gx, gy);
    EXPECT_LT(cv::norm(recovered, MinusMean(r), cv::NORM_INF), 1e-4) << size;
    EXPECT_NEAR(cv::mean(recovered)[0], 0.0, 1e-6);
  }
}

TEST(GradientIntegration, IsTheLeastSquaresSolutionOfAFieldThatIsNoGradient) {
  // Independent gx, gy (curl ≠ 0): no image has them; the result must be the least-squares one.
  for (cv::Size size : {cv::Size(8, 6), cv::Size(7, 5)}) {
    const cv::Mat gx = RandomImage(size.height, size.width, 7);
    const cv::Mat gy = RandomImage(size.height, size.width, 8);
    const cv::Mat reference = DenseLeastSquares(gx, gy);
    EXPECT_LT(cv::norm(IntegrateGradients(gx, gy), reference, cv::NORM_INF), 1e-5) << size;
    const cv::Mat all(size, CV_8U, cv::Scalar(255));
    EXPECT_LT(cv::norm(IntegrateGradientsInRegion(gx, gy, all), reference, cv::NORM_INF), 1e-5)
        << size;
  }
}

TEST(GradientIntegration, FourierAndSparseSolutionsAgreeOnAFullFrame) {
  const cv::Mat gx = RandomImage(60, 80, 3, 0.3), gy = RandomImage(60, 80, 4, 0.3);
  const cv::Mat all(gx.size(), CV_8U, cv::Scalar(255));
  EXPECT_LT(
      cv::norm(IntegrateGradients(gx, gy), IntegrateGradientsInRegion(gx, gy, all), cv::NORM_INF),
      1e-4);
}

TEST(GradientIntegration, ARegionIgnoresGradientsThatLeaveItAndSolvesEachPartAlone) {
  const cv::Mat r = RandomImage(20, 30, 5);
  cv::Mat gx, gy;
  ForwardDifferences(r, gx, gy);
  // Garbage across the region's borders and outside must not matter.
  cv::Mat region = cv::Mat::zeros(r.size(), CV_8U);
  region(cv::Rect(2, 3, 10, 12)).setTo(255);
  region(cv::Rect(16, 5, 9, 9)).setTo(255);
  region.at<uchar>(18, 28) = 255;  // a lone pixel: its own part, value 0
  const cv::Mat outside = region == 0;
  cv::Mat noisy_gx = gx.clone(), noisy_gy = gy.clone();
  RandomImage(20, 30, 6, 50.0).copyTo(noisy_gx, outside);
  RandomImage(20, 30, 9, 50.0).copyTo(noisy_gy, outside);
  const cv::Mat recovered = IntegrateGradientsInRegion(noisy_gx, noisy_gy, region);
  for (cv::Rect part : {cv::Rect(2, 3, 10, 12), cv::Rect(16, 5, 9, 9)}) {
    EXPECT_LT(cv::norm(recovered(part), MinusMean(r(part)), cv::NORM_INF), 1e-4) << part;
  }
  EXPECT_EQ(recovered.at<float>(18, 28), 0.0f);
  EXPECT_EQ(cv::countNonZero((recovered != 0) & outside), 0);
}

TEST(GradientIntegration, RejectsMismatchedOrNonFiniteInput) {
  const cv::Mat g = cv::Mat::zeros(4, 4, CV_32F);
  EXPECT_THROW(IntegrateGradients(g, cv::Mat::zeros(4, 5, CV_32F)), std::invalid_argument);
  EXPECT_THROW(IntegrateGradients(g, cv::Mat::zeros(4, 4, CV_64F)), std::invalid_argument);
  cv::Mat nan = g.clone();
  nan.at<float>(1, 1) = std::nanf("");
  EXPECT_THROW(IntegrateGradients(nan, g), std::invalid_argument);
  EXPECT_THROW(IntegrateGradientsInRegion(g, g, cv::Mat::zeros(4, 4, CV_32F)),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
