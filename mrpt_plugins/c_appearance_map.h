// CAppearanceMap: the probabilistic appearance map (maps/appearance) as an MRPT metric map.
//
// - insertObservation(CObservation3DRangeScan with intensity image, robotPose) updates the map
//   and computes the frame's products (lastProducts()); with `depth_source = stereo` also
//   CObservationStereoImages (depth by plane sweep + belief propagation); other observations are
//   not used.
//   The camera pose is robotPose ⊕ sensorPose (robot at the origin if no pose is given).
// - Declared in a CMultiMetricMap .ini as "CAppearanceMap" (call RegisterMaps() first); its
//   options are read from the section "<prefix>_options" with the keys of share/appearance.ini
//   (unknown keys: error).
// - MRPT serialization saves views, anchors and every option by key (the depth source too);
//   SaveToFile writes atomically and LoadFromFile leaves the map as it was when the file is
//   truncated or not a CAppearanceMap.
// - getVisualizationInto draws each reference view's frustum coloured by its mean uncertainty
//   Σβ (green: certain, red: uncertain); SaveSceneFile writes them for SceneViewer3D.
#pragma once

#include "maps/appearance/appearance_map.h"
#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/view_map_adapter.h"

namespace novelty::mrpt_plugins {

class CAppearanceMap : public ViewMapAdapter<appearance::AppearanceMap, AppearanceMapConfig,
                                             appearance::AppearanceProducts> {
  DEFINE_SERIALIZABLE(CAppearanceMap, novelty::mrpt_plugins)

 public:
  explicit CAppearanceMap(const AppearanceMapConfig& config = {});
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
  void LoadFromFile(const std::string& path) { LoadAs<CAppearanceMap>(path); }

  MAP_DEFINITION_START(CAppearanceMap)
  AppearanceMapConfig config;  ///< from the section "<prefix>_options"
  MAP_DEFINITION_END(CAppearanceMap)
};

}  // namespace novelty::mrpt_plugins
