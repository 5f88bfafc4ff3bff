#include "mrpt_plugins/differencing_map_options.h"

#include "mrpt_plugins/view_map_options.h"

namespace novelty::mrpt_plugins {

const OptionTable<DifferencingMapConfig>& DifferencingMapConfig::Table() {
  using C = DifferencingMapConfig;
  static const OptionTable<C> table = [] {
    OptionTable<C> t;
    t.Include(
         ViewMapOptionTable(), [](C & c) -> auto& { return c.map; })
        .Include(
            DepthSourceOptionTable(), [](C & c) -> auto& { return c.depth; })
        .Include(
            PoseCheckOptionTable(), [](C & c) -> auto& { return c.poses; });
    return t;
  }();
  return table;
}

const std::vector<std::string>& DifferencingMapConfig::Version0Keys() {
  static const std::vector<std::string> keys = {"new_view_distance", "new_view_angle_deg",
                                                "max_relative_depth_jump", "depth_tolerance"};
  return keys;
}

const std::vector<std::string>& DifferencingMapConfig::Version1Keys() {
  static const std::vector<std::string> keys = {"angle_power", "weight_by_rays"};
  return keys;
}

}  // namespace novelty::mrpt_plugins
