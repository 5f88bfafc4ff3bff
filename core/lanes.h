// Sixteen lanes of floats (F16) and ints (I16) for the per-pixel kernels of warping, blending
// and belief propagation, held as the CPU's own registers: one AVX-512 register, two AVX2 ones,
// or four NEON / SSE ones. Arithmetic, comparisons and bit operations are operators, as on
// GCC's vector extensions; comparisons give lane masks (-1 / 0); Select(mask, a, b) picks per
// lane. Arithmetic with a float broadcasts it: `F16{} + 1.0f` is sixteen ones.
//
// Why a struct of registers and not one 64-byte vector extension: GCC 12 lowers a comparison
// or select of a vector wider than the CPU's registers lane by lane, through memory — which
// made AVX2 seven times slower than AVX-512 (DESIGN.md, performance budgets). On registers of
// the CPU's own width every operator is one instruction per part. What the compiler cannot
// lower by itself — gathers, masked loads and stores, mask bits, lane reductions, shuffles by
// index, half floats, byte widening — is written per target below (AVX-512, AVX2, NEON) with a
// portable form for any other CPU. Only Scatter stays a loop below AVX-512: neither AVX2 nor
// NEON has a scatter instruction. tests/core/lanes_test.cc checks every function against its
// lane-by-lane definition on each target (scripts/portable.sh, scripts/cross_aarch64.sh).
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#if defined(__AVX512F__) || defined(__AVX2__) || defined(__F16C__)
#include <immintrin.h>
#endif
#if defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>
#endif

// Always inlined: sixteen lanes passed by value to a call go through the stack.
#define NOVELTY_LANES_INLINE inline __attribute__((always_inline))

namespace novelty::core::lanes {

constexpr int kLanes = 16;

#if defined(__AVX512F__)
#define NOVELTY_LANES_AVX512 1
constexpr int kPartLanes = 16;
#elif defined(__AVX2__)
#define NOVELTY_LANES_AVX2 1
constexpr int kPartLanes = 8;
#elif defined(__ARM_NEON) && defined(__aarch64__)
#define NOVELTY_LANES_NEON 1
constexpr int kPartLanes = 4;
#else
constexpr int kPartLanes = 4;  // 128-bit vectors: SSE2 (every x86-64), and most other CPUs
#endif
/// Registers per sixteen lanes, and their types (GCC vector extensions of the native width).
constexpr int kParts = kLanes / kPartLanes;
typedef float FPart __attribute__((vector_size(4 * kPartLanes)));
typedef int32_t IPart __attribute__((vector_size(4 * kPartLanes)));

/// The bits of `from` as a `To` of the same size (registers stay registers).
template <class To, class From>
NOVELTY_LANES_INLINE To BitCast(const From& from) {
  static_assert(sizeof(To) == sizeof(From), "BitCast needs types of one size");
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

namespace detail {
// f(0), f(1), …, f(kParts − 1), unrolled.
template <class F, int... Q>
NOVELTY_LANES_INLINE void EachPart(F&& f, std::integer_sequence<int, Q...>) {
  (f(Q), ...);
}
template <class F>
NOVELTY_LANES_INLINE void EachPart(F&& f) {
  EachPart(f, std::make_integer_sequence<int, kParts>{});
}
}  // namespace detail

/// Sixteen lanes of `Part`'s element type. Lane k lives in part k / kPartLanes.
template <class Part_, class Element_>
struct Lanes16 {
  using Part = Part_;
  using Element = Element_;
  Part p[kParts];

  Lanes16() = default;  // `Lanes16{}` is zero; `Lanes16 v;` is not initialised
  /// The sixteen lanes given one by one: `I16{0, 2, 4, …}`.
  template <class... T, std::enable_if_t<sizeof...(T) == kLanes, int> = 0>
  Lanes16(T... values) {  // NOLINT: brace initialisation, as of a vector extension
    const Element v[kLanes] = {Element(values)...};
    std::memcpy(p, v, sizeof p);
  }
  /// Lane k, read or written in memory, as a vector extension's v[k] is (GCC's and clang's
  /// vector types alias their element type).
  Element operator[](int k) const { return reinterpret_cast<const Element*>(p)[k]; }
  Element& operator[](int k) { return reinterpret_cast<Element*>(p)[k]; }
};
using F16 = Lanes16<FPart, float>;
using I16 = Lanes16<IPart, int32_t>;

namespace detail {
template <class R, class A, class B, class Op>
NOVELTY_LANES_INLINE R PartWise(const A& a, const B& b, Op op) {
  R r;
  EachPart([&](int q) { r.p[q] = op(a.p[q], b.p[q]); });
  return r;
}
// A scalar broadcast to every lane, so that `v + 1.0f` and `1.0f + v` work as on vectors.
template <class V, class S>
NOVELTY_LANES_INLINE V Broadcast(S s) {
  V v;
  EachPart([&](int q) { v.p[q] = typename V::Part{} + s; });
  return v;
}
}  // namespace detail

// Operators, part by part: the arithmetic of F16 and I16, comparisons (→ I16 masks), and the
// bit operations of I16. A scalar operand is broadcast (float for F16, int32_t for I16).
#define NOVELTY_LANES_BINARY(V, S, R, op)                                    \
  NOVELTY_LANES_INLINE R operator op(const V& a, const V& b) {               \
    return detail::PartWise<R>(a, b, [](auto x, auto y) { return x op y; }); \
  }                                                                          \
  NOVELTY_LANES_INLINE R operator op(const V& a, S b) {                      \
    return a op detail::Broadcast<V>(b);                                     \
  }                                                                          \
  NOVELTY_LANES_INLINE R operator op(S a, const V& b) {                      \
    return detail::Broadcast<V>(a) op b;                                     \
  }
#define NOVELTY_LANES_ASSIGN(V, S, op)                       \
  NOVELTY_LANES_INLINE V& operator op##=(V& a, const V& b) { \
    return a = a op b;                                       \
  }                                                          \
  NOVELTY_LANES_INLINE V& operator op##=(V& a, S b) {        \
    return a = a op b;                                       \
  }
