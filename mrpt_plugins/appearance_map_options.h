// The options of CAppearanceMap: one table (option_table.h) from which its `.ini` section is read,
// its defaults dumped (share/appearance.ini is that dump, tested) and its map file's options
// written and read by key. MRPT's CLoadableOptions interface on top.
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>

#include "maps/appearance/appearance_map.h"
#include "mrpt_plugins/depth_source.h"
#include "mrpt_plugins/option_table.h"
#include "mrpt_plugins/pose_check.h"

namespace novelty::mrpt_plugins {

/// Everything a CAppearanceMap section configures: the map's options and where camera
/// observations get their depth (depth_source.h).
struct AppearanceMapConfig : public TabledOptions<AppearanceMapConfig> {
  appearance::AppearanceMapOptions map;
  DepthSourceOptions depth;
  PoseCheckOptions poses;

  static const OptionTable<AppearanceMapConfig>& Table();
  static constexpr const char* kClass = "CAppearanceMap";
  /// The options section of the first CAppearanceMap of a CMultiMetricMap .ini whose maps are
  /// declared in [map] (MRPT's naming: <section>_<Class>_<NN>_options), as in share/*.ini.
  static constexpr const char* kSection = "map_CAppearanceMap_00_options";
};

}  // namespace novelty::mrpt_plugins
