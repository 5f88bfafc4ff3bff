// A simulated experiment: the room and its furniture and objects, the lamps, the camera rig and
// where it is carried (a Pioneer 3-DX on a trajectory, or a fixed tripod), and the events that
// change the scene (objects added, removed or moved by a person's arm; lamps moved or switched).
// Parsed from the human-readable scenario files in share/scenarios (scenario_parser.h documents
// the format); errors there name the file, the line and the problem.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/pinhole_camera.h"
#include "sim/render/lighting.h"
#include "sim/render/material.h"
#include "sim/render/renderer.h"
#include "sim/world/trajectory.h"

namespace novelty::sim {

enum class RigKind {
  kMono,        ///< one camera → CObservationImage
  kStereo,      ///< two cameras `baseline` apart → CObservationStereoImages
  kTrinocular,  ///< three cameras on one bar, `baseline` between neighbours (Bumblebee XB3:
                ///< 0.12 m) → three CObservationImage (labels CAM_LEFT, CAM_CENTER, CAM_RIGHT)
  kRgbd,        ///< colour + depth → CObservation3DRangeScan
};

struct RigSpec {
  RigKind kind = RigKind::kRgbd;
  double baseline = 0.12;
};

enum class Shape { kBox, kCylinder, kSphere, kCup, kPlate, kPlane };

struct ObjectSpec {
  std::string name;
  int id = 0;  ///< object id in the id image (1, 2, … in declaration order)
  Shape shape = Shape::kBox;
  Eigen::Vector3d dims{0.1, 0.1,
                       0.1};  ///< box: x y z; cylinder/cup: r h; sphere/plate: r; plane: x y
  std::string material;
  Eigen::Vector2d xy{0, 0};  ///< position on its support
  double yaw = 0.0;          ///< rad
  std::string support;       ///< "floor" or the name of the object it stands on
  bool fixed = false;        ///< furniture: collides, never moves
  bool present = true;       ///< present at the start (else added by an event)
  double mass = 0.3;         ///< kg, for dynamic objects
  int line = 0;              ///< where it was declared
};

struct LampSpec {
  std::string name;
  PointLight light;
  bool on = true;
};

struct EventSpec {
  enum class Kind { kAdd, kRemove, kMove, kLampMove, kLampOn, kLampOff, kWalk, kSun, kExposure };
  Kind kind = Kind::kAdd;
  double time = 0.0;                  ///< seconds from the start
  std::string target;                 ///< object or lamp name (none for sun and exposure)
  Eigen::Vector3d position{0, 0, 0};  ///< move, walk: new x y (on the same support); lamp: x y z;
                                      ///< sun: the daylight's new direction of travel
  double arm_duration = 0.0;  ///< > 0: a person's arm reaches in over this many seconds and the
                              ///< change happens at its midpoint
  double duration = 0.0;      ///< walk, sun, exposure: seconds over which the change is linear
  double value = 0.0;         ///< exposure: the new exposure
  int line = 0;
};

struct PhaseSpec {
  std::string name;
  int first_frame = 0, last_frame = 0;  ///< inclusive, 1-based like the thesis's table 4.1
  std::string description;
};

/// Where the camera head sits on the robot base: x y z (m), yaw (left positive) and pitch
/// (down positive) in rad.
struct MountSpec {
  Eigen::Vector3d position{0.0, 0.0, 1.10};
  double yaw = M_PI / 2;
  double pitch = 0.35;
};

struct Scenario {
  std::string name;
  std::string file;  ///< where it was read from
  int frames = 100;
  double fps = 7.0;
  std::uint64_t seed = 1;
  core::PinholeCamera camera = core::PinholeCamera::FromFov(320, 240, 60.0 * M_PI / 180.0);
  RigSpec rig;
  RenderOptions render;
  MountSpec mount;
  std::optional<Eigen::Isometry3d> static_camera;  ///< set: a tripod, no robot
  Eigen::Vector3d room{6.0, 6.0, 2.8};             ///< walls around the origin, x y height
  std::optional<Eigen::Vector4d> window;           ///< on the +y wall: x centre, z centre, w, h
  Lighting lighting;                               ///< ambient + daylight
  std::map<std::string, Material> materials;
  std::vector<ObjectSpec> objects;
  std::vector<LampSpec> lamps;
  std::vector<EventSpec> events;
  std::vector<PhaseSpec> phases;
  Trajectory trajectory;
  Eigen::Vector2d start_offset{0, 0};  ///< robot start error against the trajectory (m)

  const ObjectSpec* FindObject(const std::string& name) const;
  double Duration() const { return frames / fps; }
};

}  // namespace novelty::sim
