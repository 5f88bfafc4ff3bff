// CIlluminationInvariantMap: the illumination-invariant image-based map of thesis ch. 6
// (maps/illumination/illumination_map.h) as an MRPT metric map — what the room looks like without
// its lighting, at a dense series of viewpoints, and what lighting can do to it, so that a new
// frame's real changes stand out and its shadows and highlights do not.
//
// - Declared in a CMultiMetricMap .ini ("CIlluminationInvariantMap_count = 1", options in
//   "<prefix>_options" with the keys of share/illumination_invariant.ini; unknown keys are
//   errors).
// - Acquisition: one pass of the robot per lighting (6.1), the lamps fixed during it (leave out
//   frames taken while they move); the first lighting's path places the viewpoints.
//   beginLighting() before each; insertObservation takes CObservation3DRangeScan with a range
//   (depth) and an intensity image — in acquisition and in detection; other observation types
//   are skipped (returns false) — with the robot pose, all in one frame (a tracker's, or
//   registered: 6.1.1); without a pose the robot is at the origin and the camera at sensorPose.
//   beginLighting() renders the ending lighting's virtual images and finishAcquisition() makes
//   the invariant images and models: both slow (up to a second per viewpoint where virtual images
//   leave pixels uncovered), both throw std::invalid_argument and leave the map as it was (a
//   lighting without frames, fewer than two lightings, no viewpoint covered).
// - In a CMultiMetricMap every map gets every observation: a CAppearanceMap beside this one
//   learns the training lightings too; a multimap holding a map still acquiring cannot be saved.
// - Detection: after that, insertObservation judges each frame against the map interpolated at
//   its pose; lastResult() holds the interpolated invariant image, the information maps and the
//   novelty Δ (eq. 6.24), and the *Image() methods draw them as MRPT images.
// - MRPT serialization saves the options, the lightings and every viewpoint (pose, camera,
//   depth, invariant image with its coverage, shapes, gamma models); a map still acquiring cannot
//   be saved (its frames are not a map yet). SaveToFile writes atomically; LoadFromFile leaves
//   the map as it was when the file is truncated, damaged or of another class.
// - getVisualizationInto draws the viewpoints' frusta, green to red by how little of the
//   viewpoint the invariant image covers; asString lists lightings, viewpoints and thresholds.
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <memory>
#include <string>

#include "maps/illumination/illumination_map.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"

namespace novelty::mrpt_plugins {

class CIlluminationInvariantMap : public mrpt::maps::CMetricMap {
  DEFINE_SERIALIZABLE(CIlluminationInvariantMap, novelty::mrpt_plugins)

 public:
  explicit CIlluminationInvariantMap(const IlluminationInvariantMapConfig& config = {});

  /// Starts the next lighting's sequence (illumination_map.h: BeginLighting).
  void beginLighting() { map_->BeginLighting(); }
  /// Ends the acquisition: invariant images and models at every viewpoint. Throws
  /// std::invalid_argument with fewer than two lightings.
  void finishAcquisition() { map_->Build(); }
  bool acquired() const { return map_->built(); }

  bool isEmpty() const override { return map_->size() == 0; }
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;

  /// The last judged frame and its result (empty before the first).
  const core::Frame& lastFrame() const { return last_frame_; }
  const illumination::IlluminationMapResult& lastResult() const { return last_; }
  /// Pictures of the last result: the interpolated invariant image (exp r̂: the reflectance on
  /// the camera's 0…255 scale, up to the constant r̂ is defined with), the novelty Δ in false
  /// colour up to `max_novelty` and the luminance information i_Y up to `max_information` (both
  /// in nats, eq. 6.17 and 6.24; T_Y, asString's mean, is where i_Y starts a region).
  mrpt::img::CImage invariantImage() const;
  mrpt::img::CImage noveltyImage(double max_novelty = 20.0) const;
  mrpt::img::CImage informationImage(double max_information = 10.0) const;
  const illumination::IlluminationMap& map() const { return *map_; }
  const IlluminationInvariantMapConfig& config() const { return config_; }

  void SaveToFile(const std::string& path) const;
  /// Replaces this map by the CIlluminationInvariantMap in `path`; throws std::runtime_error
  /// naming the file and leaves this map as it was.
  void LoadFromFile(const std::string& path);
  /// Saves the map as `prefix` + ".illumination_invariant".
  void saveMetricMapRepresentationToFile(const std::string& prefix) const override;

  MAP_DEFINITION_START(CIlluminationInvariantMap)
  IlluminationInvariantMapConfig config;  ///< from the section "<prefix>_options"
  MAP_DEFINITION_END(CIlluminationInvariantMap)

 private:
  void internal_clear() override;
  bool internal_insertObservation(
      const mrpt::obs::CObservation& obs,
      const std::optional<const mrpt::poses::CPose3D>& robot_pose = std::nullopt) override;
  double internal_computeObservationLikelihood(const mrpt::obs::CObservation&,
                                               const mrpt::poses::CPose3D&) const override {
    return 0.0;  // novelty is the product, not a likelihood for localization
  }
  bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation&) const override {
    return false;
  }

  IlluminationInvariantMapConfig config_;
  std::unique_ptr<illumination::IlluminationMap> map_;
  core::Frame last_frame_;
  illumination::IlluminationMapResult last_;
};

}  // namespace novelty::mrpt_plugins
