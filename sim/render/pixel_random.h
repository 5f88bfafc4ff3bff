// Counter-based random numbers: the value for (seed, frame, pixel, draw) does not depend on which
// thread renders the pixel or in which order, so multi-threaded renders are bit-identical.
#pragma once

#include <cmath>
#include <cstdint>

namespace novelty::sim {

class PixelRandom {
 public:
  PixelRandom(std::uint64_t seed, std::uint64_t stream, std::uint64_t pixel)
      : state_(Mix(Mix(seed ^ 0x9E3779B97F4A7C15ull) ^ stream) ^ (pixel * 0xD1B54A32D192ED03ull)) {}

  /// Uniform in [0, 1).
  double Uniform() { return double(Next() >> 11) * 0x1.0p-53; }

  /// Standard normal (Box-Muller; each pair of uniforms gives two normals).
  double Gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - Uniform(), u2 = Uniform();
    const double r = std::sqrt(-2.0 * std::log(u1)), phi = 6.283185307179586 * u2;
    spare_ = r * std::sin(phi);
    has_spare_ = true;
    return r * std::cos(phi);
  }

 private:
  static std::uint64_t Mix(std::uint64_t z) {  // splitmix64 finaliser
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t Next() { return Mix(state_ += 0x9E3779B97F4A7C15ull); }
  std::uint64_t state_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace novelty::sim
