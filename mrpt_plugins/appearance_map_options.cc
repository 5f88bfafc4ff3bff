#include "mrpt_plugins/appearance_map_options.h"

#include "mrpt_plugins/view_map_options.h"

namespace novelty::mrpt_plugins {

const OptionTable<AppearanceMapConfig>& AppearanceMapConfig::Table() {
  using C = AppearanceMapConfig;
  static const OptionTable<C> table = [] {
    OptionTable<C> t;
    t.Add(
         "forgetting_factor",
         [](C & c) -> auto& { return c.map.surprise.update.forgetting_factor; },
         "f, eq. 4.10-4.11 (thesis value)")
        .Add(
            "xi", [](C & c) -> auto& { return c.map.surprise.update.xi; },
            "xi, eq. 4.8, 1/variance (chosen: noise variance 4 -> tau averages ~25 frames)")
        .Add(
            "sigma_min", [](C & c) -> auto& { return c.map.surprise.update.sigma_min; },
            "sigma_min, eq. 4.8 (chosen: keeps >= 1 % learning rate)")
        .Add(
            "sigma_max", [](C & c) -> auto& { return c.map.surprise.update.sigma_max; },
            "sigma_max, eq. 4.8 (chosen: the initial sigma)")
        .Add(
            "min_variance", [](C & c) -> auto& { return c.map.surprise.update.min_variance; },
            "floor of beta/alpha: 1/12, one quantisation level (0 = the thesis's update)", 1.0, 0.0)
        .Add(
            "initial_alpha", [](C & c) -> auto& { return c.map.initial_prior.alpha; },
            "initial prior, thesis 4.3")
        .Add(
            "initial_beta", [](C & c) -> auto& { return c.map.initial_prior.beta; }, "")
        .Add(
            "initial_tau", [](C & c) -> auto& { return c.map.initial_prior.tau; }, "")
        .Add(
            "initial_sigma", [](C & c) -> auto& { return c.map.initial_prior.sigma; }, "")
        .Add(
            "fast_approximations",
            [](C & c) -> auto& { return c.map.surprise.kl.fast_approximations; },
            "eq. 4.22-4.23 instead of exact ln Gamma and psi")
        .Add(
            "half_precision", [](C & c) -> auto& { return c.map.half_precision; },
            "alpha, beta, sigma stored as half floats (tau always float)")
        .Add(
            "warp_sigma_px", [](C & c) -> auto& { return c.map.warp_sigma_px; },
            "px; prior variance >= (warp_sigma_px * |grad tau|)^2: the warp's error (0 = thesis)",
            1.0, 0.0)
        .Add(
            "learn_warp_sigma", [](C & c) -> auto& { return c.map.learn_warp_sigma; },
            "learn that error from the shift of edges against the prior (false = thesis)", 1.0, 0.0)
        .Add(
            "align_to_prior", [](C & c) -> auto& { return c.map.align_to_prior; },
            "correct the pose by the small rotation aligning frame and prior (false = thesis)", 1.0,
            0.0)
        .Add(
            "predictive_novelty", [](C & c) -> auto& { return c.map.predictive_novelty; },
            "also -ln p(frame | prior), nats: how unexpected, beside surprise (costs ~0.3 ms)", 1.0,
            0.0)
        .Include(
            ViewMapOptionTable(), [](C & c) -> auto& { return c.map.views; })
        .Include(
            DepthSourceOptionTable(), [](C & c) -> auto& { return c.depth; })
        .Include(
            PoseCheckOptionTable(), [](C & c) -> auto& { return c.poses; })
        .Check([](const C& c) {
          c.map.surprise.update.Check();
          stats::CheckNormalGamma(c.map.initial_prior, "initial prior");
          // The prior of a colour channel (0…255): beyond these, every pixel's surprise is 0
          // or saturates, and the panels are black.
          CheckInRange(c.map.initial_prior.alpha, 1e-3, 1e6, "initial_alpha");
          CheckInRange(c.map.initial_prior.beta, 1e-3, 1e9, "initial_beta");
          CheckInRange(c.map.initial_prior.tau, 0, 255, "initial_tau");
          CheckInRange(c.map.initial_prior.sigma, 1e-3, 1e6, "initial_sigma");
          CheckInRange(c.map.surprise.update.xi, 0, 1e6, "xi");
          CheckInRange(c.map.surprise.update.sigma_max, 0, 1e6, "sigma_max");
          CheckInRange(c.map.warp_sigma_px, 0, 10, "warp_sigma_px");
        });
    return t;
  }();
  return table;
}

}  // namespace novelty::mrpt_plugins
