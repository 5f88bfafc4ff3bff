// Elementwise maths that reads the same for a double and for an Eigen fixed-size array, so one
// template of each formula serves the scalar reference path and the vectorised per-pixel path.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/eigen_abi.h"

namespace novelty::stats {

namespace detail {
template <class T, class = void>
struct ScalarOfImpl {
  using type = T;
};
template <class T>
struct ScalarOfImpl<T, std::void_t<typename T::Scalar>> {
  using type = typename T::Scalar;
};
}  // namespace detail

/// The element type: T itself for float/double, T::Scalar for Eigen arrays.
template <class T>
using ScalarOf = typename detail::ScalarOfImpl<T>::type;

/// A value of type T with every element equal to v (T is a scalar or an Eigen fixed-size array).
template <class T>
T Filled(ScalarOf<T> v) {
  if constexpr (std::is_arithmetic_v<T>) {
    return v;
  } else {
    return T::Constant(v);
  }
}

inline double Log(double x) {
  return std::log(x);
}
inline float Log(float x) {
  return std::log(x);
}
inline double Exp(double x) {
  return std::exp(x);
}
inline float Exp(float x) {
  return std::exp(x);
}
inline double Min(double a, double b) {
  return std::min(a, b);
}
inline float Min(float a, float b) {
  return std::min(a, b);
}
inline double Max(double a, double b) {
  return std::max(a, b);
}
inline float Max(float a, float b) {
  return std::max(a, b);
}

template <class D>
auto Log(const Eigen::ArrayBase<D>& x) {
  return x.log().eval();
}
template <class D>
auto Exp(const Eigen::ArrayBase<D>& x) {
  return x.exp().eval();
}
template <class D>
auto Min(const Eigen::ArrayBase<D>& a, const Eigen::ArrayBase<D>& b) {
  return a.min(b).eval();
}
template <class D>
auto Max(const Eigen::ArrayBase<D>& a, const Eigen::ArrayBase<D>& b) {
  return a.max(b).eval();
}
template <class D>
auto Min(const Eigen::ArrayBase<D>& a, typename D::Scalar b) {
  return a.min(b).eval();
}
template <class D>
auto Max(const Eigen::ArrayBase<D>& a, typename D::Scalar b) {
  return a.max(b).eval();
}

}  // namespace novelty::stats
