// Sixteen lanes of floats / ints with GCC's vector extensions, for the per-pixel kernels of
// warping, blending and belief propagation: the compiler maps them to one AVX-512 register or
// two AVX2 ones; comparisons give lane masks (-1 / 0) and `mask ? a : b` selects per lane.
// (Eigen's boolean arrays and select are evaluated lane by lane, which kept those kernels
// scalar.) Arithmetic with a float broadcasts it: `F16{} + 1.0f` is sixteen ones.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>
#if defined(__AVX512F__) || defined(__F16C__)
#include <immintrin.h>
#endif

namespace novelty::core::lanes {

constexpr int kLanes = 16;
typedef float F16 __attribute__((vector_size(4 * kLanes)));
typedef int32_t I16 __attribute__((vector_size(4 * kLanes)));

/// GCC's __builtin_shuffle: lane k of the result is lane index[k] of `a` (of a, then b, for
/// two). Clang has only shuffles by constant indices, so there (the fuzzing build) a loop.
template <class V>
inline V Shuffle(V a, I16 index) {
#if defined(__clang__)
  V r;
  for (int k = 0; k < kLanes; ++k) r[k] = a[index[k] & (kLanes - 1)];
  return r;
#else
  return __builtin_shuffle(a, index);
#endif
}
template <class V>
inline V Shuffle(V a, V b, I16 index) {
#if defined(__clang__)
  V r;
  for (int k = 0; k < kLanes; ++k) {
    const int i = index[k] & (2 * kLanes - 1);
    r[k] = i < kLanes ? a[i] : b[i - kLanes];
  }
  return r;
#else
  return __builtin_shuffle(a, b, index);
#endif
}

inline F16 Load(const float* p) {
  F16 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void Store(float* p, F16 v) {
  std::memcpy(p, &v, sizeof v);
}
inline F16 Min(F16 a, F16 b) {
  return a < b ? a : b;
}
inline F16 Max(F16 a, F16 b) {
  return a > b ? a : b;
}
inline F16 AsFloat(I16 m) {
  return __builtin_convertvector(m, F16);
}
inline I16 AsInt(F16 x) {  // truncates
  return __builtin_convertvector(x, I16);
}
/// 0, 1, …, 15.
inline F16 Iota() {
  F16 v;
  for (int k = 0; k < kLanes; ++k) v[k] = float(k);
  return v;
}
/// floor and ceil through int conversion; x must lie within ±2^24 (callers clamp).
inline F16 Floor(F16 x) {
  const F16 t = AsFloat(AsInt(x));
  return t + AsFloat(t > x);  // true = -1
}
inline F16 Ceil(F16 x) {
  const F16 t = AsFloat(AsInt(x));
  return t - AsFloat(t < x);
}
/// The 32-bit word at byte offset offset[k] of `base` per lane (unaligned reads).
inline I16 GatherBytes(const char* base, I16 offset) {
#if defined(__AVX512F__)
  return (I16)_mm512_i32gather_epi32((__m512i)offset, base, 1);
#else
  I16 v;
  for (int k = 0; k < kLanes; ++k) {
    int32_t word;
    std::memcpy(&word, base + offset[k], 4);
    v[k] = word;
  }
  return v;
#endif
}
/// An IEEE half float (the low 16 bits of `bits`) as float, exactly (one instruction with F16C).
inline float HalfToFloat(uint32_t bits) {
#if defined(__F16C__)
  return _cvtsh_ss(static_cast<unsigned short>(bits & 0xFFFFu));
#else
  const uint32_t sign = (bits & 0x8000u) << 16, exponent = (bits >> 10) & 0x1Fu,
                 mantissa = bits & 0x3FFu;
  uint32_t out = sign | ((exponent + 112) << 23) | (mantissa << 13);  // normal numbers
  if (exponent == 31) out = sign | 0x7F800000u | (mantissa << 13);    // inf, NaN
  if (exponent == 0) {                                                // zero, subnormal
    const float f = float(mantissa) * (1.0f / 16777216.0f);           // mantissa · 2^−24
    std::memcpy(&out, &f, 4);
    out |= sign;
  }
  float f;
  std::memcpy(&f, &out, 4);
  return f;
#endif
}
/// Per lane, as the scalar form (one conversion instruction with AVX-512).
inline F16 HalfToFloat(I16 bits) {
#if defined(__AVX512F__)
  return (F16)_mm512_cvtph_ps(_mm512_cvtepi32_epi16((__m512i)bits));
#else
  F16 v;
  for (int k = 0; k < kLanes; ++k) v[k] = HalfToFloat(uint32_t(bits[k]));
  return v;
#endif
}
/// 1/x to within about one float ulp: AVX-512's 14-bit estimate and one Newton step, several
/// times cheaper than a division (exact division elsewhere).
inline float Reciprocal(float x) {
  return 1.0f / x;
}
inline F16 Reciprocal(F16 x) {
#if defined(__AVX512F__)
  const F16 r = (F16)_mm512_rcp14_ps((__m512)x);
  return r * (2.0f - x * r);
#else
  return 1.0f / x;
#endif
}
/// The lanes of a mask as bits (bit k: lane k), to visit only the set lanes.
inline unsigned Bits(I16 mask) {
#if defined(__AVX512F__)
  return _mm512_test_epi32_mask((__m512i)mask, (__m512i)mask);
#else
  unsigned bits = 0;
  for (int k = 0; k < kLanes; ++k) bits |= unsigned(mask[k] != 0) << k;
  return bits;
#endif
}
/// The smallest (kLargest false) or largest lane of v among those set in `mask` (at least one).
template <bool kLargest>
inline int ExtremeLane(I16 v, I16 mask) {
#if defined(__AVX512F__)
  const __mmask16 m = __mmask16(Bits(mask));
  if constexpr (kLargest) return _mm512_mask_reduce_max_epi32(m, (__m512i)v);
  return _mm512_mask_reduce_min_epi32(m, (__m512i)v);
#else
  int e = kLargest ? INT32_MIN : INT32_MAX;
  for (int k = 0; k < kLanes; ++k)
    if (mask[k] && (kLargest ? v[k] > e : v[k] < e)) e = v[k];
  return e;
#endif
}
inline int MinLane(I16 v, I16 mask) {
  return ExtremeLane<false>(v, mask);
}
inline int MaxLane(I16 v, I16 mask) {
  return ExtremeLane<true>(v, mask);
}
/// Whether any lane of a mask is set.
inline bool Any(I16 mask) {
  return Bits(mask) != 0;
}
/// Whether every lane of a mask is set.
inline bool All(I16 mask) {
  return Bits(mask) == (1u << kLanes) - 1;
}
/// How many lanes of a mask are set.
inline int Count(I16 mask) {
  return __builtin_popcount(Bits(mask));
}
/// p[k] = 255 where mask[k], 0 elsewhere (sixteen bytes: an 8-bit validity mask).
inline void StoreMaskBytes(uint8_t* p, I16 mask) {
#if defined(__AVX512F__)
  _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm512_cvtepi32_epi8((__m512i)mask));
#else
  for (int k = 0; k < kLanes; ++k) p[k] = mask[k] ? 255 : 0;
#endif
}
/// Sixteen signed bytes, one per lane.
inline I16 LoadBytes(const int8_t* p) {
#if defined(__AVX512F__)
  return (I16)_mm512_cvtepi8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
#else
  I16 v;
  for (int k = 0; k < kLanes; ++k) v[k] = p[k];
  return v;
#endif
}
/// p[k] where mask[k] (-1), 0 elsewhere; masked-out lanes are not read (may lie past the end).
inline F16 LoadMasked(const float* p, I16 mask) {
#if defined(__AVX512F__)
  return (F16)_mm512_maskz_loadu_ps(__mmask16(Bits(mask)), p);
#else
  F16 v{};
  for (int k = 0; k < kLanes; ++k)
    if (mask[k]) v[k] = p[k];
  return v;
#endif
}
/// p[k] = v[k] where mask[k]; other lanes are neither read nor written.
inline void StoreMasked(float* p, F16 v, I16 mask) {
#if defined(__AVX512F__)
  _mm512_mask_storeu_ps(p, __mmask16(Bits(mask)), (__m512)v);
#else
  for (int k = 0; k < kLanes; ++k)
    if (mask[k]) p[k] = v[k];
#endif
}
/// Pairs (a[k], b[k]) interleaved into p[2k], p[2k+1] where mask[k] (e.g. CV_32FC2 pixels).
inline void StoreMaskedPairs(float* p, F16 a, F16 b, I16 mask) {
  const I16 lo{0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23};
  const I16 spread_lo{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7};
  StoreMasked(p, Shuffle(a, b, lo), Shuffle(mask, spread_lo));
  StoreMasked(p + kLanes, Shuffle(a, b, lo + 8), Shuffle(mask, spread_lo + 8));
}
/// The inverse of StoreMaskedPairs: a[k] = p[2k], b[k] = p[2k+1] where mask[k], 0 elsewhere
/// (masked-out pairs are not read).
inline void LoadMaskedPairs(const float* p, I16 mask, F16& a, F16& b) {
  const I16 spread_lo{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7};
  const F16 lo = LoadMasked(p, Shuffle(mask, spread_lo));
  const F16 hi = LoadMasked(p + kLanes, Shuffle(mask, spread_lo + 8));
  const I16 even{0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30};
  a = Shuffle(lo, hi, even);
  b = Shuffle(lo, hi, even + 1);
}
/// p[index[k]] = v[k] per lane (one scatter instruction with AVX-512).
inline void Scatter(float* p, I16 index, F16 v) {
#if defined(__AVX512F__)
  _mm512_i32scatter_ps(p, (__m512i)index, (__m512)v, 4);
#else
  for (int k = 0; k < kLanes; ++k) p[index[k]] = v[k];
#endif
}

}  // namespace novelty::core::lanes
