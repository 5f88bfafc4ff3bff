// CAppearanceMap: the probabilistic appearance map (maps/appearance) as an MRPT metric map.
//
// - insertObservation(CObservation3DRangeScan with intensity image, robotPose) updates the map
//   and computes the frame's products (lastProducts()); other observations are not used.
//   The camera pose is robotPose ⊕ sensorPose (robot at the origin if no pose is given).
// - Declared in a CMultiMetricMap .ini as "CAppearanceMap"; its options are read from the
//   section "<prefix>_options" with the keys of share/appearance.ini (unknown keys: error).
// - MRPT serialization saves views, anchors and options; SaveToFile writes atomically
//   (temporary + rename) and LoadFromFile leaves the map as it was when the file is truncated or
//   not a CAppearanceMap.
// - getVisualizationInto draws each reference view's frustum coloured by its mean uncertainty
//   Σβ (green: certain, red: uncertain), so SceneViewer3D can show a saved map's coverage.
#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/obs/CObservation.h>

#include <memory>
#include <string>

#include "maps/appearance/appearance_map.h"

namespace novelty::mrpt_plugins {

class CAppearanceMap : public mrpt::maps::CMetricMap {
  DEFINE_SERIALIZABLE(CAppearanceMap, novelty::mrpt_plugins)

 public:
  explicit CAppearanceMap(const appearance::AppearanceMapOptions& options = {});

  bool isEmpty() const override;
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
  /// Writes the visualization (frusta) as an MRPT scene that SceneViewer3D opens; throws
  /// std::runtime_error naming the file on failure.
  void SaveSceneFile(const std::string& path) const;
  /// Saves the map as `prefix + ".appearance_map"` (see SaveToFile).
  void saveMetricMapRepresentationToFile(const std::string& prefix) const override;

  /// Inserts a decoded frame directly (what insertObservation does after decoding); for callers
  /// that read frames themselves. Same errors as appearance::AppearanceMap::Insert.
  const appearance::AppearanceProducts& InsertFrame(const cv::Mat& rgb, const cv::Mat& depth,
                                                    const views::PinholeCamera& camera,
                                                    const Eigen::Isometry3d& T_world_cam);

  /// Products of the last inserted frame (empty before the first).
  const appearance::AppearanceProducts& lastProducts() const { return last_; }
  const appearance::AppearanceMap& map() const { return *map_; }

  /// MRPT-serialized map, written to a temporary file renamed into place.
  void SaveToFile(const std::string& path) const;
  /// Replaces this map by the one in `path`; throws std::runtime_error naming the file and the
  /// problem, leaving this map unchanged.
  void LoadFromFile(const std::string& path);

  MAP_DEFINITION_START(CAppearanceMap)
  appearance::AppearanceMapOptions options;
  MAP_DEFINITION_END(CAppearanceMap)

 private:
  void internal_clear() override;
  bool internal_insertObservation(
      const mrpt::obs::CObservation& obs,
      const std::optional<const mrpt::poses::CPose3D>& robot_pose = std::nullopt) override;
  double internal_computeObservationLikelihood(const mrpt::obs::CObservation&,
                                               const mrpt::poses::CPose3D&) const override {
    return 0.0;  // surprise is the product, not a likelihood for localization
  }
  bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation&) const override {
    return false;
  }

  std::unique_ptr<appearance::AppearanceMap> map_;
  appearance::AppearanceProducts last_;
};

}  // namespace novelty::mrpt_plugins
