// A scenario brought to life: the ODE world with the room, furniture, objects and the robot on
// its trajectory; events applied at their times (objects added, removed, moved — by a person's
// arm when asked — lamps moved or switched); the camera rig's true poses; and the renderable
// scene, now and in the reference configuration of the start (for ground-truth novelty masks).
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "sim/render/ray_scene.h"
#include "sim/scenario/scenario.h"
#include "sim/world/physics_world.h"
#include "sim/world/pioneer3dx.h"

namespace novelty::sim {

/// Object id of the person's arm in id images and novelty masks; room structure is 0.
inline constexpr int kArmObjectId = 1000;
inline constexpr int kRoomObjectId = 0;

/// A value changing linearly from `from` at `start` to `to` over `duration` seconds (walks, the
/// sun, the exposure).
template <class T>
struct LinearRamp {
  T from, to;
  double start = 0.0, duration = 0.0;
  T At(double t) const {
    const double a = duration > 0 ? std::clamp((t - start) / duration, 0.0, 1.0) : 1.0;
    return T(from + a * (to - from));
  }
  bool Done(double t) const { return t >= start + duration; }
};

class ScenarioWorld {
 public:
  /// Builds the world and lets the initial objects settle for `settle_seconds` (physics only).
  explicit ScenarioWorld(const Scenario& scenario, double settle_seconds = 1.0);
  ~ScenarioWorld();

  /// Runs physics, the robot controller and the events up to time t (seconds, ≥ the current).
  void AdvanceTo(double t);
  double time() const { return time_; }

  /// True pose of the camera head (the rig's reference camera): T_world_cam.
  Eigen::Isometry3d HeadPose() const;
  /// Where the camera head is on the robot (T_base_head), or T_world_head for a tripod: the
  /// nominal sensor pose written into the rawlog.
  Eigen::Isometry3d RobotFromHead() const;
  /// T_head_cam of each rig camera, reference camera first (see RigKind).
  std::vector<Eigen::Isometry3d> RigOffsets() const;
  /// The robot (nullptr for a static camera).
  const Pioneer3dx* robot() const { return robot_.get(); }

  /// Whether an object is in the scene now, and its current pose (throws for unknown names).
  bool IsPresent(const std::string& name) const;
  Eigen::Isometry3d ObjectPose(const std::string& name) const;

  /// Adds everything visible now to `scene` (not committed); the person's arm only if
  /// `with_arm`.
  void AddToScene(RayScene& scene, bool with_arm = true) const;
  /// The reference for novelty masks: the scene now without the arm, plus every removed object
  /// at the pose where it was last seen and every moved object at its old place.
  void AddNoveltyReferenceToScene(RayScene& scene) const;
  /// The scene now without its foreground: no arm, no object added since the start, no moved
  /// object at its new place (what a fixed camera's background is; shadow ground truth).
  void AddBackgroundToScene(RayScene& scene) const;
  /// Lamps and the daylight as they are now.
  Lighting CurrentLighting() const;
  /// The camera's exposure now (the scenario's, changed by exposure events).
  double CurrentExposure() const { return exposure_.At(time_); }

  /// Ids of changes: added (present now but not at the start, or moved, or the arm) and removed
  /// (taken away or moved since they were last seen, whenever that was).
  std::vector<int> AddedIds() const;
  std::vector<int> RemovedIds() const;
  /// Events applied so far, as "time kind target" strings for the ground-truth event table.
  const std::vector<std::string>& applied_events() const { return applied_; }

 private:
  struct ObjectState {
    const ObjectSpec* spec;
    TriangleMesh mesh;
    dBodyID body = nullptr;
    Eigen::Isometry3d pose;  // current (fixed objects and absent ones keep theirs)
    std::optional<Eigen::Isometry3d> gone_pose;  // where it was before a remove or move
    bool present;
    bool present_at_start;
    bool moved = false;
    std::optional<LinearRamp<Eigen::Vector2d>> walk;  // sliding on its support, no physics body
  };
  struct ArmMotion {
    const EventSpec* event;
    Eigen::Vector3d target, direction;
  };

  void BuildRoom();
  void BuildObjects();
  double SupportTop(const std::string& support) const;
  Eigen::Isometry3d PlacementPose(const ObjectSpec& o, const Eigen::Vector2d& xy) const;
  void Spawn(ObjectState& o, const Eigen::Isometry3d& pose);
  void Despawn(ObjectState& o);
  void Apply(const EventSpec& e);
  void StepOnce();
  void StepWalks();
  void StartWalk(ObjectState& o, const EventSpec& e);
  bool IsForeground(const ObjectState& o) const;
  ObjectState& Object(const std::string& name);
  const ObjectState& Object(const std::string& name) const;
  std::optional<TriangleMesh> ArmMesh() const;

  const Scenario& s_;
  std::unique_ptr<PhysicsWorld> physics_;
  std::unique_ptr<Pioneer3dx> robot_;
  std::vector<ObjectState> objects_;
  std::vector<std::pair<TriangleMesh, Material>> room_;
  std::vector<LampSpec> lamps_;
  std::vector<bool> event_done_;
  std::vector<ArmMotion> arms_;
  std::vector<std::string> applied_;
  LinearRamp<Eigen::Vector3d> sun_;
  LinearRamp<double> exposure_;
  double time_ = 0.0;
};

}  // namespace novelty::sim
