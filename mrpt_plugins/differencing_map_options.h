// The options of CDifferencingMap: the view options every view-based map has and its depth
// source (view_map_options.h), in one table (option_table.h) — share/differencing.ini is the dump
// of its defaults (tested).
#pragma once

#include <string>
#include <vector>

#include "maps/appearance/view_based_map.h"
#include "mrpt_plugins/depth_source.h"
#include "mrpt_plugins/option_table.h"
#include "mrpt_plugins/pose_check.h"

namespace novelty::mrpt_plugins {

struct DifferencingMapConfig : public TabledOptions<DifferencingMapConfig> {
  appearance::ViewBasedMapOptions map;
  DepthSourceOptions depth;
  PoseCheckOptions poses;

  static const OptionTable<DifferencingMapConfig>& Table();
  static constexpr const char* kClass = "CDifferencingMap";
  /// The options section of the first CDifferencingMap of a CMultiMetricMap .ini whose maps are
  /// declared in [map] (MRPT's naming: <section>_<Class>_<NN>_options), as in share/*.ini.
  static constexpr const char* kSection = "map_CDifferencingMap_00_options";
};

}  // namespace novelty::mrpt_plugins