NOVELTY_LANES_BINARY(F16, float, F16, +)
NOVELTY_LANES_BINARY(F16, float, F16, -)
NOVELTY_LANES_BINARY(F16, float, F16, *)
NOVELTY_LANES_BINARY(F16, float, F16, /)
NOVELTY_LANES_ASSIGN(F16, float, +)
NOVELTY_LANES_ASSIGN(F16, float, -)
NOVELTY_LANES_ASSIGN(F16, float, *)
NOVELTY_LANES_ASSIGN(F16, float, /)
NOVELTY_LANES_BINARY(F16, float, I16, <)
NOVELTY_LANES_BINARY(F16, float, I16, <=)
NOVELTY_LANES_BINARY(F16, float, I16, >)
NOVELTY_LANES_BINARY(F16, float, I16, >=)
NOVELTY_LANES_BINARY(F16, float, I16, ==)
NOVELTY_LANES_BINARY(F16, float, I16, !=)
NOVELTY_LANES_BINARY(I16, int32_t, I16, +)
NOVELTY_LANES_BINARY(I16, int32_t, I16, -)
NOVELTY_LANES_BINARY(I16, int32_t, I16, *)
NOVELTY_LANES_BINARY(I16, int32_t, I16, &)
NOVELTY_LANES_BINARY(I16, int32_t, I16, |)
NOVELTY_LANES_BINARY(I16, int32_t, I16, ^)
NOVELTY_LANES_BINARY(I16, int32_t, I16, <<)
NOVELTY_LANES_BINARY(I16, int32_t, I16, >>)
NOVELTY_LANES_BINARY(I16, int32_t, I16, <)
NOVELTY_LANES_BINARY(I16, int32_t, I16, <=)
NOVELTY_LANES_BINARY(I16, int32_t, I16, >)
NOVELTY_LANES_BINARY(I16, int32_t, I16, >=)
NOVELTY_LANES_BINARY(I16, int32_t, I16, ==)
NOVELTY_LANES_BINARY(I16, int32_t, I16, !=)
NOVELTY_LANES_ASSIGN(I16, int32_t, +)
NOVELTY_LANES_ASSIGN(I16, int32_t, -)
NOVELTY_LANES_ASSIGN(I16, int32_t, *)
NOVELTY_LANES_ASSIGN(I16, int32_t, &)
NOVELTY_LANES_ASSIGN(I16, int32_t, |)
NOVELTY_LANES_ASSIGN(I16, int32_t, ^)
#undef NOVELTY_LANES_BINARY
#undef NOVELTY_LANES_ASSIGN
NOVELTY_LANES_INLINE F16 operator-(const F16& a) {
  return F16{} - a;
}
NOVELTY_LANES_INLINE I16 operator-(const I16& a) {
  return I16{} - a;
}
NOVELTY_LANES_INLINE I16 operator~(const I16& a) {
  return a ^ -1;
}

