// CAppearanceMap: the probabilistic appearance map (maps/appearance) as an MRPT metric map.
//
// - insertObservation(CObservation3DRangeScan with intensity image, robotPose) updates the map
//   and computes the frame's products (lastProducts(), surpriseImage()); with
//   `depth_source = stereo` also CObservationStereoImages (depth by plane sweep + belief
//   propagation); other observations are not used.
//   robotPose is the ROBOT's pose: the camera is at robotPose ⊕ obs.sensorPose (robot at the
//   origin if no pose is given). Passing the camera's pose applies the sensor pose twice; poses
//   that look like it are logged as warnings (pose_check.h, poseWarnings()).
// - Declared in a CMultiMetricMap .ini as "CAppearanceMap" (registered when the library loads;
//   LoadMultiMapConfig checks the file); its options are read from the section
//   "<prefix>_options" with the keys of share/appearance.ini (unknown keys: error).
// - MRPT serialization saves views, anchors and every option by key (the depth source too);
//   SaveToFile writes atomically and LoadFromFile leaves the map as it was when the file is
//   truncated or not a CAppearanceMap.
// - getVisualizationInto draws each reference view's frustum coloured by its mean uncertainty
//   Σβ (green: certain, red: uncertain); SaveSceneFile writes them for SceneViewer3D.
#pragma once

#include "maps/appearance/appearance_map.h"
#include "maps/appearance/product_images.h"
#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/view_map_adapter.h"

namespace novelty::mrpt_plugins {

class CAppearanceMap;

/// A map that takes each frame's products from a CAppearanceMap as it inserts the frame
/// (CObjectDatabaseMap): handed explicitly, so that neither the order of the maps in a
/// CMultiMetricMap nor frame counters decide what it reads.
class AppearanceFrameConsumer {
 public:
  virtual ~AppearanceFrameConsumer() = default;
  /// Called at the end of `appearance`'s insertion of a frame (lastFrame(), lastProducts()).
  virtual void ConsumeAppearanceFrame(const CAppearanceMap& appearance) = 0;
};

class CAppearanceMap : public ViewMapAdapter<appearance::AppearanceMap, AppearanceMapConfig,
                                             appearance::AppearanceProducts> {
  DEFINE_SERIALIZABLE(CAppearanceMap, novelty::mrpt_plugins)

 public:
  explicit CAppearanceMap(const AppearanceMapConfig& config = {});
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
  void LoadFromFile(const std::string& path) { LoadAs<CAppearanceMap>(path); }
  /// Whether lastProducts() holds the depth the map expected (AppearanceProducts::
  /// expected_depth): off by default, turned on by a CObjectDatabaseMap linked to this map.
  void setPredictDepth(bool on) {
    predict_depth_ = on;
    map_->set_predict_depth(on);
  }
  /// Hands every frame inserted from now on to `consumer` (once, however often added) until
  /// removeFrameConsumer; the consumer must remove itself before it is destroyed.
  void addFrameConsumer(AppearanceFrameConsumer* consumer);
  void removeFrameConsumer(AppearanceFrameConsumer* consumer);
  /// The last frame's surprise and uncertainty Σβ in false colour on the fixed scales of
  /// maps/appearance/product_images.h (empty before the first frame): for mrpt::gui windows, or
  /// written into a rawlog with ProductObservation (cimage_products.h) for RawLogViewer.
  mrpt::img::CImage surpriseImage(const appearance::ProductScales& scales = {}) const {
    return ToCImage(appearance::SurpriseImage(last_, scales));
  }
  mrpt::img::CImage uncertaintyImage(const appearance::ProductScales& scales = {}) const {
    return ToCImage(appearance::UncertaintyImage(last_, scales));
  }

  MAP_DEFINITION_START(CAppearanceMap)
  AppearanceMapConfig config;  ///< from the section "<prefix>_options"
  MAP_DEFINITION_END(CAppearanceMap)

 private:
  void MapReplaced() override { map_->set_predict_depth(predict_depth_); }
  void FrameInserted() override;
  bool predict_depth_ = false;
  std::vector<AppearanceFrameConsumer*> consumers_;  // not owned
};

}  // namespace novelty::mrpt_plugins
