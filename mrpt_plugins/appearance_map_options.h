// The options of CAppearanceMap: one table (option_table.h) from which its `.ini` section is read,
// its defaults dumped (share/appearance.ini is that dump, tested) and its map file's options
// written and read by key. MRPT's CLoadableOptions interface on top.
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>

#include "maps/appearance/appearance_map.h"
#include "mrpt_plugins/depth_source.h"
#include "mrpt_plugins/option_table.h"

namespace novelty::mrpt_plugins {

/// Everything a CAppearanceMap section configures: the map's options and where camera
/// observations get their depth (depth_source.h).
struct AppearanceMapConfig : public TabledOptions<AppearanceMapConfig> {
  appearance::AppearanceMapOptions map;
  DepthSourceOptions depth;

  static const OptionTable<AppearanceMapConfig>& Table();
  /// The section name of share/appearance.ini.
  static constexpr const char* kSection = "AppearanceMap";
  /// The keys a map file of version 0, and those version 1 added, stored one after another.
  static const std::vector<std::string>& Version0Keys();
  static const std::vector<std::string>& Version1Keys();
};

}  // namespace novelty::mrpt_plugins
