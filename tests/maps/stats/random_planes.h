// Test helper: normal-gamma parameter planes of n pixels with plausible map values and
// observations near and far from the mean, for the batch and packet kernels' tests.
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "maps/stats/normal_gamma_batch.h"

namespace novelty::stats {

// A plane set of n pixels with plausible map parameters and observations.
struct RandomPlanes {
  std::vector<float> alpha, beta, tau, sigma, x;
  explicit RandomPlanes(std::size_t n, unsigned seed) : alpha(n), beta(n), tau(n), sigma(n), x(n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> a(0.6f, 3.0f), lb(-2.0f, 8.0f), t(0.0f, 255.0f),
        ls(-4.0f, 1.6f), dx(-80.0f, 80.0f);
    for (std::size_t i = 0; i < n; ++i) {
      alpha[i] = a(rng);
      beta[i] = std::exp(lb(rng));
      tau[i] = t(rng);
      sigma[i] = std::exp(ls(rng));
      x[i] = tau[i] + (i % 3 == 0 ? dx(rng) * 0.05f : dx(rng));
    }
  }
  ConstNormalGammaPlanes View() const {
    return {alpha.data(), beta.data(), tau.data(), sigma.data()};
  }
  NormalGammaPlanes Mutable() { return {alpha.data(), beta.data(), tau.data(), sigma.data()}; }
};

}  // namespace novelty::stats
