// The option tables every view-based map shares (option_table.h): how views are made, selected,
// warped and blended (ViewBasedMapOptions), and where camera observations get their depth
// (DepthSourceOptions). The maps' own tables include them.
#pragma once

#include "maps/appearance/view_based_map.h"
#include "mrpt_plugins/depth_source.h"
#include "mrpt_plugins/option_table.h"

namespace novelty::mrpt_plugins {

/// new_view_distance, new_view_angle_deg, view selection, warping and blending.
const OptionTable<appearance::ViewBasedMapOptions>& ViewMapOptionTable();

/// depth_source (rgbd | stereo) and the stereo matcher's range and window.
const OptionTable<DepthSourceOptions>& DepthSourceOptionTable();

}  // namespace novelty::mrpt_plugins
