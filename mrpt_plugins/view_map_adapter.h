// What CAppearanceMap and CDifferencingMap share as MRPT metric maps: a view-based map from
// maps/appearance inside an mrpt::maps::CMetricMap — RGB-D observations (or stereo pairs, with a
// stereo depth source) in, products of the last frame out, atomic saves, loads that keep the map
// when the file is bad, a .3Dscene of the frusta. Each class adds its serialization, map
// definition and visualization.
#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "mrpt_plugins/depth_source.h"
#include "mrpt_plugins/map_files.h"
#include "mrpt_plugins/register_maps.h"

namespace novelty::mrpt_plugins {

template <class Map, class Options, class Products>
class ViewMapAdapter : public mrpt::maps::CMetricMap {
 public:
  bool isEmpty() const override { return map_->store().size() == 0; }

  /// Inserts a decoded frame directly (what insertObservation does after decoding), for callers
  /// that read frames themselves. Same errors as the map's Insert.
  const Products& InsertFrame(const cv::Mat& rgb, const cv::Mat& depth,
                              const views::PinholeCamera& camera,
                              const Eigen::Isometry3d& T_world_cam) {
    last_ = map_->Insert(rgb, depth, camera, T_world_cam);
    frame_ = {rgb, depth, camera, T_world_cam};
    return last_;
  }
  /// Where camera observations without depth get it (default: they are not used).
  void setDepthSource(const DepthSourceOptions& options) { depth_source_ = options; }
  const DepthSourceOptions& depthSource() const { return depth_source_; }
  /// Products of the last inserted frame (empty before the first).
  const Products& lastProducts() const { return last_; }
  /// The last inserted frame as the map saw it: image, depth, camera and T_world_cam (decoded
  /// from the observation, the pose robot ⊕ sensor).
  const ObservedFrame& lastFrame() const { return frame_; }
  const Map& map() const { return *map_; }

  /// MRPT-serialized map, written to a temporary file renamed into place.
  void SaveToFile(const std::string& path) const { SaveAtomically(*this, path); }
  /// Writes the frusta as an MRPT scene that SceneViewer3D opens.
  void SaveSceneFile(const std::string& path) const {
    mrpt::opengl::COpenGLScene scene;
    auto objects = mrpt::opengl::CSetOfObjects::Create();
    this->getVisualizationInto(*objects);
    scene.insert(objects);
    const std::string tmp = path + ".tmp";
    if (!scene.saveToFile(tmp)) throw std::runtime_error(path + ": cannot write the scene");
    std::filesystem::rename(tmp, path);
  }
  /// Saves the map as `prefix + extension` (see SaveToFile).
  void saveMetricMapRepresentationToFile(const std::string& prefix) const override {
    SaveToFile(prefix + extension_);
  }

 protected:
  ViewMapAdapter(const Options& options, const char* name, const char* extension)
      : map_(std::make_unique<Map>(options)), name_(name), extension_(extension) {}

  /// Replaces this map by the `Derived` map in `path`; throws std::runtime_error naming the file,
  /// leaving this map unchanged.
  template <class Derived>
  void LoadAs(const std::string& path) {
    RegisterMaps();  // the archive names the class
    Derived loaded;  // a fresh map: on failure this one is untouched
    LoadInto(loaded, path, name_);
    ReplaceMap(std::move(static_cast<ViewMapAdapter&>(loaded).map_));
  }
  void ReplaceMap(std::unique_ptr<Map> map) {
    map_ = std::move(map);
    last_ = {};
    frame_ = {};
  }

  std::unique_ptr<Map> map_;
  Products last_;
  ObservedFrame frame_;
  DepthSourceOptions depth_source_;

 private:
  void internal_clear() override { ReplaceMap(std::make_unique<Map>(map_->options())); }
  bool internal_insertObservation(
      const mrpt::obs::CObservation& obs,
      const std::optional<const mrpt::poses::CPose3D>& robot_pose = std::nullopt) override {
    ObservedFrame f;
    try {
      if (!DecodeObservation(obs, robot_pose, f) &&
          !DecodeWithDepthSource(obs, robot_pose, depth_source_, f))
        return false;
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string(name_) + ": " + e.what());
    }
    InsertFrame(f.rgb, f.depth, f.camera, f.T_world_cam);
    return true;
  }
  double internal_computeObservationLikelihood(const mrpt::obs::CObservation&,
                                               const mrpt::poses::CPose3D&) const override {
    return 0.0;  // surprise is the product, not a likelihood for localization
  }
  bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation&) const override {
    return false;
  }

  const char* name_;
  const char* extension_;
};

}  // namespace novelty::mrpt_plugins
