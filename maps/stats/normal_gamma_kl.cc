#include "maps/stats/normal_gamma_kl.h"

#include <cmath>

namespace novelty::stats {

double NormalGammaKLAsPrinted(const NormalGamma& post, const NormalGamma& prior) {
  const double a = post.alpha, b = post.beta, t = post.tau, s = post.sigma;
  const double a0 = prior.alpha, b0 = prior.beta, t0 = prior.tau, s0 = prior.sigma;
  const double t1 = a * std::log(b) + LogGamma(a0) + 0.5 * std::log(s0) - a0 * std::log(b0) -
                    LogGamma(a) - 0.5 * std::log(s);                          // eq. 4.16
  const double t2 = (b0 - b) * a / b;                                         // eq. 4.17
  const double t3 = (a - a0) * (Digamma(a) - std::log(b));                    // eq. 4.18
  const double t4 = ((t0 * t0 - 2 * t0 * t + t * t) * a / b + s) / (2 * s0);  // eq. 4.19
  const double t5 = -0.5;                                                     // eq. 4.20
  return t1 + t2 + t3 + t4 + t5;
}

}  // namespace novelty::stats
