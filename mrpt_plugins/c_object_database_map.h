// CObjectDatabaseMap: the object database of thesis ch. 5 (maps/objects/object_acquisition.h) as
// an MRPT metric map — where the appearance map is surprised, it learns the new object's features
// on its own, and recognises learnt objects later, in this room or another.
//
// - Declared in a CMultiMetricMap .ini beside a CAppearanceMap ("CObjectDatabaseMap_count = 1",
//   options in "<prefix>_options" with the keys of share/object_database.ini; unknown keys are
//   errors). The appearance map hands it each frame it inserts, with that frame's products
//   (surprise, expected depth): link them with LinkObjectDatabaseMaps(multimap) after the
//   multimap's maps are made (and again whenever they are remade), or linkAppearanceMap. The
//   order of the maps in the multimap does not matter.
// - The frame is used as the appearance map inserts it; insertObservation itself takes nothing
//   (it returns false, and throws std::logic_error while the map is not linked). lastStep()
//   holds the last used frame's focus of attention, added/removed decision, features and
//   recognition; framesUsed() counts them.
// - With depth_of_room_at_start, added/removed and the nearer tests (learn_only_nearer_features,
//   nearer_is_surprising, grow_focus_over_nearer) compare with the depth the appearance map's
//   views hold now together with what they held at the first frame this map used — the first
//   after setPaused(false), that frame's own depth included (maps/appearance/room_depth.h). Let
//   the appearance map learn the room first (setPaused, novelty-run --objects-from): what is not
//   in its views then is not in the room, and without that pass the room is one frame. The room
//   is taken again after this map is cleared, loaded or linked to another appearance map, and
//   after that map is cleared or loaded.
// - MRPT serialization saves the options and the database (descriptors, counts n_{h,k}, 3-D
//   places, where each object was learnt); not the active features of an object being learnt, nor
//   the room's depth (taken again at the first frame after a load, objects in view included).
//   SaveToFile writes atomically; LoadFromFile leaves the map as it was when the file is truncated,
//   of another class, or holds descriptors of another extractor.
// - getVisualizationInto draws each object's features at their 3-D places, one colour per object,
//   with its name; asString lists objects, feature counts and where they were learnt.
#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/system/COutputLogger.h>

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "maps/appearance/room_depth.h"
#include "maps/objects/object_acquisition.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/object_database_map_options.h"

namespace novelty::mrpt_plugins {

class CObjectDatabaseMap : public mrpt::maps::CMetricMap,
                           public mrpt::system::COutputLogger,
                           public AppearanceFrameConsumer {
  DEFINE_SERIALIZABLE(CObjectDatabaseMap, novelty::mrpt_plugins)

 public:
  explicit CObjectDatabaseMap(const ObjectDatabaseMapConfig& config = {});
  ~CObjectDatabaseMap() override;
  CObjectDatabaseMap(const CObjectDatabaseMap&) = delete;
  CObjectDatabaseMap& operator=(const CObjectDatabaseMap&) = delete;

  /// Takes the frames and products `appearance` inserts from now on (instead of those of the map
  /// it was linked to), and asks it for its expected depth.
  void linkAppearanceMap(const std::shared_ptr<CAppearanceMap>& appearance);
  /// Uses the frame `appearance` just inserted unless paused (AppearanceFrameConsumer).
  void ConsumeAppearanceFrame(const CAppearanceMap& appearance) override;

  bool isEmpty() const override { return database().features() == 0; }
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;

  /// The last used frame's step (empty before the first).
  const objects::AcquisitionStep& lastStep() const { return last_; }
  const objects::FeatureDatabase& database() const { return acquisition_->learner().database(); }
  /// For tools that build or edit a database themselves (a baseline's, a merge); objects added
  /// here have no place they were learnt from (NaN in learntAt()).
  objects::FeatureDatabase& database() { return acquisition_->learner().database(); }
  const objects::ObjectAcquisition& acquisition() const { return *acquisition_; }
  const ObjectDatabaseMapConfig& config() const { return config_; }
  /// Per object, the camera position (world) of the frame that gave it its class; NaN unknown.
  std::vector<Eigen::Vector3d> learntAt() const;
  /// Frames used (handed by the appearance map while not paused).
  int framesUsed() const { return frames_used_; }
  /// With depth_of_room_at_start: the views of the room's depth as taken; -1 while none is.
  int roomViews() const { return room_ ? room_->views() : -1; }
  /// While paused, observations are not used (insertObservation returns false): the appearance
  /// map learns the room first, as in the thesis's sequence I1, and surprise at sensor noise in a
  /// map still being built teaches no object. Not saved with the map.
  void setPaused(bool paused) { paused_ = paused; }
  bool paused() const { return paused_; }

  void SaveToFile(const std::string& path) const;
  /// Replaces this map by the CObjectDatabaseMap in `path`; throws std::runtime_error naming the
  /// file and leaves this map as it was.
  void LoadFromFile(const std::string& path);
  /// Saves the map as `prefix` + ".object_database".
  void saveMetricMapRepresentationToFile(const std::string& prefix) const override;

  MAP_DEFINITION_START(CObjectDatabaseMap)
  ObjectDatabaseMapConfig config;  ///< from the section "<prefix>_options"
  MAP_DEFINITION_END(CObjectDatabaseMap)

 private:
  void internal_clear() override;
  cv::Mat ExpectedDepthWithRoom(const CAppearanceMap& appearance);
  bool internal_insertObservation(
      const mrpt::obs::CObservation& obs,
      const std::optional<const mrpt::poses::CPose3D>& robot_pose = std::nullopt) override;
  double internal_computeObservationLikelihood(const mrpt::obs::CObservation&,
                                               const mrpt::poses::CPose3D&) const override {
    return 0.0;  // recognition is the product, not a likelihood for localization
  }
  bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation&) const override {
    return false;
  }

  ObjectDatabaseMapConfig config_;
  std::unique_ptr<objects::ObjectAcquisition> acquisition_;
  std::vector<Eigen::Vector3d> learnt_at_;
  objects::AcquisitionStep last_;
  std::weak_ptr<CAppearanceMap> appearance_;
  // With depth_of_room_at_start: the appearance map's views at the first frame used since this
  // map was made, cleared, loaded or linked to another appearance map, or since that one was
  // loaded or cleared (its mapsReplaced() then); not saved.
  std::unique_ptr<appearance::RoomDepth> room_;
  long room_maps_replaced_ = 0;
  int frames_used_ = 0;
  bool paused_ = false;
};

/// Links every CObjectDatabaseMap in `maps` to the first CAppearanceMap there, wherever each
/// stands in the list. Throws std::invalid_argument if there is an object database but no
/// appearance map.
void LinkObjectDatabaseMaps(mrpt::maps::CMultiMetricMap& maps);

}  // namespace novelty::mrpt_plugins
