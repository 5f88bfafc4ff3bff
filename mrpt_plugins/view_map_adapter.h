// What CAppearanceMap and CDifferencingMap share as MRPT metric maps: a view-based map from
// maps/appearance inside an mrpt::maps::CMetricMap — RGB-D observations (or stereo pairs, with a
// stereo depth source) in, products of the last frame out, atomic saves, loads that keep the map
// when the file is bad, a .3Dscene of the frusta. Each class adds its serialization, map
// definition and visualization.
#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/COutputLogger.h>

#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mrpt_plugins/cimage_products.h"
#include "mrpt_plugins/depth_source.h"
#include "mrpt_plugins/map_file.h"
#include "mrpt_plugins/observation_frame.h"
#include "mrpt_plugins/pose_check.h"
#include "mrpt_plugins/register_maps.h"
#include "mrpt_plugins/view_archive.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::mrpt_plugins {

// Config: the map's option table (appearance_map_options.h), with the map's options in `map`,
// the depth source in `depth` and the pose checks in `poses`.
//
// Poses: insertObservation(obs, robot_pose) takes the ROBOT's pose; the camera is at
// robot_pose ⊕ obs.sensorPose (MRPT's convention). Poses a robot cannot have (pose_check.h) are
// logged as warnings through MRPT's COutputLogger (the logger is named after the class).
template <class Map, class Config, class Products>
class ViewMapAdapter : public mrpt::maps::CMetricMap, public mrpt::system::COutputLogger {
 public:
  bool isEmpty() const override { return map_->store().size() == 0; }

  /// Inserts a decoded frame directly (what insertObservation does after decoding), for callers
  /// that read frames themselves; T_world_cam is the camera's pose (+Z forward, +Y down), `time`
  /// in seconds for the pose checks (NaN: unknown). Same errors as the map's Insert.
  const Products& InsertFrame(const cv::Mat& rgb, const cv::Mat& depth,
                              const core::PinholeCamera& camera,
                              const Eigen::Isometry3d& T_world_cam,
                              double time = std::numeric_limits<double>::quiet_NaN()) {
    return Insert(rgb, depth, camera, T_world_cam, time, std::nullopt);
  }
  /// Where camera observations without depth get it (default: they are not used).
  void setDepthSource(const DepthSourceOptions& options) { depth_source_ = options; }
  const DepthSourceOptions& depthSource() const { return depth_source_; }
  /// Products of the last inserted frame (empty before the first).
  const Products& lastProducts() const { return last_; }
  /// The last inserted frame as the map saw it: image, depth, camera and T_world_cam (decoded
  /// from the observation, the pose robot ⊕ sensor).
  const core::Frame& lastFrame() const { return frame_; }
  const Map& map() const { return *map_; }
  /// The image the map expected for the last frame (the prior's mean), as an MRPT image.
  mrpt::img::CImage expectedImage() const { return ToCImage(last_.expected_rgb); }
  /// Frames inserted since construction (never reset).
  long framesInserted() const { return frames_inserted_; }
  /// Off: frames inserted are judged (products as ever) but change nothing in the map — built
  /// from one pass, it judges the next as it was. Kept across a load or clear; not saved.
  void setLearning(bool on) {
    learning_ = on;
    map_->view_map().set_learning(on);
  }
  bool learning() const { return learning_; }
  /// Times a load or clear put a new map in place: a map that keeps something taken from this
  /// one (CObjectDatabaseMap's room depth) tells by it that what it took is gone.
  long mapsReplaced() const { return maps_replaced_; }
  /// Frames whose camera pose the pose checks found implausible (each logged as a warning).
  int poseWarnings() const { return pose_check_.warnings(); }

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
  ViewMapAdapter(const Config& config, const char* name, const char* extension)
      : mrpt::system::COutputLogger(name),
        map_(std::make_unique<Map>(config.map)),
        depth_source_(config.depth),
        pose_check_(config.poses),
        name_(name),
        extension_(extension) {}