/// Per lane, a where mask (−1) and b where not (0).
NOVELTY_LANES_INLINE F16 Select(const I16& mask, const F16& a, const F16& b) {
  F16 r;
  detail::EachPart([&](int q) { r.p[q] = mask.p[q] ? a.p[q] : b.p[q]; });
  return r;
}
NOVELTY_LANES_INLINE I16 Select(const I16& mask, const I16& a, const I16& b) {
  I16 r;
  detail::EachPart([&](int q) { r.p[q] = mask.p[q] ? a.p[q] : b.p[q]; });
  return r;
}
/// The one-lane forms, for kernels written once for a pixel (float, bool) and sixteen.
NOVELTY_LANES_INLINE float Select(bool mask, float a, float b) {
  return mask ? a : b;
}
NOVELTY_LANES_INLINE int32_t Select(bool mask, int32_t a, int32_t b) {
  return mask ? a : b;
}

/// Lanes 0–7 and 8–15 as AVX2 registers, and back.
#if defined(NOVELTY_LANES_AVX2)
NOVELTY_LANES_INLINE __m256i Half(const I16& v, int h) {
  return (__m256i)v.p[h];
}
NOVELTY_LANES_INLINE __m256 Half(const F16& v, int h) {
  return (__m256)v.p[h];
}
NOVELTY_LANES_INLINE I16 Join(__m256i lo, __m256i hi) {
  I16 v;
  v.p[0] = (IPart)lo;
  v.p[1] = (IPart)hi;
  return v;
}
NOVELTY_LANES_INLINE F16 Join(__m256 lo, __m256 hi) {
  F16 v;
  v.p[0] = (FPart)lo;
  v.p[1] = (FPart)hi;
  return v;
}
#endif

