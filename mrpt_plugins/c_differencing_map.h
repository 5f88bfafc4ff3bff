// CDifferencingMap: the image-differencing baseline of 4.3.2 (maps/appearance) as an MRPT metric
// map, the same way as CAppearanceMap: "CDifferencingMap" in CMultiMetricMap .ini files with the
// view keys of share/appearance.ini in "[<prefix>_options]" (new_view_distance,
// new_view_angle_deg, max_relative_depth_jump, depth_tolerance), RGB-D observations, MRPT
// serialization with atomic saves, frusta for SceneViewer3D.
#pragma once

#include <mrpt/maps/CMetricMap.h>

#include <memory>
#include <string>

#include "maps/appearance/differencing_map.h"

namespace novelty::mrpt_plugins {

class CDifferencingMap : public mrpt::maps::CMetricMap {
  DEFINE_SERIALIZABLE(CDifferencingMap, novelty::mrpt_plugins)

 public:
  explicit CDifferencingMap(const appearance::ViewBasedMapOptions& options = {});

  bool isEmpty() const override;
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
  void saveMetricMapRepresentationToFile(const std::string& prefix) const override;

  const appearance::DifferencingProducts& InsertFrame(const cv::Mat& rgb, const cv::Mat& depth,
                                                      const views::PinholeCamera& camera,
                                                      const Eigen::Isometry3d& T_world_cam);
  const appearance::DifferencingProducts& lastProducts() const { return last_; }
  const appearance::DifferencingMap& map() const { return *map_; }
  void SaveToFile(const std::string& path) const;
  void LoadFromFile(const std::string& path);

  MAP_DEFINITION_START(CDifferencingMap)
  appearance::ViewBasedMapOptions options;
  MAP_DEFINITION_END(CDifferencingMap)

 private:
  void internal_clear() override;
  bool internal_insertObservation(
      const mrpt::obs::CObservation& obs,
      const std::optional<const mrpt::poses::CPose3D>& robot_pose = std::nullopt) override;
  double internal_computeObservationLikelihood(const mrpt::obs::CObservation&,
                                               const mrpt::poses::CPose3D&) const override {
    return 0.0;
  }
  bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation&) const override {
    return false;
  }

  std::unique_ptr<appearance::DifferencingMap> map_;
  appearance::DifferencingProducts last_;
};

}  // namespace novelty::mrpt_plugins
