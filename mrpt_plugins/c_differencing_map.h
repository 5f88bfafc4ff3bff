// CDifferencingMap: the image-differencing baseline of 4.3.2 (maps/appearance) as an MRPT metric
// map, the same way as CAppearanceMap: "CDifferencingMap" in CMultiMetricMap .ini files with the
// keys of share/differencing.ini in "[<prefix>_options]" (the view, depth-source and pose-check
// keys the appearance map has too), RGB-D observations with the ROBOT's pose (the camera is at
// robot_pose ⊕ sensorPose), MRPT serialization with atomic saves, grey frusta for SceneViewer3D.
#pragma once

#include "maps/appearance/differencing_map.h"
#include "maps/appearance/product_images.h"
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
  /// The last frame's |ΔY|+|ΔCb|+|ΔCr| in false colour (product_images.h; empty before a frame).
  mrpt::img::CImage differenceImage(const appearance::ProductScales& scales = {}) const {
    return ToCImage(appearance::DifferenceImage(last_, scales));
  }

  MAP_DEFINITION_START(CDifferencingMap)
  DifferencingMapConfig config;  ///< from the section "<prefix>_options"
  MAP_DEFINITION_END(CDifferencingMap)
};

}  // namespace novelty::mrpt_plugins