// Part by part: one register-wide copy each (a 64-byte copy goes through the stack).
NOVELTY_LANES_INLINE F16 Load(const float* p) {
  F16 v;
  detail::EachPart([&](int q) { std::memcpy(&v.p[q], p + q * kPartLanes, sizeof v.p[q]); });
  return v;
}
NOVELTY_LANES_INLINE void Store(float* p, F16 v) {
  detail::EachPart([&](int q) { std::memcpy(p + q * kPartLanes, &v.p[q], sizeof v.p[q]); });
}
NOVELTY_LANES_INLINE F16 Min(F16 a, F16 b) {
  return Select(a < b, a, b);
}
NOVELTY_LANES_INLINE F16 Max(F16 a, F16 b) {
  return Select(a > b, a, b);
}
NOVELTY_LANES_INLINE F16 AsFloat(I16 m) {
  F16 r;
  detail::EachPart([&](int q) { r.p[q] = __builtin_convertvector(m.p[q], FPart); });
  return r;
}
NOVELTY_LANES_INLINE I16 AsInt(F16 x) {  // truncates
  I16 r;
  detail::EachPart([&](int q) { r.p[q] = __builtin_convertvector(x.p[q], IPart); });
  return r;
}
/// 0, 1, …, 15.
NOVELTY_LANES_INLINE F16 Iota() {
  return F16{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
}
/// floor and ceil through int conversion; x must lie within ±2^24 (callers clamp).
NOVELTY_LANES_INLINE F16 Floor(F16 x) {
  const F16 t = AsFloat(AsInt(x));
  return t + AsFloat(t > x);  // true = -1
}
NOVELTY_LANES_INLINE F16 Ceil(F16 x) {
  const F16 t = AsFloat(AsInt(x));
  return t - AsFloat(t < x);
}

/// Shuffles by lane index: lane k of the result is lane index[k] of `a` (of a, then b, for
/// two; indices modulo 16 or 32).
template <class V>
NOVELTY_LANES_INLINE V Shuffle(V a, I16 index) {
#if defined(NOVELTY_LANES_AVX512)
  const F16 f = BitCast<F16>(a);
  return BitCast<V>(_mm512_permutexvar_ps((__m512i)index.p[0], (__m512)f.p[0]));
#elif defined(NOVELTY_LANES_AVX2)
  // Each half of the result from both halves of a (the index's low three bits), picked by bit 3.
  const F16 f = BitCast<F16>(a);
  F16 r;
  for (int h = 0; h < 2; ++h) {
    const __m256i i = Half(index, h);
    const __m256 from_lo = _mm256_permutevar8x32_ps(Half(f, 0), i);
    const __m256 from_hi = _mm256_permutevar8x32_ps(Half(f, 1), i);
    const __m256 upper = _mm256_castsi256_ps(_mm256_slli_epi32(i, 28));  // bit 3 → sign
    r.p[h] = (FPart)_mm256_blendv_ps(from_lo, from_hi, upper);
  }
  return BitCast<V>(r);
#elif defined(NOVELTY_LANES_NEON)
  // One table lookup of the 64 bytes per quarter: byte j of lane k is byte 4·index[k] + j.
  uint8x16x4_t table;
  std::memcpy(&table, &a, sizeof a);
  const I16 bytes = ((index & (kLanes - 1)) << 2) * 0x01010101 + 0x03020100;
  V r;
  for (int q = 0; q < kParts; ++q) {
    const uint8x16_t picked = vqtbl4q_u8(table, vreinterpretq_u8_s32(bytes.p[q]));
    std::memcpy(&r.p[q], &picked, 16);
  }
  return r;
#else
  V r;
  for (int k = 0; k < kLanes; ++k) r[k] = a[index[k] & (kLanes - 1)];
  return r;
#endif
}
template <class V>
NOVELTY_LANES_INLINE V Shuffle(V a, V b, I16 index) {
#if defined(NOVELTY_LANES_AVX512)
  const F16 fa = BitCast<F16>(a), fb = BitCast<F16>(b);
  return BitCast<V>(_mm512_permutex2var_ps((__m512)fa.p[0], (__m512i)index.p[0], (__m512)fb.p[0]));
#else
  const I16 i = index & (2 * kLanes - 1);
  return Select(i < kLanes, Shuffle(a, i), Shuffle(b, i));  // Shuffle takes indices mod 16
#endif
}

/// The 32-bit word at byte offset offset[k] of `base` per lane (unaligned reads).
NOVELTY_LANES_INLINE I16 GatherBytes(const char* base, I16 offset) {
#if defined(NOVELTY_LANES_AVX512)
  return BitCast<I16>(_mm512_i32gather_epi32((__m512i)offset.p[0], base, 1));
#elif defined(NOVELTY_LANES_AVX2)
  const int* b = reinterpret_cast<const int*>(base);
  return Join(_mm256_i32gather_epi32(b, Half(offset, 0), 1),
              _mm256_i32gather_epi32(b, Half(offset, 1), 1));
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
NOVELTY_LANES_INLINE float HalfToFloat(uint32_t bits) {
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
/// Per lane, as the scalar form (one conversion instruction with AVX-512, two with F16C).
NOVELTY_LANES_INLINE F16 HalfToFloat(I16 bits) {
#if defined(NOVELTY_LANES_AVX512)
  return BitCast<F16>(_mm512_cvtph_ps(_mm512_cvtepi32_epi16((__m512i)bits.p[0])));
#elif defined(NOVELTY_LANES_AVX2)
  // The low 16 bits of eight lanes packed (unsigned saturation keeps 0…65535), then converted.
  const I16 low = bits & 0xFFFF;
  const auto eight = [](__m256i v) {
    return _mm256_cvtph_ps(
        _mm_packus_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1)));
  };
  return Join(eight(Half(low, 0)), eight(Half(low, 1)));
#elif defined(NOVELTY_LANES_NEON)
  F16 v;
  for (int q = 0; q < kParts; ++q) {
    const uint16x4_t h = vmovn_u32(vreinterpretq_u32_s32(bits.p[q]));
    const float32x4_t f = vcvt_f32_f16(vreinterpret_f16_u16(h));
    std::memcpy(&v.p[q], &f, 16);
  }
  return v;
#else
  F16 v;
  for (int k = 0; k < kLanes; ++k) v[k] = HalfToFloat(uint32_t(bits[k]));
  return v;
#endif
}
/// 1/x to within about one float ulp: AVX-512's 14-bit estimate and one Newton step, several
/// times cheaper than a division (exact division elsewhere).
NOVELTY_LANES_INLINE float Reciprocal(float x) {
  return 1.0f / x;
}
NOVELTY_LANES_INLINE F16 Reciprocal(F16 x) {
#if defined(NOVELTY_LANES_AVX512)
  const F16 r = BitCast<F16>(_mm512_rcp14_ps((__m512)x.p[0]));
  return r * (2.0f - x * r);
#else
  return 1.0f / x;
#endif
}
/// The lanes of a mask as bits (bit k: lane k), to visit only the set lanes.
NOVELTY_LANES_INLINE unsigned Bits(I16 mask) {
#if defined(NOVELTY_LANES_AVX512)
  return _mm512_test_epi32_mask((__m512i)mask.p[0], (__m512i)mask.p[0]);
#elif defined(NOVELTY_LANES_AVX2)
  // A lane mask is −1 or 0, so its sign bit is the lane's bit.
  return unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(Half(mask, 0)))) |
         unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(Half(mask, 1)))) << 8;
