#include "core/fill_where.h"

#include <array>
#include <stdexcept>
#include <string>

namespace novelty::core {

namespace {

// Pixels of N channels of T: each channel is a select between the pixel and the value, with no
// branch, so that the loop vectorises.
template <class T, int N>
void FillRows(cv::Mat& m, const cv::Mat& mask, const cv::Scalar& value) {
  std::array<T, N> v;
  for (int c = 0; c < N; ++c) v[std::size_t(c)] = cv::saturate_cast<T>(value[c]);
  for (int y = 0; y < m.rows; ++y) {
    T* p = m.ptr<T>(y);
    const uchar* k = mask.ptr<uchar>(y);
    for (int x = 0; x < m.cols; ++x) {
      for (int c = 0; c < N; ++c) p[N * x + c] = k[x] ? v[std::size_t(c)] : p[N * x + c];
    }
  }
}

}  // namespace

void FillWhere(cv::Mat& m, const cv::Mat& mask, const cv::Scalar& value) {
  if (mask.type() != CV_8UC1 || mask.size() != m.size()) {
    throw std::invalid_argument("FillWhere: the mask must be CV_8UC1 of " + std::to_string(m.cols) +
                                "×" + std::to_string(m.rows) + " pixels");
  }
  switch (m.type()) {
    case CV_32FC1:
      return FillRows<float, 1>(m, mask, value);
    case CV_8UC1:
      return FillRows<uchar, 1>(m, mask, value);
    case CV_8UC2:
      return FillRows<uchar, 2>(m, mask, value);
    case CV_8UC3:
      return FillRows<uchar, 3>(m, mask, value);
    case CV_8UC4:
      return FillRows<uchar, 4>(m, mask, value);
    default:
      m.setTo(value, mask);
  }
}

}  // namespace novelty::core