  /// The options as the map uses them, in one table.
  Config CurrentConfig() const {
    Config c;
    c.map = map_->options();
    c.depth = depth_source_;
    c.poses = pose_check_.options();
    return c;
  }
  /// Map file: every option by key (option_table.h), then the views with their images encoded
  /// (views::EncodedView: rounded, predicted, zstd). Older versions: map_formats.h.
  uint8_t FileVersion() const { return CurrentMapFormat(name_); }
  void WriteMapFile(mrpt::serialization::CArchive& out) const {
    Config::Table().Write(out, CurrentConfig());
    WriteViewMap(out, map_->view_map());
  }
  /// Reads any version this class wrote (map_formats.h says how each is laid out). The map is
  /// replaced only when everything was read.
  void ReadMapFile(mrpt::serialization::CArchive& in, uint8_t version) {
    const MapFormat format = MapFormatOf(name_, version);
    Config c;
    c.depth = depth_source_;  // files before version 2 did not hold it: the map's stays
    c.poses = pose_check_.options();
    if (format.options_by_key)
      Config::Table().Read(in, c);
    else
      Config::Table().ReadPositional(in, format.positional_keys, c);
    auto map = std::make_unique<Map>(c.map);
    try {
      ReadViewMap(in, map->view_map(), format);
      map->CheckStoredPlanes();
    } catch (const std::invalid_argument& e) {  // the content, not the archive, is wrong
      ThrowMapFileError(e.what());
    }
    ReplaceMap(std::move(map));  // only now: a failure above leaves the map as it was
    depth_source_ = c.depth;
    pose_check_ = PoseCheck(c.poses);
  }

  /// Replaces this map by the `Derived` map in `path`; throws std::runtime_error naming the file,
  /// leaving this map unchanged.
  template <class Derived>
  void LoadAs(const std::string& path) {
    RegisterMaps();  // the archive names the class
    Derived loaded;  // a fresh map: on failure this one is untouched
    LoadInto(loaded, path, name_);
    ViewMapAdapter& from = loaded;
    ReplaceMap(std::move(from.map_));
    depth_source_ = from.depth_source_;
    pose_check_ = PoseCheck(from.pose_check_.options());
  }
  void ReplaceMap(std::unique_ptr<Map> map) {
    map_ = std::move(map);
    map_->view_map().set_learning(learning_);
    ++maps_replaced_;
    last_ = {};
    frame_ = {};
    MapReplaced();
  }
  /// After a load or clear put a new map in place: what the derived class set on the old one
  /// that is not an option (not saved) is set again here.
  virtual void MapReplaced() {}
  /// After each inserted frame, its products in lastProducts(): for maps that hand them on.
  virtual void FrameInserted() {}

  std::unique_ptr<Map> map_;
  Products last_;
  core::Frame frame_;
  DepthSourceOptions depth_source_;
  PoseCheck pose_check_;

 private:
  void internal_clear() override {
    ReplaceMap(std::make_unique<Map>(map_->options()));
    pose_check_.Reset();
  }
  const Products& Insert(const cv::Mat& rgb, const cv::Mat& depth,
                         const core::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam,
                         double time, const std::optional<PoseCheck::Mount>& mount) {
    WarnIfImplausible(T_world_cam, time, mount);
    last_ = map_->Insert(rgb, depth, camera, T_world_cam);
    ++frames_inserted_;
    frame_ = core::Frame();
    frame_.rgb = rgb;
    frame_.depth = depth;
    frame_.camera = camera;
    frame_.T_world_cam = T_world_cam;
    FrameInserted();
    return last_;
  }
  // The first three implausible poses, then every hundredth: a wrong convention shows in every
  // frame and must not drown the log.
  void WarnIfImplausible(const Eigen::Isometry3d& T_world_cam, double time,
                         const std::optional<PoseCheck::Mount>& mount) {
    const std::string problem = pose_check_.Check(T_world_cam, time, mount);
    const int n = pose_check_.warnings();
    if (problem.empty() || (n > 3 && n % 100 != 0)) return;
    MRPT_LOG_WARN_FMT(
        "implausible camera pose (%d so far): %s. insertObservation takes the robot's pose; the "
        "camera is at robot_pose + sensorPose (limits: the map's platform, max_speed, "
        "max_tilt_deg, ... options; a hand-held camera: platform = hand-held)",
        n, problem.c_str());
  }
  bool internal_insertObservation(
      const mrpt::obs::CObservation& obs,
      const std::optional<const mrpt::poses::CPose3D>& robot_pose = std::nullopt) override {
    core::Frame f;
    try {
      if (!DecodeObservation(obs, robot_pose, f) &&
          !DecodeWithDepthSource(obs, robot_pose, depth_source_, f))
        return false;
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string(name_) + ": " + e.what());
    }
    mrpt::poses::CPose3D sensor_on_robot;
    obs.getSensorPose(sensor_on_robot);
    const PoseCheck::Mount mount{sensors::ToEigen(robot_pose.value_or(mrpt::poses::CPose3D())),
                                 sensors::ToEigen(sensor_on_robot)};
    Insert(f.rgb, f.depth, f.camera, *f.T_world_cam,
           obs.timestamp == INVALID_TIMESTAMP ? std::numeric_limits<double>::quiet_NaN()
                                              : mrpt::Clock::toDouble(obs.timestamp),
           mount);
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
  long frames_inserted_ = 0;
  bool learning_ = true;
  long maps_replaced_ = 0;
};

}  // namespace novelty::mrpt_plugins
