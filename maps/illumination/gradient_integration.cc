#include "maps/illumination/gradient_integration.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace novelty::illumination {

namespace {

void CheckGradients(const cv::Mat& gx, const cv::Mat& gy, const char* who) {
  if (gx.empty() || gx.type() != CV_32FC1 || gy.type() != CV_32FC1 || gx.size() != gy.size())
    throw std::invalid_argument(std::string(who) +
                                ": gx and gy must be non-empty CV_32FC1 images of one size");
  if (!cv::checkRange(gx) || !cv::checkRange(gy))
    throw std::invalid_argument(std::string(who) + ": gradients must be finite");
}

// b = gx*f̃^x + gy*f̃^y: the right side of the normal equations, with the constraints that leave
// the image dropped (mirror border).
cv::Mat Divergence(const cv::Mat& gx, const cv::Mat& gy) {
  const int w = gx.cols, h = gx.rows;
  cv::Mat b(gx.size(), CV_32F);
  for (int y = 0; y < h; ++y) {
    const float* gxr = gx.ptr<float>(y);
    const float* gyr = gy.ptr<float>(y);
    const float* gyu = y > 0 ? gy.ptr<float>(y - 1) : nullptr;
    float* out = b.ptr<float>(y);
    for (int x = 0; x < w; ++x) {
      float v = 0.0f;
      if (x > 0) v += gxr[x - 1];
      if (x < w - 1) v -= gxr[x];
      if (gyu) v += gyu[x];
      if (y < h - 1) v -= gyr[x];
      out[x] = v;
    }
  }
  return b;
}

// Eigenvalue of the 1-D mirrored second difference for frequency k of a period-n transform.
double Eigen1d(int k, int n) {
  return 2.0 - 2.0 * std::cos(2.0 * M_PI * k / n);
}

// Even sizes: the DCT-II diagonalises the mirrored Laplacian (eigenvalues for period 2n).
cv::Mat SolveDct(const cv::Mat& b) {
  cv::Mat spectrum;
  cv::dct(b, spectrum);
  const int w = b.cols, h = b.rows;
  std::vector<double> ex(w), ey(h);
  for (int k = 0; k < w; ++k) ex[k] = Eigen1d(k, 2 * w);
  for (int k = 0; k < h; ++k) ey[k] = Eigen1d(k, 2 * h);
  for (int y = 0; y < h; ++y) {
    float* s = spectrum.ptr<float>(y);
    for (int x = 0; x < w; ++x) {
      const double lambda = ex[x] + ey[y];
      s[x] = lambda > 0.0 ? float(s[x] / lambda) : 0.0f;  // the constant is free: mean 0
    }
  }
  cv::Mat r;
  cv::dct(spectrum, r, cv::DCT_INVERSE);
  return r;
}

// Any size: the FFT pseudo-inverse of the thesis on the image mirrored to 2h × 2w.
cv::Mat SolveMirroredDft(const cv::Mat& b) {
  const int w = b.cols, h = b.rows;
  cv::Mat mirrored(2 * h, 2 * w, CV_32F);
  for (int y = 0; y < 2 * h; ++y) {
    const float* src = b.ptr<float>(y < h ? y : 2 * h - 1 - y);
    float* out = mirrored.ptr<float>(y);
    for (int x = 0; x < 2 * w; ++x) out[x] = src[x < w ? x : 2 * w - 1 - x];
  }
  cv::Mat spectrum;
  cv::dft(mirrored, spectrum, cv::DFT_COMPLEX_OUTPUT);
  for (int y = 0; y < 2 * h; ++y) {
    cv::Vec2f* s = spectrum.ptr<cv::Vec2f>(y);
    const double ey = Eigen1d(y, 2 * h);
    for (int x = 0; x < 2 * w; ++x) {
      const double lambda = Eigen1d(x, 2 * w) + ey;
      s[x] = lambda > 0.0 ? s[x] * float(1.0 / lambda) : cv::Vec2f(0.0f, 0.0f);
    }
  }
  cv::Mat r;
  cv::idft(spectrum, r, cv::DFT_REAL_OUTPUT | cv::DFT_SCALE);
  return r(cv::Rect(0, 0, w, h)).clone();
}

}  // namespace

