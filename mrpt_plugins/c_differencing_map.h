// CDifferencingMap: the image-differencing baseline of 4.3.2 (maps/appearance) as an MRPT metric
// map, the same way as CAppearanceMap: "CDifferencingMap" in CMultiMetricMap .ini files with the
// keys of share/differencing.ini in "[<prefix>_options]" (the view and depth-source keys the
// appearance map has too), RGB-D observations, MRPT
// serialization with atomic saves, grey frusta for SceneViewer3D.
#pragma once

#include "maps/appearance/differencing_map.h"
#include "mrpt_plugins/differencing_map_options.h"
#include "mrpt_plugins/view_map_adapter.h"

namespace novelty::mrpt_plugins {

class CDifferencingMap : public ViewMapAdapter<appearance::DifferencingMap, DifferencingMapConfig,
                                               appearance::DifferencingProducts> {
  DEFINE_SERIALIZABLE(CDifferencingMap, novelty::mrpt_plugins)

 public:
  explicit CDifferencingMap(const DifferencingMapConfig& config = {});
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
  void LoadFromFile(const std::string& path) { LoadAs<CDifferencingMap>(path); }

  MAP_DEFINITION_START(CDifferencingMap)
  DifferencingMapConfig config;  ///< from the section "<prefix>_options"
  MAP_DEFINITION_END(CDifferencingMap)
};

}  // namespace novelty::mrpt_plugins