#elif defined(NOVELTY_LANES_NEON)
  const uint32x4_t weight = {1, 2, 4, 8};
  unsigned bits = 0;
  for (int q = 0; q < kParts; ++q)
    bits |= vaddvq_u32(vandq_u32(vreinterpretq_u32_s32(mask.p[q]), weight)) << (4 * q);
  return bits;
#else
  unsigned bits = 0;
  for (int k = 0; k < kLanes; ++k) bits |= unsigned(mask[k] != 0) << k;
  return bits;
#endif
}
/// The smallest (kLargest false) or largest lane of v among those set in `mask` (at least one).
template <bool kLargest>
NOVELTY_LANES_INLINE int ExtremeLane(I16 v, I16 mask) {
#if defined(NOVELTY_LANES_AVX512)
  const __mmask16 m = __mmask16(Bits(mask));
  if constexpr (kLargest) return _mm512_mask_reduce_max_epi32(m, (__m512i)v.p[0]);
  return _mm512_mask_reduce_min_epi32(m, (__m512i)v.p[0]);
#else
  // Lanes outside the mask take the identity of the reduction; then a tree of parts, then
  // within the last part.
  const I16 x = Select(mask, v, I16{} + (kLargest ? INT32_MIN : INT32_MAX));
  const auto fold = [](IPart a, IPart b) { return kLargest ? (a > b ? a : b) : (a < b ? a : b); };
  IPart e = x.p[0];
  for (int q = 1; q < kParts; ++q) e = fold(e, x.p[q]);
#if defined(NOVELTY_LANES_NEON)
  return kLargest ? vmaxvq_s32(e) : vminvq_s32(e);
#else
  int r = e[0];
  for (int k = 1; k < kPartLanes; ++k) r = kLargest ? (e[k] > r ? e[k] : r) : (e[k] < r ? e[k] : r);
  return r;
#endif
#endif
}
NOVELTY_LANES_INLINE int MinLane(I16 v, I16 mask) {
  return ExtremeLane<false>(v, mask);
}
NOVELTY_LANES_INLINE int MaxLane(I16 v, I16 mask) {
  return ExtremeLane<true>(v, mask);
}
/// Whether any lane of a mask is set.
NOVELTY_LANES_INLINE bool Any(I16 mask) {
  return Bits(mask) != 0;
}
/// Whether every lane of a mask is set.
NOVELTY_LANES_INLINE bool All(I16 mask) {
  return Bits(mask) == (1u << kLanes) - 1;
}
/// How many lanes of a mask are set.
NOVELTY_LANES_INLINE int Count(I16 mask) {
  return __builtin_popcount(Bits(mask));
}
/// p[k] = 255 where mask[k], 0 elsewhere (sixteen bytes: an 8-bit validity mask).
NOVELTY_LANES_INLINE void StoreMaskBytes(uint8_t* p, I16 mask) {
#if defined(NOVELTY_LANES_AVX512)
  _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm512_cvtepi32_epi8((__m512i)mask.p[0]));
#elif defined(NOVELTY_LANES_AVX2)
  // −1 / 0 narrowed with signed saturation stays −1 / 0: 32 → 16 → 8 bits.
  const auto words = [](__m256i v) {
    return _mm_packs_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  };
  _mm_storeu_si128(reinterpret_cast<__m128i*>(p),
                   _mm_packs_epi16(words(Half(mask, 0)), words(Half(mask, 1))));
#elif defined(NOVELTY_LANES_NEON)
  const auto words = [&](int q) { return vmovn_u32(vreinterpretq_u32_s32(mask.p[q])); };
  const uint16x8_t lo = vcombine_u16(words(0), words(1)), hi = vcombine_u16(words(2), words(3));
  vst1q_u8(p, vcombine_u8(vmovn_u16(lo), vmovn_u16(hi)));
#else
  for (int k = 0; k < kLanes; ++k) p[k] = mask[k] ? 255 : 0;
