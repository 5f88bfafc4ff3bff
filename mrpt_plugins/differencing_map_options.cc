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

}  // namespace novelty::mrpt_plugins
