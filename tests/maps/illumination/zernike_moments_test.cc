#include "maps/illumination/zernike_moments.h"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(ZernikeMoments, CountsAndTheMomentOfAFullSquare) {
  EXPECT_EQ(ZernikeMoments::Count(120), 3721);
  const ZernikeMoments z({8, 16});
  EXPECT_EQ(z.size(), ZernikeMoments::Count(8));
  // f = 1 on the whole square inscribed in the unit disc: A_00 = (1/π) · area = 2/π, and by the
  // square's symmetry A_nm = 0 unless m is a multiple of 4 (to 1e-7: cv::resize, which brings
  // the shape to the cell grid, rounds to single precision).
  const auto a = z.Moments(cv::Mat(10, 10, CV_8U, cv::Scalar(255)));
  EXPECT_NEAR(a[0].real(), 2.0 / M_PI, 1e-7);
  EXPECT_NEAR(a[0].imag(), 0.0, 1e-12);
  int k = 0;
  for (int n = 0; n <= 8; ++n)
    for (int m = n % 2; m <= n; m += 2, ++k) {
      if (m % 4) {
        EXPECT_LT(std::abs(a[k]), 1e-7) << n << " " << m;
      }
    }
}

cv::Mat LShape(int size) {
  cv::Mat s = cv::Mat::zeros(size, size, CV_8U);
  s(cv::Rect(size / 8, size / 8, size / 4, size * 3 / 4)).setTo(255);
  s(cv::Rect(size / 8, size * 5 / 8, size * 3 / 4, size / 4)).setTo(255);
  return s;
}

TEST(ZernikeMoments, MagnitudesIgnoreQuarterTurnsAndTellShapesApart) {
  const ZernikeMoments z;  // order 120, grid 32
  const cv::Mat l = LShape(64);
  cv::Mat turned, disc = cv::Mat::zeros(64, 64, CV_8U);
  cv::rotate(l, turned, cv::ROTATE_90_CLOCKWISE);
  cv::circle(disc, {32, 32}, 24, cv::Scalar(255), cv::FILLED);
  const auto dl = z.Magnitudes(l), dt = z.Magnitudes(turned), dd = z.Magnitudes(disc);
  // A quarter turn maps the cell grid onto itself: equal up to rounding.
  EXPECT_LT(DescriptorDistance(dl, dt), 1e-4 * DescriptorDistance(dl, dd));
  // The same L drawn at twice the resolution is nearly the same descriptor; a disc is not.
  EXPECT_LT(DescriptorDistance(dl, z.Magnitudes(LShape(128))), 0.2 * DescriptorDistance(dl, dd));
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
