#include "core/interleave.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/lanes.h"
#include "core/with_count.h"

namespace novelty::core {

namespace {

constexpr int kMaxChannels = 32;

// One element as float: 8-bit, half-float bits, or float.
inline float ToFloat(uchar v) {
  return float(v);
}
inline float ToFloat(uint16_t bits) {
  return core::lanes::HalfToFloat(uint32_t(bits));
}
inline float ToFloat(float v) {
  return v;
}

#if defined(__AVX512F__) && defined(__AVX512BW__)
// Sixteen pixels of N interleaved channels at a time, for the map's half (N = 7) and float
// (N = 3) images: GCC leaves those strided loops scalar (three instructions per value). The
// values of sixteen pixels fill ⌈N/2⌉ (half) or N (float) registers; each channel of them, or
// each register of the interleaved output, is picked with one two-register permute per pair of
// registers. Element e of the interleaved pixels is channel e % N of pixel e / N; element
// 16·c + i of the planar side is channel c of pixel i.
constexpr bool kVectorised = true;

// Per lane k of the result: element idx[k] of the concatenated registers (kPerReg each).
template <int kPerReg>
inline __m512i Pick(const __m512i* regs, int n_regs, __m512i idx) {
  const auto permute = [](__m512i a, __m512i i, __m512i b) {
    if constexpr (kPerReg == 32) return _mm512_permutex2var_epi16(a, i, b);
    return _mm512_permutex2var_epi32(a, i, b);
  };
  __m512i picked = permute(regs[0], idx, n_regs > 1 ? regs[1] : regs[0]);
  for (int p = 2; p < n_regs; p += 2) {
    __m512i local;
    __mmask32 in_pair;  // the lanes whose element lies in registers p, p + 1
    if constexpr (kPerReg == 32) {
      local = _mm512_sub_epi16(idx, _mm512_set1_epi16(short(32 * p)));
      in_pair = _mm512_cmplt_epu16_mask(local, _mm512_set1_epi16(64));
      picked = _mm512_mask_mov_epi16(
          picked, in_pair, permute(regs[p], local, p + 1 < n_regs ? regs[p + 1] : regs[p]));
    } else {
      local = _mm512_sub_epi32(idx, _mm512_set1_epi32(16 * p));
      in_pair = _mm512_cmplt_epu32_mask(local, _mm512_set1_epi32(32));
      picked =
          _mm512_mask_mov_epi32(picked, __mmask16(in_pair),
                                permute(regs[p], local, p + 1 < n_regs ? regs[p + 1] : regs[p]));
    }
  }
  return picked;
}

// Index vectors: for each lane k of register `r`, the element it takes. Split: channel r's pixel
// k (element N·k + r of the interleaved registers). Merge: interleaved element e = kPerReg·r + k,
// channel e % N of pixel e / N (element 16·(e % N) + e / N of the planar registers).
template <int kPerReg>
inline __m512i SplitIndex(int n, int channel) {
  alignas(64) int32_t idx32[16];
  alignas(64) int16_t idx16[32];
  for (int k = 0; k < 32; ++k) {
    const int e = n * (k % 16) + channel;
    if (k < 16) idx32[k] = e;
    idx16[k] = short(e);
  }
  return kPerReg == 32 ? _mm512_load_si512(idx16) : _mm512_load_si512(idx32);
}
template <int kPerReg>
inline __m512i MergeIndex(int n, int reg) {
  alignas(64) int32_t idx32[16];
  alignas(64) int16_t idx16[32];
  for (int k = 0; k < kPerReg; ++k) {
    const int e = kPerReg * reg + k, source = 16 * (e % n) + e / n;
    if (kPerReg == 16) idx32[k] = source;
    if (kPerReg == 32) idx16[k] = short(source);
  }
  return kPerReg == 32 ? _mm512_load_si512(idx16) : _mm512_load_si512(idx32);
}

// Masked loads and stores of the first `count` elements of a register.
template <int kPerReg>
inline __m512i LoadFirst(const void* p, int count) {
  if constexpr (kPerReg == 32) return _mm512_maskz_loadu_epi16(__mmask32(~0ull >> (64 - count)), p);
  return _mm512_maskz_loadu_epi32(__mmask16((1u << count) - 1), p);
}
template <int kPerReg>
inline void StoreFirst(void* p, int count, __m512i v) {
  if constexpr (kPerReg == 32) {
    _mm512_mask_storeu_epi16(p, __mmask32(~0ull >> (64 - count)), v);
  } else {
    _mm512_mask_storeu_epi32(p, __mmask16((1u << count) - 1), v);
  }
}

// Pixels [0, 16·⌊cols/16⌋) of a row: In = uint16_t (half bits) or float.
template <int N, class In>
int SplitGroups(const In* in, int cols, float* const* out) {
  constexpr int kPerReg = 64 / int(sizeof(In)), kRegs = (16 * N + kPerReg - 1) / kPerReg;
  __m512i idx[N];
  for (int c = 0; c < N; ++c) idx[c] = SplitIndex<kPerReg>(N, c);
  int x = 0;
  for (; x + 16 <= cols; x += 16) {
    __m512i regs[kRegs];
    for (int r = 0; r < kRegs; ++r)
      regs[r] =
          LoadFirst<kPerReg>(in + N * x + kPerReg * r, std::min(kPerReg, 16 * N - kPerReg * r));
    for (int c = 0; c < N; ++c) {
      const __m512i v = Pick<kPerReg>(regs, kRegs, idx[c]);
      if constexpr (kPerReg == 32) {
        _mm512_storeu_ps(out[c] + x, _mm512_cvtph_ps(_mm512_castsi512_si256(v)));
      } else {
        _mm512_storeu_si512(out[c] + x, v);
      }
    }
  }
  return x;
}

// Pixels [0, 16·⌊cols/16⌋) of a row into Out = uint16_t (half bits, rounded to nearest even as
// convertTo) or float.
template <int N, class Out>
int MergeGroups(const float* const* in, int cols, Out* out) {
  constexpr int kPerReg = 64 / int(sizeof(Out)), kRegs = (16 * N + kPerReg - 1) / kPerReg;
  __m512i idx[kRegs];
  for (int r = 0; r < kRegs; ++r) idx[r] = MergeIndex<kPerReg>(N, r);
  constexpr int kPlanarRegs = kPerReg == 32 ? (N + 1) / 2 : N;
  int x = 0;
  for (; x + 16 <= cols; x += 16) {
    __m512i planar[kPlanarRegs];
    for (int q = 0; q < kPlanarRegs; ++q) {
      if constexpr (kPerReg == 32) {  // channels 2q and 2q + 1 as halves
        const auto half = [&](int c) {
          return c < N ? _mm512_cvtps_ph(_mm512_loadu_ps(in[c] + x),
                                         _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC)
                       : _mm256_setzero_si256();
        };
        planar[q] = _mm512_inserti64x4(_mm512_castsi256_si512(half(2 * q)), half(2 * q + 1), 1);
      } else {
        planar[q] = _mm512_castps_si512(_mm512_loadu_ps(in[q] + x));
      }
    }
    for (int r = 0; r < kRegs; ++r) {
      StoreFirst<kPerReg>(out + N * x + kPerReg * r, std::min(kPerReg, 16 * N - kPerReg * r),
                          Pick<kPerReg>(planar, kPlanarRegs, idx[r]));
    }
  }
  return x;
}
#else
constexpr bool kVectorised = false;
#endif

// Whether rows of N channels of T are split or merged sixteen pixels at a time.
template <int N, class T>
constexpr bool Grouped() {
  return kVectorised && (N == 3 || N == 7) &&
         (std::is_same_v<T, uint16_t> || std::is_same_v<T, float>);
}

// One row, with the channel count N known to the compiler (N = 0: `channels` at run time).
template <int N, class In>
void SplitRow(const In* in, int channels, int cols, float* const* out) {
  const int n = N > 0 ? N : channels;
  int x = 0;
#if defined(__AVX512F__) && defined(__AVX512BW__)
  if constexpr (Grouped<N, In>()) x = SplitGroups<N>(in, cols, out);
#endif
  for (; x < cols; ++x)
    for (int c = 0; c < n; ++c) out[c][x] = ToFloat(in[x * n + c]);
}
template <int N>
void MergeRow(const float* const* in, int channels, int cols, float* out) {
  const int n = N > 0 ? N : channels;
  int x = 0;
#if defined(__AVX512F__) && defined(__AVX512BW__)
  if constexpr (Grouped<N, float>()) x = MergeGroups<N>(in, cols, out);
#endif
  for (; x < cols; ++x)
    for (int c = 0; c < n; ++c) out[x * n + c] = in[c][x];
}
// Straight into half floats (the rest as MergeRow followed by StoreHalves).
template <int N>
void MergeRowToHalves(const float* const* in, int cols, uint16_t* out) {
  int x = 0;
#if defined(__AVX512F__) && defined(__AVX512BW__)
  x = MergeGroups<N>(in, cols, out);
#endif
  for (; x < cols; ++x)
    for (int c = 0; c < N; ++c) out[x * N + c] = cv::float16_t(in[c][x]).bits();
}

// The row function for a channel count: compiled for the counts the map uses, else generic.
template <class In>
auto SplitRowFor(int channels) {
  return core::WithCount<0, 1, 3, 7>(channels,
                                     [](auto n) { return &SplitRow<decltype(n)::value, In>; });
}
// MergeRowToHalves where rows of that channel count are grouped, else null.
auto MergeRowToHalvesFor(int channels) {
  using Row = void (*)(const float* const*, int, uint16_t*);
  if constexpr (Grouped<3, uint16_t>()) {
    if (channels == 3) return Row(&MergeRowToHalves<3>);
    if (channels == 7) return Row(&MergeRowToHalves<7>);
  }
  return Row(nullptr);
}
auto MergeRowFor(int channels) {
  return core::WithCount<0, 1, 3, 7>(channels,
                                     [](auto n) { return &MergeRow<decltype(n)::value>; });
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

// Float to half, rounded to nearest even (as cv::Mat::convertTo): sixteen (AVX-512) or eight
// (F16C) at a time; OpenCV's own conversion is a software one on x86.
void StoreHalves(const float* in, int n, uchar* out) {
  int i = 0;
#if defined(__AVX512F__)
  for (; i + core::lanes::kLanes <= n; i += core::lanes::kLanes) {
    const __m256i h =
        _mm512_cvtps_ph(_mm512_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + 2 * i), h);
  }
#elif defined(__F16C__)
  for (; i + 8 <= n; i += 8) {
    const __m128i h =
        _mm256_cvtps_ph(_mm256_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 2 * i), h);
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
  const auto merge_to_halves = out.depth() == CV_16F ? MergeRowToHalvesFor(channels) : nullptr;
  std::array<const float*, kMaxChannels> in;
  std::vector<float> row_floats(
      out.depth() == CV_16F && !merge_to_halves ? std::size_t(out.cols) * channels : 0);
  for (int y = 0; y < out.rows; ++y) {
    for (std::size_t c = 0; c < planes.size(); ++c) in[c] = planes[c].ptr<float>(y);
    if (merge_to_halves) {
      merge_to_halves(in.data(), out.cols, out.ptr<uint16_t>(y));
      continue;
    }
    float* row = out.depth() == CV_32F ? out.ptr<float>(y) : row_floats.data();
    merge_row(in.data(), channels, out.cols, row);
    if (out.depth() == CV_16F) StoreHalves(row, out.cols * channels, out.ptr(y));
  }
}

}  // namespace novelty::core
