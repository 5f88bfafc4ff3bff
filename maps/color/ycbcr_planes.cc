#include "maps/color/ycbcr_planes.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/lanes.h"
#include "maps/color/ycbcr.h"

namespace novelty::color {

namespace {

namespace L = core::lanes;

// The transform's coefficients in float, as cv::transform applies them.
struct Affine {
  float m[3][4];
  explicit Affine(const cv::Matx34d& a) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) m[r][c] = float(a(r, c));
  }
  // Row r applied to (a, b, c); T is float or L::F16 (the same expression, so lanes and tail
  // pixels round alike).
  template <class T>
  T Row(int r, T a, T b, T c) const {
    return a * m[r][0] + b * m[r][1] + c * m[r][2] + m[r][3];
  }
};

// To 0…255 as convertTo rounds (to nearest even) and saturates; NaN fails both comparisons of the
// clamp and becomes 0.
inline L::I16 ToByteValues(L::F16 v) {
  const L::F16 clamped = L::Min(L::Max(v, L::F16{} + 0.0f), L::F16{} + 255.0f);
  constexpr float kRound = 12582912.0f;  // 1.5·2^23: adding it leaves no fraction bits
  return L::AsInt((clamped + kRound) - kRound);
}
inline uchar ToByte(float v) {
  return uchar(ToByteValues(L::F16{} + v)[0]);
}

#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
constexpr __mmask64 kRgbBytes = (1ull << 48) - 1;  // sixteen pixels

// Byte index vectors: `planar` takes byte 3k + c of the pixels to 16c + k, `interleaved` back.
inline __m512i ByteIndex(bool planar) {
  alignas(64) uint8_t idx[64] = {};
  for (int k = 0; k < 16; ++k)
    for (int c = 0; c < 3; ++c) {
      if (planar) idx[16 * c + k] = uint8_t(3 * k + c);
      if (!planar) idx[3 * k + c] = uint8_t(16 * c + k);
    }
  return _mm512_load_si512(idx);
}
inline L::F16 Widen(__m512i planar, int c) {
  const __m128i bytes = c == 0   ? _mm512_castsi512_si128(planar)
                        : c == 1 ? _mm512_extracti32x4_epi32(planar, 1)
                                 : _mm512_extracti32x4_epi32(planar, 2);
  return L::BitCast<L::F16>(_mm512_cvtepi32_ps(_mm512_cvtepu8_epi32(bytes)));
}
#endif

// One image's conversion: the transform and, with VBMI, the byte permute of sixteen pixels
// (`to_planar`: bytes to planes, else back), made once per image rather than per row.
struct Conversion {
  Affine a;
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
  __m512i permute;
#endif
  Conversion(const cv::Matx34d& m, bool to_planar) : a(m) {
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
    permute = ByteIndex(to_planar);
#else
    (void)to_planar;
#endif
  }
};

void RgbRow(const uchar* in, int cols, const Conversion& k, float* y, float* cb, float* cr) {
  const Affine& a = k.a;
  int x = 0;
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
  for (; x + L::kLanes <= cols; x += L::kLanes) {
    const __m512i planar =
        _mm512_permutexvar_epi8(k.permute, _mm512_maskz_loadu_epi8(kRgbBytes, in + 3 * x));
    const L::F16 r = Widen(planar, 0), g = Widen(planar, 1), b = Widen(planar, 2);
    L::Store(y + x, a.Row(0, r, g, b));
    L::Store(cb + x, a.Row(1, r, g, b));
    L::Store(cr + x, a.Row(2, r, g, b));
  }
#endif
  for (; x < cols; ++x) {
    const float r = in[3 * x], g = in[3 * x + 1], b = in[3 * x + 2];
    y[x] = a.Row(0, r, g, b);
    cb[x] = a.Row(1, r, g, b);
    cr[x] = a.Row(2, r, g, b);
  }
}

void PlanesRow(const float* y, const float* cb, const float* cr, int cols, const Conversion& k,
               uchar* out) {
  const Affine& a = k.a;
  int x = 0;
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
  for (; x + L::kLanes <= cols; x += L::kLanes) {
    const L::F16 Y = L::Load(y + x), Cb = L::Load(cb + x), Cr = L::Load(cr + x);
    const auto bytes = [&](int c) {
      return _mm512_cvtepi32_epi8((__m512i)ToByteValues(a.Row(c, Y, Cb, Cr)).p[0]);
    };
    __m512i planar = _mm512_castsi128_si512(bytes(0));
    planar = _mm512_inserti32x4(planar, bytes(1), 1);
    planar = _mm512_inserti32x4(planar, bytes(2), 2);
    _mm512_mask_storeu_epi8(out + 3 * x, kRgbBytes, _mm512_permutexvar_epi8(k.permute, planar));
  }
#else
  // Sixteen pixels' arithmetic in lanes, interleaved a byte at a time (ToByte per value would
  // run the sixteen-lane rounding once per byte).
  for (; x + L::kLanes <= cols; x += L::kLanes) {
    const L::F16 Y = L::Load(y + x), Cb = L::Load(cb + x), Cr = L::Load(cr + x);
    int32_t bytes[3][L::kLanes];
    for (int c = 0; c < 3; ++c) {
      const L::I16 v = ToByteValues(a.Row(c, Y, Cb, Cr));
      std::memcpy(bytes[c], &v, sizeof v);
    }
    for (int i = 0; i < L::kLanes; ++i)
      for (int c = 0; c < 3; ++c) out[3 * (x + i) + c] = uchar(bytes[c][i]);
  }
#endif
  for (; x < cols; ++x)
    for (int c = 0; c < 3; ++c) out[3 * x + c] = ToByte(a.Row(c, y[x], cb[x], cr[x]));
}

}  // namespace

void RgbToYCbCrPlanes(const cv::Mat& rgb, std::vector<cv::Mat>& planes) {
  if (rgb.type() != CV_8UC3) {
    throw std::invalid_argument("RgbToYCbCrPlanes: expected a CV_8UC3 RGB image, got OpenCV type " +
                                std::to_string(rgb.type()));
  }
  planes.resize(3);
  for (cv::Mat& p : planes) p.create(rgb.size(), CV_32FC1);
  const Conversion k(RgbToYCbCrMatrix(), true);
  for (int r = 0; r < rgb.rows; ++r) {
    RgbRow(rgb.ptr<uchar>(r), rgb.cols, k, planes[0].ptr<float>(r), planes[1].ptr<float>(r),
           planes[2].ptr<float>(r));
  }
}

void YCbCrPlanesToRgb(const cv::Mat& y, const cv::Mat& cb, const cv::Mat& cr, cv::Mat& rgb) {
  bool ok = rgb.type() == CV_8UC3;
  for (const cv::Mat* p : {&y, &cb, &cr})
    ok = ok && p->type() == CV_32FC1 && p->size() == rgb.size();
  if (!ok) {
    throw std::invalid_argument(
        "YCbCrPlanesToRgb: need three CV_32FC1 planes of the CV_8UC3 output's size, got OpenCV "
        "types " +
        std::to_string(y.type()) + ", " + std::to_string(cb.type()) + ", " +
        std::to_string(cr.type()) + " for " + std::to_string(rgb.type()));
  }
  const Conversion k(YCbCrToRgbMatrix(), false);
  for (int r = 0; r < rgb.rows; ++r) {
    PlanesRow(y.ptr<float>(r), cb.ptr<float>(r), cr.ptr<float>(r), rgb.cols, k, rgb.ptr<uchar>(r));
  }
}

}  // namespace novelty::color
