// The blend kernel's arithmetic (view_blender.cc) in one-pixel (float, int) and sixteen-pixel
// (F16, I16: core/lanes.h) forms, so that one kernel template serves a row's body and its tail.
// Included by view_blender.cc only.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>
#include <type_traits>

#include "core/lanes.h"

namespace novelty::views::blend {

using core::lanes::F16;
using core::lanes::I16;
using core::lanes::kLanes;
using core::lanes::Select;

// Scalar (one pixel) and vector (sixteen) forms of the few operations the sampling kernel needs,
// so that one kernel serves the row's body and its tail.
inline float LoadLane(const float* p, float) {
  return *p;
}
inline F16 LoadLane(const float* p, F16) {
  return core::lanes::Load(p);
}
inline int ToInt(float x) {
  return int(x);
}
inline I16 ToInt(F16 x) {
  return core::lanes::AsInt(x);
}
inline float ToFloat(int x) {
  return float(x);
}
inline F16 ToFloat(I16 x) {
  return core::lanes::AsFloat(x);
}
inline int GatherBytes(const char* base, int offset) {
  int v;
  std::memcpy(&v, base + offset, 4);
  return v;
}
inline float AsFloatBits(int bits) {
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}
inline F16 AsFloatBits(I16 bits) {
  return core::lanes::BitCast<F16>(bits);
}
// IEEE half floats (in the low 16 bits) to float (lanes.h).
inline float HalfToFloat(int bits) {
  return core::lanes::HalfToFloat(uint32_t(bits));
}
// Stores one value (T = float) or sixteen at `stride` floats apart (interleaved channels).
inline void ScatterLane(float* p, int, float v) {
  *p = v;
}
inline void ScatterLane(float* p, int stride, F16 v) {
  core::lanes::Scatter(p, core::lanes::AsInt(core::lanes::Iota()) * stride, v);
}
// 255 where `hit`, 0 elsewhere, for one pixel or sixteen; returns how many are hit.
inline int StoreValid(uint8_t* p, bool hit) {
  *p = hit ? 255 : 0;
  return hit;
}
inline int StoreValid(uint8_t* p, I16 hit) {
  core::lanes::StoreMaskBytes(p, hit);
  return core::lanes::Count(hit);
}
// x^p for one pixel or sixteen. Whole powers up to 64 (the blend's usual ones) by repeated
// squaring, in vector registers: std::pow lane by lane dominated a blend with angle_power
// (BM_AppearanceMapSevenViews with angle_power set).
template <typename T>
inline T Pow(T x, float p) {
  const int n = int(p);
  if (float(n) == p && n >= 1 && n <= 64) {
    T result = T{} + 1.0f;
    for (int e = n; e > 0; e >>= 1, x = x * x)
      if (e & 1) result = result * x;
    return result;
  }
  if constexpr (std::is_same_v<T, float>) {
    return std::pow(x, p);
  } else {
    for (int k = 0; k < kLanes; ++k) x[k] = std::pow(x[k], p);
    return x;
  }
}
template <typename T>
inline T Max(T x, float lo) {
  return Select(x > lo, x, T{} + lo);
}
template <typename T>
inline T Clamp(T x, float lo, float hi) {
  x = Select(x < lo, T{} + lo, x);
  return Select(x > hi, T{} + hi, x);
}
// The (u, v) pairs of the warp map at pixel x: interleaved in memory.
inline void LoadMap(const cv::Vec2f* map, float& u, float& v) {
  u = (*map)[0];
  v = (*map)[1];
}
inline void LoadMap(const cv::Vec2f* map, F16& u, F16& v) {
  core::lanes::LoadMaskedPairs(&(*map)[0], I16{} - 1, u, v);
}

}  // namespace novelty::views::blend
