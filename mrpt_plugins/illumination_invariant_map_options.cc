#include "mrpt_plugins/illumination_invariant_map_options.h"

#include "core/range_check.h"

namespace novelty::mrpt_plugins {

const OptionTable<IlluminationInvariantMapConfig>& IlluminationInvariantMapConfig::Table() {
  using C = IlluminationInvariantMapConfig;
  static const OptionTable<C> table = [] {
    OptionTable<C> t;
    t.Add(
         "viewpoint_distance", [](C & c) -> auto& { return c.map.viewpoint_distance; },
         "m, a frame of the first lighting is a new viewpoint this far from the last (6.1: as "
         "dense as the camera's frames)")
        .Add(
            "viewpoint_angle_deg", [](C & c) -> auto& { return c.map.viewpoint_angle_deg; },
            "deg, ... or turned this much from it")
        .Add(
            "min_viewpoint_coverage", [](C & c) -> auto& { return c.map.min_viewpoint_coverage; },
            "share of the pixels a viewpoint's depth knows with an invariant value, to keep it "
            "(chosen)")
        .AddChoice(
            "colour", [](C & c) -> auto& { return c.map.invariant.colour; },
            {"per-channel", "luminance-chromaticity"},
            "per-channel (each RGB channel, the thesis) | luminance-chromaticity (scores better on "
            "the table and specular scenes)")
        .Add(
            "min_intensity", [](C & c) -> auto& { return c.map.invariant.min_intensity; },
            "0..255, smaller intensities are clipped before the log (6.1.2; 3 as the MIT code)")
        .Add(
            "min_lightings", [](C & c) -> auto& { return c.map.invariant.min_lightings; },
            "lightings that must cover a pixel for an invariant value there (one is no median)")
        .Add(
            "kappa", [](C & c) -> auto& { return c.map.model.kappa; },
            "kappa of T_Y = mean / (1 - kappa) (eq. 6.18: 0.5 Lambertian, 0.2 specular)")
        .Add(
            "missing_texture", [](C & c) -> auto& { return c.map.model.missing_texture; },
            "also judge the texture r-hat has and the frame lacks (beyond the thesis; finds "
            "objects coloured like the surface they hide)")
        .Add(
            "texture_block", [](C & c) -> auto& { return c.map.model.texture.block; },
            "pixels per side (odd) of the block the missing texture is summed over")
        .Add(
            "zernike_max_order", [](C & c) -> auto& { return c.map.zernike.max_order; },
            "highest Zernike order (eq. 6.21; the thesis 120, see zernike_moments.h)")
        .Add(
            "zernike_grid", [](C & c) -> auto& { return c.map.zernike.grid; },
            "cells per side of the disc a shape is sampled on")
        .Add(
            "min_region_pixels", [](C & c) -> auto& { return c.map.novelty.min_region_pixels; },
            "regions of fewer pixels are not shape-matched (chosen)")
        .Add(
            "min_window_share", [](C & c) -> auto& { return c.map.novelty.min_window_share; },
            "share of both shapes a matching window must hold (the thesis: any; chosen)")
        .AddChoice(
            "shape_scale", [](C & c) -> auto& { return c.map.novelty.shape_scale; },
            {"frame", "empty"},
            "e-hat of eq. 6.24: frame (the frame's largest e, the thesis) | empty (each region's "
            "distance to the empty shape)")
        .Add(
            "false_alarm_rate", [](C & c) -> auto& { return c.map.threshold.false_alarm_rate; },
            "share of an unchanged new lighting's pixels above the decision threshold learnt by "
            "leaving one training lighting out (beyond the thesis)")
        .Add(
            "threshold_viewpoints", [](C & c) -> auto& { return c.map.threshold.viewpoints; },
            "viewpoints the threshold is learnt at (each costs one invariant image per "
            "lighting; 0: no threshold)")
        .Check([](const C& c) {
          const illumination::IlluminationMapOptions& o = c.map;
          CheckInRange(o.viewpoint_distance, 0, 100, "viewpoint_distance");
          CheckInRange(o.viewpoint_angle_deg, 0, 180, "viewpoint_angle_deg");
          CheckInRange(o.min_viewpoint_coverage, 0, 1, "min_viewpoint_coverage");
          CheckInRange(o.invariant.min_intensity, 1e-3, 255, "min_intensity");
          CheckInRange(o.invariant.min_lightings, 2, 1000, "min_lightings");
          CheckInRange(o.model.kappa, 0, 0.999, "kappa");
          CheckInRange(o.model.texture.block, 1, illumination::kMaxTextureBlock, "texture_block");
          if (o.model.texture.block % 2 == 0)
            throw std::invalid_argument("texture_block: " + std::to_string(o.model.texture.block) +
                                        " is even; the block needs a centre pixel");
          CheckInRange(o.zernike.max_order, 0, 200, "zernike_max_order");
          CheckInRange(o.zernike.grid, 2, 512, "zernike_grid");
          CheckInRange(o.novelty.min_region_pixels, 1, 1000000, "min_region_pixels");
          CheckInRange(o.novelty.min_window_share, 0, 1, "min_window_share");
          CheckInRange(o.threshold.false_alarm_rate, 1e-6, 0.5, "false_alarm_rate");
          CheckInRange(o.threshold.viewpoints, 0, 1000, "threshold_viewpoints");
        });
    return t;
  }();
  return table;
}

}  // namespace novelty::mrpt_plugins