#endif
}
/// Sixteen signed bytes, one per lane.
NOVELTY_LANES_INLINE I16 LoadBytes(const int8_t* p) {
#if defined(NOVELTY_LANES_AVX512)
  return BitCast<I16>(_mm512_cvtepi8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))));
#elif defined(NOVELTY_LANES_AVX2)
  const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  return Join(_mm256_cvtepi8_epi32(bytes), _mm256_cvtepi8_epi32(_mm_unpackhi_epi64(bytes, bytes)));
#elif defined(NOVELTY_LANES_NEON)
  const int8x16_t bytes = vld1q_s8(p);
  const int16x8_t lo = vmovl_s8(vget_low_s8(bytes)), hi = vmovl_s8(vget_high_s8(bytes));
  const int32x4_t q[4] = {vmovl_s16(vget_low_s16(lo)), vmovl_s16(vget_high_s16(lo)),
                          vmovl_s16(vget_low_s16(hi)), vmovl_s16(vget_high_s16(hi))};
  return BitCast<I16>(q);
#else
  I16 v;
  for (int k = 0; k < kLanes; ++k) v[k] = p[k];
  return v;
#endif
}
/// p[k] where mask[k] (-1), 0 elsewhere; masked-out lanes are not read (may lie past the end).
NOVELTY_LANES_INLINE F16 LoadMasked(const float* p, I16 mask) {
#if defined(NOVELTY_LANES_AVX512)
  return BitCast<F16>(_mm512_maskz_loadu_ps(__mmask16(Bits(mask)), p));
#elif defined(NOVELTY_LANES_AVX2)
  // vmaskmov reads nothing where the mask's sign bit is clear (no fault past the end).
  return Join(_mm256_maskload_ps(p, Half(mask, 0)), _mm256_maskload_ps(p + 8, Half(mask, 1)));
#else
  // No masked load (NEON, SSE): whole vectors where every lane is set, the usual case.
  if (All(mask)) return Load(p);
  F16 v{};
  for (int k = 0; k < kLanes; ++k)
    if (mask[k]) v[k] = p[k];
  return v;
#endif
}
/// p[k] = v[k] where mask[k]; other lanes are neither read nor written.
NOVELTY_LANES_INLINE void StoreMasked(float* p, F16 v, I16 mask) {
#if defined(NOVELTY_LANES_AVX512)
  _mm512_mask_storeu_ps(p, __mmask16(Bits(mask)), (__m512)v.p[0]);
#elif defined(NOVELTY_LANES_AVX2)
  _mm256_maskstore_ps(p, Half(mask, 0), Half(v, 0));
  _mm256_maskstore_ps(p + 8, Half(mask, 1), Half(v, 1));
#else
  if (All(mask)) return Store(p, v);
  for (int k = 0; k < kLanes; ++k)
    if (mask[k]) p[k] = v[k];
#endif
}
/// Pairs (a[k], b[k]) interleaved into p[2k], p[2k+1] where mask[k] (e.g. CV_32FC2 pixels).
NOVELTY_LANES_INLINE void StoreMaskedPairs(float* p, F16 a, F16 b, I16 mask) {
  const I16 lo{0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23};
  const I16 spread_lo{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7};
  StoreMasked(p, Shuffle(a, b, lo), Shuffle(mask, spread_lo));
  StoreMasked(p + kLanes, Shuffle(a, b, lo + 8), Shuffle(mask, spread_lo + 8));
}
/// The inverse of StoreMaskedPairs: a[k] = p[2k], b[k] = p[2k+1] where mask[k], 0 elsewhere
/// (masked-out pairs are not read).
NOVELTY_LANES_INLINE void LoadMaskedPairs(const float* p, I16 mask, F16& a, F16& b) {
  const I16 spread_lo{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7};
  const F16 lo = LoadMasked(p, Shuffle(mask, spread_lo));
  const F16 hi = LoadMasked(p + kLanes, Shuffle(mask, spread_lo + 8));
  const I16 even{0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30};
  a = Shuffle(lo, hi, even);
  b = Shuffle(lo, hi, even + 1);
}
/// p[index[k]] = v[k] per lane (one scatter instruction with AVX-512).
NOVELTY_LANES_INLINE void Scatter(float* p, I16 index, F16 v) {
#if defined(NOVELTY_LANES_AVX512)
  _mm512_i32scatter_ps(p, (__m512i)index.p[0], (__m512)v.p[0], 4);
#else
  for (int k = 0; k < kLanes; ++k) p[index[k]] = v[k];
#endif
}

}  // namespace novelty::core::lanes
