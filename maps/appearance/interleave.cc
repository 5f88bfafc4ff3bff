#include "maps/appearance/interleave.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "maps/stats/lanes.h"

namespace novelty::appearance {

namespace {

constexpr int kMaxChannels = 32;

// One element as float: 8-bit, half-float bits, or float.
inline float ToFloat(uchar v) {
  return float(v);
}
inline float ToFloat(uint16_t bits) {
  return stats::lanes::HalfToFloat(uint32_t(bits));
}
inline float ToFloat(float v) {
  return v;
}

// One row, with the channel count N known to the compiler: the strided loops then vectorise
// with permutes, several times faster than gathers or scatters (N = 0: `channels` at run time).
template <int N, class In>
void SplitRow(const In* in, int channels, int cols, float* const* out) {
  const int n = N > 0 ? N : channels;
  for (int x = 0; x < cols; ++x)
    for (int c = 0; c < n; ++c) out[c][x] = ToFloat(in[x * n + c]);
}
template <int N>
void MergeRow(const float* const* in, int channels, int cols, float* out) {
  const int n = N > 0 ? N : channels;
  for (int x = 0; x < cols; ++x)
    for (int c = 0; c < n; ++c) out[x * n + c] = in[c][x];
}

// The row function for a channel count: compiled for the counts the map uses, else generic.
template <class In>
auto SplitRowFor(int channels) {
  switch (channels) {
    case 1:
      return &SplitRow<1, In>;
    case 3:
      return &SplitRow<3, In>;
    case 7:
      return &SplitRow<7, In>;
    default:
      return &SplitRow<0, In>;
  }
}
auto MergeRowFor(int channels) {
  switch (channels) {
    case 1:
      return &MergeRow<1>;
    case 3:
      return &MergeRow<3>;
    case 7:
      return &MergeRow<7>;
    default:
      return &MergeRow<0>;
  }
}

template <class In>
void SplitRows(const cv::Mat& rows, std::vector<cv::Mat>& planes) {
  const auto split_row = SplitRowFor<In>(rows.channels());
  std::array<float*, kMaxChannels> out;
  for (int y = 0; y < rows.rows; ++y) {
    for (std::size_t c = 0; c < planes.size(); ++c) out[c] = planes[c].ptr<float>(y);
    split_row(rows.ptr<In>(y), rows.channels(), rows.cols, out.data());
  }
}

// Float to half, rounded to nearest even (as cv::Mat::convertTo): sixteen at a time where the
// CPU has a conversion instruction.
void StoreHalves(const float* in, int n, uchar* out) {
  int i = 0;
#if defined(__AVX512F__)
  for (; i + stats::lanes::kLanes <= n; i += stats::lanes::kLanes) {
    const __m256i h =
        _mm512_cvtps_ph(_mm512_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + 2 * i), h);
  }
#endif
  for (; i < n; ++i) {
    const ushort bits = cv::float16_t(in[i]).bits();
    std::memcpy(out + 2 * i, &bits, 2);
  }
}

}  // namespace

void SplitToFloat(const cv::Mat& rows, std::vector<cv::Mat>& planes) {
  const int depth = rows.depth(), channels = rows.channels();
  if ((depth != CV_8U && depth != CV_16F && depth != CV_32F) || channels > kMaxChannels) {
    throw std::invalid_argument("SplitToFloat: expected 8-bit, half or float rows of at most " +
                                std::to_string(kMaxChannels) + " channels, got OpenCV type " +
                                std::to_string(rows.type()));
  }
  planes.resize(std::size_t(channels));
  for (cv::Mat& p : planes) p.create(rows.size(), CV_32FC1);
  if (depth == CV_8U) {
    SplitRows<uchar>(rows, planes);
  } else if (depth == CV_16F) {
    SplitRows<uint16_t>(rows, planes);
  } else {
    SplitRows<float>(rows, planes);
  }
}

void MergeInto(const std::vector<cv::Mat>& planes, cv::Mat& out) {
  const int channels = out.channels();
  bool ok = (out.depth() == CV_16F || out.depth() == CV_32F) && channels <= kMaxChannels &&
            int(planes.size()) == channels;
  for (const cv::Mat& p : planes) ok = ok && p.type() == CV_32FC1 && p.size() == out.size();
  if (!ok) {
    throw std::invalid_argument(
        "MergeInto: need one CV_32FC1 plane of the output's size per channel of a half or float "
        "output, got " +
        std::to_string(planes.size()) + " planes for OpenCV type " + std::to_string(out.type()));
  }
  const auto merge_row = MergeRowFor(channels);
  std::array<const float*, kMaxChannels> in;
  std::vector<float> row_floats(out.depth() == CV_16F ? std::size_t(out.cols) * channels : 0);
  for (int y = 0; y < out.rows; ++y) {
    for (std::size_t c = 0; c < planes.size(); ++c) in[c] = planes[c].ptr<float>(y);
    float* row = out.depth() == CV_32F ? out.ptr<float>(y) : row_floats.data();
    merge_row(in.data(), channels, out.cols, row);
    if (out.depth() == CV_16F) StoreHalves(row, out.cols * channels, out.ptr(y));
  }
}

}  // namespace novelty::appearance
