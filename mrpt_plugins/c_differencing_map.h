// CDifferencingMap: the image-differencing baseline of 4.3.2 (maps/appearance) as an MRPT metric
// map, the same way as CAppearanceMap: "CDifferencingMap" in CMultiMetricMap .ini files with the
// view keys of share/appearance.ini in "[<prefix>_options]" (new_view_distance,
// new_view_angle_deg, max_relative_depth_jump, depth_tolerance, angle_power, weight_by_rays;
// the surprise keys are read and not used), RGB-D observations, MRPT
// serialization with atomic saves, grey frusta for SceneViewer3D.
#pragma once

#include "maps/appearance/differencing_map.h"
#include "mrpt_plugins/view_map_adapter.h"

namespace novelty::mrpt_plugins {

class CDifferencingMap
    : public ViewMapAdapter<appearance::DifferencingMap, appearance::ViewBasedMapOptions,
                            appearance::DifferencingProducts> {
  DEFINE_SERIALIZABLE(CDifferencingMap, novelty::mrpt_plugins)

 public:
  explicit CDifferencingMap(const appearance::ViewBasedMapOptions& options = {});
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
  void LoadFromFile(const std::string& path) { LoadAs<CDifferencingMap>(path); }

  MAP_DEFINITION_START(CDifferencingMap)
  appearance::ViewBasedMapOptions options;
  DepthSourceOptions depth_source;
  MAP_DEFINITION_END(CDifferencingMap)
};

}  // namespace novelty::mrpt_plugins