cv::Mat IntegrateGradients(const cv::Mat& gx, const cv::Mat& gy) {
  CheckGradients(gx, gy, "IntegrateGradients");
  const cv::Mat b = Divergence(gx, gy);
  cv::Mat r = (b.cols % 2 == 0 && b.rows % 2 == 0) ? SolveDct(b) : SolveMirroredDft(b);
  r -= cv::mean(r)[0];
  return r;
}

cv::Mat IntegrateGradientsInRegion(const cv::Mat& gx, const cv::Mat& gy, const cv::Mat& region) {
  CheckGradients(gx, gy, "IntegrateGradientsInRegion");
  if (region.type() != CV_8UC1 || region.size() != gx.size())
    throw std::invalid_argument(
        "IntegrateGradientsInRegion: region must be a CV_8UC1 image of the gradients' size");
  cv::Mat labels;
  const int parts = cv::connectedComponents(region != 0, labels, 4, CV_32S);
  // Unknowns: region pixels, except the first pixel of each part, pinned to 0 (the Laplacian of
  // a part is singular by the free constant).
  cv::Mat index(region.size(), CV_32S, cv::Scalar(-1));
  std::vector<bool> pinned(parts, false);
  int n = 0;
  for (int y = 0; y < region.rows; ++y) {
    for (int x = 0; x < region.cols; ++x) {
      const int label = labels.at<int>(y, x);
      if (label == 0) continue;
      if (!pinned[label]) {
        pinned[label] = true;
        continue;
      }
      index.at<int>(y, x) = n++;
    }
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(n) * 5);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  // One constraint r(q) - r(p) ≈ g between two region pixels.
  auto constrain = [&](int p, int q, double g) {
    if (p >= 0) entries.emplace_back(p, p, 1.0), rhs[p] -= g;
    if (q >= 0) entries.emplace_back(q, q, 1.0), rhs[q] += g;
    if (p >= 0 && q >= 0) entries.emplace_back(p, q, -1.0), entries.emplace_back(q, p, -1.0);
  };
  for (int y = 0; y < region.rows; ++y) {
    for (int x = 0; x < region.cols; ++x) {
      if (labels.at<int>(y, x) == 0) continue;
      const int p = index.at<int>(y, x);
      if (x + 1 < region.cols && labels.at<int>(y, x + 1) != 0)
        constrain(p, index.at<int>(y, x + 1), gx.at<float>(y, x));
      if (y + 1 < region.rows && labels.at<int>(y + 1, x) != 0)
        constrain(p, index.at<int>(y + 1, x), gy.at<float>(y, x));
    }
  }
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(n);
  if (n > 0) {
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("IntegrateGradientsInRegion: factorisation failed");
    solution = solver.solve(rhs);
  }
  cv::Mat r = cv::Mat::zeros(region.size(), CV_32F);
  std::vector<double> sum(parts, 0.0);
  std::vector<int> count(parts, 0);
  for (int y = 0; y < region.rows; ++y) {
    for (int x = 0; x < region.cols; ++x) {
      const int label = labels.at<int>(y, x);
      if (label == 0) continue;
      const int i = index.at<int>(y, x);
      const double v = i >= 0 ? solution[i] : 0.0;
      r.at<float>(y, x) = float(v);
      sum[label] += v;
      ++count[label];
    }
  }
  for (int y = 0; y < region.rows; ++y) {
    for (int x = 0; x < region.cols; ++x) {
      const int label = labels.at<int>(y, x);
      if (label != 0) r.at<float>(y, x) -= float(sum[label] / count[label]);
    }
  }
  return r;
}

}  // namespace novelty::illumination
