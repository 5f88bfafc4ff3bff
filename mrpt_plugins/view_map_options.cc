#include "mrpt_plugins/view_map_options.h"

#include <cmath>

namespace novelty::mrpt_plugins {

const OptionTable<appearance::ViewBasedMapOptions>& ViewMapOptionTable() {
  using O = appearance::ViewBasedMapOptions;
  static const OptionTable<O> table = [] {
    OptionTable<O> t;
    // Files made before an option existed behaved as the legacy value says (map file version 0).
    t.Add(
         "new_view_distance", [](O & o) -> auto& { return o.new_view_distance; },
         "m; a frame this far from every view's anchor becomes a new view (chosen: 8 mm)")
        .Add(
            "new_view_angle_deg", [](O & o) -> auto& { return o.new_view_angle; },
            "... or turned this much from the nearest anchor (chosen: 5 degrees)", M_PI / 180.0)
        .Add(
            "max_view_distance", [](O & o) -> auto& { return o.selection.max_distance; },
            "m; views farther from the camera are not selected (0 = no limit; 3.3.1)")
        .Add(
            "weight_by_rays", [](O & o) -> auto& { return o.selection.weight_by_rays; },
            "a view chosen by k of the 7 rays counts k times in the blend (thesis 3.3)", 1.0, 0.0)
        .Add(
            "max_relative_depth_jump",
            [](O & o) -> auto& { return o.warp.max_relative_depth_jump; },
            "depth-mesh triangles across a larger relative depth step are cut (3.3.2)")
        .Add(
            "near_plane", [](O & o) -> auto& { return o.warp.near_plane; },
            "m; surfaces nearer to the virtual camera are clipped")
        .Add(
            "planar_block", [](O & o) -> auto& { return o.warp.planar_block; },
            "quads; planar blocks of this size are drawn as one (0 = every quad alone)")
        .Add(
            "planar_tolerance", [](O & o) -> auto& { return o.warp.planar_tolerance; },
            "relative depth within which a block counts as planar")
        .Add(
            "depth_tolerance", [](O & o) -> auto& { return o.blend.depth_tolerance; },
            "blend only views within this fraction of the nearest depth (0 = all, thesis)")
        .Add(
            "resolution_power", [](O & o) -> auto& { return o.blend.resolution_power; },
            "blend weight (z_virtual / z_source)^P (0 = thesis's average)")
        .Add(
            "angle_power", [](O & o) -> auto& { return o.blend.angle_power; },
            "blend weight (cos phi / cos phi_best)^A per pixel (0 = thesis's average)", 1.0, 0.0)
        .Add(
            "decoded_views", [](O & o) -> auto& { return o.storage.decoded_views; },
            "views held decoded in memory, the rest compact (0 = all decoded; map_storage.md)")
        .Check([](const O& o) {
          CheckPositive(o.new_view_distance, "new_view_distance");
          CheckPositive(o.new_view_angle, "new_view_angle_deg");
          CheckInRange(o.new_view_distance, 0, 100, "new_view_distance");
          CheckInRange(o.new_view_angle * 180 / M_PI, 0, 180, "new_view_angle_deg");
          CheckPositive(o.warp.max_relative_depth_jump, "max_relative_depth_jump");
          CheckPositive(o.warp.near_plane, "near_plane");
          CheckNotNegative(o.warp.planar_block, "planar_block");
          CheckNotNegative(o.warp.planar_tolerance, "planar_tolerance");
          CheckNotNegative(o.blend.depth_tolerance, "depth_tolerance");
          CheckNotNegative(o.blend.resolution_power, "resolution_power");
          CheckNotNegative(o.blend.angle_power, "angle_power");
          CheckInRange(o.storage.decoded_views, 0, 100000, "decoded_views");
        });
    return t;
  }();
  return table;
}

const OptionTable<DepthSourceOptions>& DepthSourceOptionTable() {
  using O = DepthSourceOptions;
  static const OptionTable<O> table = [] {
    OptionTable<O> t;
    t.AddChoice(
         "depth_source", [](O & o) -> auto& { return o.kind; }, {"rgbd", "stereo"},
         "rgbd: CObservation3DRangeScan; stereo: also CObservationStereoImages (3.2)")
        .Add(
            "stereo_near", [](O & o) -> auto& { return o.stereo.sweep.near; },
            "m; nearest depth plane of the plane sweep")
        .Add(
            "stereo_far", [](O & o) -> auto& { return o.stereo.sweep.far; },
            "m; farthest depth plane")
        .Add(
            "stereo_hypotheses", [](O & o) -> auto& { return o.stereo.sweep.hypotheses; },
            "depth planes")
        .Add(
            "stereo_window", [](O & o) -> auto& { return o.stereo.sweep.window; },
            "pixels; cost averaging window")
        .Check([](const O& o) {
          const auto& s = o.stereo.sweep;
          if (!(s.near > 0 && s.far > s.near) || s.hypotheses < 2 || s.window < 1) {
            throw std::invalid_argument(
                "stereo: need 0 < stereo_near < stereo_far, stereo_hypotheses >= 2 and "
                "stereo_window >= 1");
          }
        });
    return t;
  }();
  return table;
}

}  // namespace novelty::mrpt_plugins
