#include "maps/illumination/zernike_moments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace novelty::illumination {
namespace {

// Eq. 6.23 as written, in long double: fine for small n, where it is the independent check.
long double ExplicitRadial(int n, int m, long double rho) {
  long double sum = 0.0L;
  for (int s = 0; s <= (n - m) / 2; ++s)
    sum += (s % 2 ? -1.0L : 1.0L) * std::tgamma((long double)(n - s + 1)) /
           (std::tgamma((long double)(s + 1)) * std::tgamma((long double)((n + m) / 2 - s + 1)) *
            std::tgamma((long double)((n - m) / 2 - s + 1))) *
           std::pow(rho, (long double)(n - 2 * s));
  return sum;
}

TEST(ZernikeMoments, RecursionEqualsTheExplicitSumWhereThatIsAccurate) {
  for (int n = 0; n <= 24; ++n)
    for (int m = n % 2; m <= n; m += 2)
      for (double rho : {0.0, 0.13, 0.5, 0.77, 0.99, 1.0})
        EXPECT_NEAR(ZernikeMoments::Radial(n, m, rho), double(ExplicitRadial(n, m, rho)), 1e-10)
            << n << " " << m << " " << rho;
  EXPECT_NEAR(ZernikeMoments::Radial(120, 0, 1.0), 1.0, 1e-12);  // R_nm(1) = 1
  EXPECT_NEAR(ZernikeMoments::Radial(120, 40, 1.0), 1.0, 1e-12);
  // High orders against eq. 6.23 in exact rational arithmetic (Python's fractions).
  EXPECT_NEAR(ZernikeMoments::Radial(120, 0, 0.5), 0.10643680647123466, 1e-12);
  EXPECT_NEAR(ZernikeMoments::Radial(120, 2, 0.3), 0.0005007780271375013, 1e-12);
  EXPECT_NEAR(ZernikeMoments::Radial(119, 59, 0.5), 0.15746728203797655, 1e-12);
  EXPECT_NEAR(ZernikeMoments::Radial(119, 59, 0.9), -0.028844032204799974, 1e-12);
}

// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_k, double precision).
void GaussLegendre(int k, std::vector<double>& x, std::vector<double>& w) {
  x.resize(k);
  w.resize(k);
  for (int i = 0; i < k; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (k + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;
      for (int j = 2; j <= k; ++j) {
        const double p2 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = k * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = 0.5 * (z + 1.0);
    w[i] = 1.0 / ((1.0 - z * z) * dp * dp);  // 2 / ((1 - z²) P'²) halved for [0, 1]
  }
}

TEST(ZernikeMoments, RadialPolynomialsAreOrthogonalUpToOrder120) {
  // ∫₀¹ R_nm R_n'm ρ dρ = δ_nn' / (2(n + 1)); the integrand has degree ≤ 241, exact with 130
  // nodes. Eq. 6.23 evaluated in double fails this by orders of magnitude at n = 120.
  std::vector<double> x, w;
  GaussLegendre(130, x, w);
  double worst = 0.0;
  for (int m : {0, 1, 2, 7, 30, 59, 100}) {
    std::vector<std::vector<double>> r(121, std::vector<double>(x.size()));
    for (int n = m; n <= 120; n += 2)
      for (size_t i = 0; i < x.size(); ++i) r[n][i] = ZernikeMoments::Radial(n, m, x[i]);
    for (int n = m; n <= 120; n += 2) {
      for (int n2 = n; n2 <= 120; n2 += 2) {
        double integral = 0.0;
        for (size_t i = 0; i < x.size(); ++i) integral += w[i] * r[n][i] * r[n2][i] * x[i];
        const double expected = n == n2 ? 1.0 / (2.0 * (n + 1)) : 0.0;
        worst = std::max(worst, std::abs(integral - expected) * 2.0 * (n + 1));
      }
    }
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(ZernikeMoments, CountsAndTheMomentsOfASquare) {
  EXPECT_EQ(ZernikeMoments::Count(120), 3721);
  const ZernikeMoments z({8, 64});
  EXPECT_EQ(z.size(), ZernikeMoments::Count(8));
  // A 40 × 40 square: centroid at its centre, its corners' far corners on the rim (R = 20√2),
  // so it is the square inscribed in the unit disc: A_00 = (1/π) · area = 2/π (to the cells'
  // sampling of its edges), and by its symmetry A_nm = 0 unless m is a multiple of 4.
  cv::Mat square = cv::Mat::zeros(60, 60, CV_8U);
  square(cv::Rect(10, 10, 40, 40)).setTo(255);
  const auto a = z.Moments(square);
  EXPECT_NEAR(a[0].real(), 2.0 / M_PI, 0.01);
  EXPECT_NEAR(a[0].imag(), 0.0, 1e-12);
  int k = 0;
  for (int n = 0; n <= 8; ++n) {
    for (int m = n % 2; m <= n; m += 2, ++k) {
      if (m % 4) {
        EXPECT_LT(std::abs(a[k]), 1e-6) << n << " " << m;
      }
    }
  }
  // Where it is drawn and how large does not matter (translation and scale drop out).
  cv::Mat moved = cv::Mat::zeros(200, 150, CV_8U);
  moved(cv::Rect(70, 90, 80, 80)).setTo(255);
  const auto b = z.Moments(moved);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(std::abs(a[i]), std::abs(b[i]), 0.01) << i;
  // An empty shape has no moments.
  for (const auto& v : z.Moments(cv::Mat::zeros(5, 5, CV_8U))) EXPECT_EQ(v, 0.0);
}

cv::Mat LShape(int size) {
  cv::Mat s = cv::Mat::zeros(size, size, CV_8U);
  s(cv::Rect(size / 8, size / 8, size / 4, size * 3 / 4)).setTo(255);
  s(cv::Rect(size / 8, size * 5 / 8, size * 3 / 4, size / 4)).setTo(255);
  return s;
}

cv::Mat Rotated(const cv::Mat& shape, double degrees) {
  cv::Mat out;
  const cv::Point2f centre(shape.cols / 2.0f, shape.rows / 2.0f);
  cv::warpAffine(shape, out, cv::getRotationMatrix2D(centre, degrees, 1.0), shape.size(),
                 cv::INTER_LINEAR);
  return out;
}

std::vector<cv::Mat> Shapes() {
  std::vector<cv::Mat> shapes(4);
  for (cv::Mat& s : shapes) s = cv::Mat::zeros(96, 96, CV_8U);
  cv::ellipse(shapes[0], {48, 48}, {30, 12}, 0, 0, 360, cv::Scalar(255), cv::FILLED);
  LShape(64).copyTo(shapes[1](cv::Rect(16, 16, 64, 64)));
  shapes[2](cv::Rect(28, 28, 40, 40)).setTo(255);
  const std::vector<cv::Point> triangle = {{20, 76}, {76, 76}, {30, 22}};
  cv::fillConvexPoly(shapes[3], triangle, cv::Scalar(255));
  return shapes;
}

// Each shape turned by 30° against its own descriptor and the nearest other shape's: the largest
// ratio of the two distances over the four shapes.
double WorstRotationRatio(const ZernikeMoments& z) {
  const std::vector<cv::Mat> shapes = Shapes();
  std::vector<std::vector<float>> d;
  for (const cv::Mat& s : shapes) d.push_back(z.Magnitudes(s));
  double worst = 0.0;
  for (size_t i = 0; i < shapes.size(); ++i) {
    const double self = DescriptorDistance(d[i], z.Magnitudes(Rotated(shapes[i], 30.0)));
    double other = 1e300;
    for (size_t j = 0; j < shapes.size(); ++j)
      if (j != i) other = std::min(other, DescriptorDistance(d[i], d[j]));
    worst = std::max(worst, self / other);
  }
  return worst;
}

TEST(ZernikeMoments, MagnitudesIgnoreRotationsAndTellShapesApart) {
  // The property the shape memory of 6.3 relies on: a shape turned by 30° stays nearer its own
  // descriptor than any other shape's — with the default options (order 20, 32 cells) by a
  // factor of two.
  const ZernikeMoments z;
  const double worst = WorstRotationRatio(z);
  std::cout << "order 20, grid 32: worst turned / other distance " << worst << "\n";
  EXPECT_LT(worst, 0.5);
  // A quarter turn about the centroid maps the cell grid onto itself: nearly equal.
  const std::vector<cv::Mat> shapes = Shapes();
  cv::Mat turned;
  cv::rotate(shapes[1], turned, cv::ROTATE_90_CLOCKWISE);
  EXPECT_LT(DescriptorDistance(z.Magnitudes(shapes[1]), z.Magnitudes(turned)),
            0.1 * DescriptorDistance(z.Magnitudes(shapes[1]), z.Magnitudes(shapes[0])));
}

TEST(ZernikeMoments, OrderOneHundredTwentyNeedsAFineGrid) {
  // The thesis's order 120 tells a turned shape from another only on a fine grid: on 128 cells
  // each turned shape is still nearest its own; on 32 cells sampling noise of the high orders
  // outweighs the shape (the reason for the default of order 20).
  EXPECT_LT(WorstRotationRatio(ZernikeMoments({120, 128})), 1.0);
  EXPECT_GT(WorstRotationRatio(ZernikeMoments({120, 32})), 0.5);
}

TEST(ZernikeMoments, AThinShapeIsDescribedLikeTheSameShapeInALargerMask) {
  // A line one pixel high and 200 long (a shadow's edge): scaled to the disc it would shrink to
  // no row at all. Its descriptor is that of the same line anywhere in a larger mask (translation
  // drops out), and a line differs from a square.
  const ZernikeMoments z;
  const cv::Mat line(1, 200, CV_8U, cv::Scalar(255));
  cv::Mat framed = cv::Mat::zeros(40, 260, CV_8U);
  line.copyTo(framed(cv::Rect(30, 17, 200, 1)));
  const std::vector<float> a = z.Magnitudes(line), b = z.Magnitudes(framed);
  const cv::Mat square(20, 20, CV_8U, cv::Scalar(255));
  EXPECT_LT(DescriptorDistance(a, b), 0.05 * DescriptorDistance(a, z.Magnitudes(square)));
  EXPECT_GT(std::abs(a[2]), 0.0f);  // not the empty shape's zeros
}

TEST(ZernikeMoments, RejectsBadOptionsAndShapes) {
  EXPECT_THROW(ZernikeMoments({-1, 32}), std::invalid_argument);
  EXPECT_THROW(ZernikeMoments({120, 1}), std::invalid_argument);
  const ZernikeMoments z({4, 8});
  EXPECT_THROW(z.Moments(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(z.Moments(cv::Mat::zeros(4, 4, CV_8UC3)), std::invalid_argument);
  EXPECT_THROW(DescriptorDistance({1.0f}, {1.0f, 2.0f}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
