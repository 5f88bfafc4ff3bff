#include "sim/scenario/scenario_world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace novelty::sim {

namespace {

constexpr double kDropHeight = 0.002;  // dynamic objects start this far above their support

Eigen::Isometry3d Translation(const Eigen::Vector3d& t) {
  return Eigen::Isometry3d(Eigen::Translation3d(t));
}

double Height(const ObjectSpec& o) {
  switch (o.shape) {
    case Shape::kBox:
      return o.dims.z();
    case Shape::kCylinder:
    case Shape::kCup:
      return o.dims.y();
    case Shape::kSphere:
      return 2.0 * o.dims.x();
    case Shape::kPlate:
      return 0.01;
    case Shape::kPlane:
      return 0.001;
  }
  return 0.0;
}

TriangleMesh MeshOf(const ObjectSpec& o) {
  switch (o.shape) {
    case Shape::kBox:
      return MakeBox(o.dims);
    case Shape::kCylinder:
      return MakeCylinder(o.dims.x(), o.dims.y());
    case Shape::kCup:
      return MakeCup(o.dims.x(), o.dims.y());
    case Shape::kSphere:
      return MakeSphere(o.dims.x());
    case Shape::kPlate:
      return MakePlate(o.dims.x());
    case Shape::kPlane:
      return MakePlane(o.dims.x(), o.dims.y());
  }
  return {};
}

Material MaterialOr(const Scenario& s, const std::string& name, const Eigen::Vector3f& colour) {
  const auto it = s.materials.find(name);
  if (it != s.materials.end()) return it->second;
  Material m;
  m.diffuse = colour;
  return m;
}

// Rotation of the camera head on the robot base: looking along base +x, then yaw (left) and
// pitch (down). Camera axes: +Z forward, +X right, +Y down.
Eigen::Matrix3d HeadRotation(double yaw, double pitch) {
  Eigen::Matrix3d looking_forward;
  looking_forward.col(0) = -Eigen::Vector3d::UnitY();
  looking_forward.col(1) = -Eigen::Vector3d::UnitZ();
  looking_forward.col(2) = Eigen::Vector3d::UnitX();
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
         Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()).toRotationMatrix() * looking_forward;
}

}  // namespace

ScenarioWorld::ScenarioWorld(const Scenario& scenario, double settle_seconds) : s_(scenario) {
  physics_ = std::make_unique<PhysicsWorld>();
  BuildRoom();
  BuildObjects();
  lamps_ = s_.lamps;
  const Eigen::Vector3d sun = s_.lighting.directional.empty()
                                  ? Eigen::Vector3d(0, 0, -1)
                                  : s_.lighting.directional[0].direction;
  sun_ = {sun, sun};
  exposure_ = {s_.render.exposure, s_.render.exposure};
  event_done_.assign(s_.events.size(), false);
  if (!s_.static_camera) {
    const TrajectoryReference start = s_.trajectory.At(0.0);
    robot_ = std::make_unique<Pioneer3dx>(*physics_, start.x + s_.start_offset.x(),
                                          start.y + s_.start_offset.y(), start.heading);
  }
  const int settle_steps = static_cast<int>(settle_seconds / physics_->options().time_step);
  for (int i = 0; i < settle_steps; ++i) {
    if (robot_) {
      robot_->Command(0.0, 0.0);
      robot_->Step();
    } else {
      physics_->Step();
    }
  }
  for (ObjectState& o : objects_) {
    if (o.body) o.pose = PhysicsWorld::PoseOf(o.body);
  }
}

ScenarioWorld::~ScenarioWorld() = default;

void ScenarioWorld::BuildRoom() {
  const Eigen::Vector3d r = s_.room;
  const Material floor = MaterialOr(s_, "floor", {0.45f, 0.40f, 0.35f});
  const Material wall = MaterialOr(s_, "wall", {0.80f, 0.80f, 0.78f});
  const Material ceiling = MaterialOr(s_, "ceiling", {0.90f, 0.90f, 0.90f});
  room_.push_back({MakePlane(r.x(), r.y()), floor});
  Eigen::Isometry3d up_side_down = Translation({0, 0, r.z()});
  up_side_down.rotate(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  room_.push_back({MakePlane(r.x(), r.y()).Transformed(up_side_down), ceiling});
  auto add_wall = [&](const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    if ((hi - lo).minCoeff() <= 1e-6) return;
    const Eigen::Isometry3d pose = Translation(0.5 * (lo + hi));
    room_.push_back({MakeBox(hi - lo).Transformed(pose), wall});
    physics_->AddStaticBox(pose, hi - lo);
  };
  const double t = 0.1, hx = r.x() / 2, hy = r.y() / 2, h = r.z();
  add_wall({hx, -hy, 0}, {hx + t, hy, h});
  add_wall({-hx - t, -hy, 0}, {-hx, hy, h});
  add_wall({-hx, -hy - t, 0}, {hx, -hy, h});
  if (!s_.window) {
    add_wall({-hx, hy, 0}, {hx, hy + t, h});
    return;
  }
  const Eigen::Vector4d w = *s_.window;  // x centre, z centre, width, height
  const double x0 = w[0] - w[2] / 2, x1 = w[0] + w[2] / 2, z0 = w[1] - w[3] / 2,
               z1 = w[1] + w[3] / 2;
  add_wall({-hx, hy, 0}, {x0, hy + t, h});
  add_wall({x1, hy, 0}, {hx, hy + t, h});
  add_wall({x0, hy, 0}, {x1, hy + t, z0});
  add_wall({x0, hy, z1}, {x1, hy + t, h});
}

double ScenarioWorld::SupportTop(const std::string& support) const {
  if (support == "floor") return 0.0;
  const ObjectSpec* o = s_.FindObject(support);
  if (!o) throw std::runtime_error(s_.file + ": unknown support '" + support + "'");
  return SupportTop(o->support) + Height(*o);
}

Eigen::Isometry3d ScenarioWorld::PlacementPose(const ObjectSpec& o,
                                               const Eigen::Vector2d& xy) const {
  const double drop = (o.fixed || o.shape == Shape::kPlane) ? 0.0 : kDropHeight;
  Eigen::Isometry3d pose =
      Translation({xy.x(), xy.y(), SupportTop(o.support) + Height(o) / 2 + drop});
  pose.rotate(Eigen::AngleAxisd(o.yaw, Eigen::Vector3d::UnitZ()));
  return pose;
}

void ScenarioWorld::Spawn(ObjectState& o, const Eigen::Isometry3d& pose) {
  const ObjectSpec& spec = *o.spec;
  o.pose = pose;
  o.present = true;
  const bool dynamic = !spec.fixed && spec.shape != Shape::kPlane;
  const double radius = spec.dims.x(), height = Height(spec);
  if (spec.shape == Shape::kBox) {
    if (dynamic)
      o.body = physics_->AddBox(pose, spec.dims, spec.mass);
    else
      physics_->AddStaticBox(pose, spec.dims);
  } else if (spec.shape != Shape::kPlane) {
    // Round shapes collide as upright cylinders (a sphere would roll off the table).
    if (dynamic)
      o.body = physics_->AddCylinder(pose, radius, height, spec.mass);
    else
      physics_->AddStaticBox(pose, {2 * radius, 2 * radius, height});
  }
}

void ScenarioWorld::Despawn(ObjectState& o) {
  if (o.body) {
    o.pose = PhysicsWorld::PoseOf(o.body);
    physics_->RemoveBody(o.body);
    o.body = nullptr;
  }
  o.present = false;
}

void ScenarioWorld::BuildObjects() {
  objects_.reserve(s_.objects.size());
  for (const ObjectSpec& spec : s_.objects) {
    ObjectState o{&spec,        MeshOf(spec), nullptr,      PlacementPose(spec, spec.xy),
                  std::nullopt, false,        spec.present, false,
                  std::nullopt};
    if (spec.present) Spawn(o, o.pose);
    objects_.push_back(std::move(o));
  }
}

const ScenarioWorld::ObjectState& ScenarioWorld::Object(const std::string& name) const {
  for (const ObjectState& o : objects_) {
    if (o.spec->name == name) return o;
  }
  throw std::runtime_error(s_.file + ": no object '" + name + "'");
}

ScenarioWorld::ObjectState& ScenarioWorld::Object(const std::string& name) {
  return const_cast<ObjectState&>(std::as_const(*this).Object(name));
}

bool ScenarioWorld::IsPresent(const std::string& name) const {
  return Object(name).present;
}

Eigen::Isometry3d ScenarioWorld::ObjectPose(const std::string& name) const {
  const ObjectState& o = Object(name);
  return o.body ? PhysicsWorld::PoseOf(o.body) : o.pose;
}

void ScenarioWorld::Apply(const EventSpec& e) {
  static const char* kNames[] = {"add",      "remove", "move", "lamp",    "lamp_on",
                                 "lamp_off", "walk",   "sun",  "exposure"};
  applied_.push_back(std::to_string(time_) + " " + kNames[int(e.kind)] + " " + e.target);
  auto lamp = [&]() -> LampSpec& {
    for (LampSpec& l : lamps_) {
      if (l.name == e.target) return l;
    }
    throw std::runtime_error(s_.file + ": no lamp '" + e.target + "'");
  };
  switch (e.kind) {
    case EventSpec::Kind::kAdd: {
      ObjectState& o = Object(e.target);
      if (!o.present) Spawn(o, PlacementPose(*o.spec, o.spec->xy));
      o.gone_pose.reset();
      break;
    }
    case EventSpec::Kind::kRemove: {
      ObjectState& o = Object(e.target);
      if (!o.present) break;
      Despawn(o);  // leaves o.pose at the last pose
      o.walk.reset();
      o.gone_pose = o.pose;
      break;
    }
    case EventSpec::Kind::kMove: {
      ObjectState& o = Object(e.target);
      if (o.present) {
        Despawn(o);
        o.gone_pose = o.pose;
      }
      o.walk.reset();
      Spawn(o, PlacementPose(*o.spec, e.position.head<2>()));
      o.moved = true;
      break;
    }
    case EventSpec::Kind::kLampMove:
      lamp().light.position = e.position;
      break;
    case EventSpec::Kind::kLampOn:
      lamp().on = true;
      break;
    case EventSpec::Kind::kLampOff:
      lamp().on = false;
      break;
    case EventSpec::Kind::kWalk:
      StartWalk(Object(e.target), e);
      break;
    case EventSpec::Kind::kSun:
      sun_ = {sun_.At(time_), e.position, time_, e.duration};
      break;
    case EventSpec::Kind::kExposure:
      exposure_ = {exposure_.At(time_), e.value, time_, e.duration};
      break;
  }
}

// The walker leaves physics (a person is not pushed by what it passes) and slides at its
// support's height; an object there from the start counts as moved, its old place as removed.
void ScenarioWorld::StartWalk(ObjectState& o, const EventSpec& e) {
  if (!o.present) return;
  if (o.body) {
    o.pose = PhysicsWorld::PoseOf(o.body);
    physics_->RemoveBody(o.body);
    o.body = nullptr;
  }
  if (o.present_at_start && !o.moved) {
    o.gone_pose = o.pose;
    o.moved = true;
  }
  o.pose.translation().z() = SupportTop(o.spec->support) + Height(*o.spec) / 2;
  o.walk = LinearRamp<Eigen::Vector2d>{o.pose.translation().head<2>(), e.position.head<2>(), time_,
                                       e.duration};
}

void ScenarioWorld::StepWalks() {
  for (ObjectState& o : objects_) {
    if (!o.walk) continue;
    o.pose.translation().head<2>() = o.walk->At(time_);
    if (o.walk->Done(time_)) o.walk.reset();
  }
}

void ScenarioWorld::StepOnce() {
  if (robot_) {
    const TrajectoryReference ref = s_.trajectory.At(time_);
    const Odometry& odo = robot_->odometry();
    const Eigen::Vector2d cmd = TrackReference(ref, {odo.x, odo.y, odo.phi});
    robot_->Command(cmd.x(), cmd.y());
    robot_->Step();
  } else {
    physics_->Step();
  }
  time_ += physics_->options().time_step;
}

void ScenarioWorld::AdvanceTo(double t) {
  while (time_ < t - 1e-9) {
    for (std::size_t i = 0; i < s_.events.size(); ++i) {
      const EventSpec& e = s_.events[i];
      if (event_done_[i] || time_ < e.time) continue;
      if (e.arm_duration > 0.0) {
        const bool started = std::any_of(arms_.begin(), arms_.end(),
                                         [&](const ArmMotion& a) { return a.event == &e; });
        if (!started) {
          // The arm reaches in from the image's left, horizontally, to the object's place.
          const ObjectState& o = Object(e.target);
          const Eigen::Vector2d xy = e.kind == EventSpec::Kind::kMove ? e.position.head<2>()
                                     : e.kind == EventSpec::Kind::kAdd
                                         ? o.spec->xy
                                         : Eigen::Vector2d(o.pose.translation().head<2>());
          Eigen::Vector3d left = -(HeadPose().linear() * Eigen::Vector3d::UnitX());
          left.z() = 0.0;
          const double top = SupportTop(o.spec->support) + Height(*o.spec);
          arms_.push_back({&e, Eigen::Vector3d(xy.x(), xy.y(), top + 0.06), left.normalized()});
        }
        if (time_ < e.time + e.arm_duration / 2) continue;  // the hand has not arrived yet
      }
      Apply(e);
      event_done_[i] = true;
    }
    arms_.erase(std::remove_if(arms_.begin(), arms_.end(),
                               [&](const ArmMotion& a) {
                                 return time_ > a.event->time + a.event->arm_duration;
                               }),
                arms_.end());
    StepOnce();
    StepWalks();
  }
}

Eigen::Isometry3d ScenarioWorld::RobotFromHead() const {
  if (s_.static_camera) return *s_.static_camera;
  Eigen::Isometry3d base_from_head = Translation(s_.mount.position);
  base_from_head.linear() = HeadRotation(s_.mount.yaw, s_.mount.pitch);
  return base_from_head;
}

Eigen::Isometry3d ScenarioWorld::HeadPose() const {
  if (s_.static_camera) return *s_.static_camera;
  return robot_->TruePose() * RobotFromHead();
}

std::vector<Eigen::Isometry3d> ScenarioWorld::RigOffsets() const {
  const double b = s_.rig.baseline;
  switch (s_.rig.kind) {
    case RigKind::kMono:
    case RigKind::kRgbd:
      return {Eigen::Isometry3d::Identity()};
    case RigKind::kStereo:
      return {Eigen::Isometry3d::Identity(), Translation({b, 0, 0})};
    case RigKind::kTrinocular:
      return {Eigen::Isometry3d::Identity(), Translation({-b, 0, 0}), Translation({b, 0, 0})};
  }
  return {};
}

std::optional<TriangleMesh> ScenarioWorld::ArmMesh() const {
  if (arms_.empty()) return std::nullopt;
  TriangleMesh arm;
  for (const ArmMotion& a : arms_) {
    const double phase = std::clamp((time_ - a.event->time) / a.event->arm_duration, 0.0, 1.0);
    const double reach = std::sin(M_PI * phase);  // 0 → 1 (at the object) → 0
    const Eigen::Vector3d hand = a.target + (1.0 - reach) * 0.9 * a.direction;
    arm.Append(MakeSphere(0.045, 24, 12).Transformed(Translation(hand)));
    Eigen::Isometry3d forearm = Translation(hand + 0.30 * a.direction);
    forearm.rotate(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), a.direction));
    arm.Append(MakeCylinder(0.04, 0.55, 24).Transformed(forearm));
  }
  return arm;
}

void ScenarioWorld::AddToScene(RayScene& scene, bool with_arm) const {
  for (const auto& [mesh, material] : room_) {
    scene.AddObject(mesh, Eigen::Isometry3d::Identity(), material, kRoomObjectId);
  }
  for (const ObjectState& o : objects_) {
    if (!o.present) continue;
    const Eigen::Isometry3d pose = o.body ? PhysicsWorld::PoseOf(o.body) : o.pose;
    scene.AddObject(o.mesh, pose, s_.materials.at(o.spec->material), o.spec->id);
  }
  if (const auto arm = with_arm ? ArmMesh() : std::nullopt) {
    scene.AddObject(*arm, Eigen::Isometry3d::Identity(),
                    MaterialOr(s_, "skin", {0.85f, 0.62f, 0.50f}), kArmObjectId);
  }
}

void ScenarioWorld::AddNoveltyReferenceToScene(RayScene& scene) const {
  AddToScene(scene, false);
  for (const ObjectState& o : objects_) {
    if (o.gone_pose) {
      scene.AddObject(o.mesh, *o.gone_pose, s_.materials.at(o.spec->material), o.spec->id);
    }
  }
}

bool ScenarioWorld::IsForeground(const ObjectState& o) const {
  return o.present && (!o.present_at_start || o.moved);
}

void ScenarioWorld::AddBackgroundToScene(RayScene& scene) const {
  for (const auto& [mesh, material] : room_) {
    scene.AddObject(mesh, Eigen::Isometry3d::Identity(), material, kRoomObjectId);
  }
  for (const ObjectState& o : objects_) {
    if (!o.present || IsForeground(o)) continue;
    const Eigen::Isometry3d pose = o.body ? PhysicsWorld::PoseOf(o.body) : o.pose;
    scene.AddObject(o.mesh, pose, s_.materials.at(o.spec->material), o.spec->id);
  }
}

Lighting ScenarioWorld::CurrentLighting() const {
  Lighting l = s_.lighting;
  if (!l.directional.empty()) l.directional[0].direction = sun_.At(time_).normalized();
  for (const LampSpec& lamp : lamps_) {
    if (lamp.on) l.points.push_back(lamp.light);
  }
  return l;
}

std::vector<int> ScenarioWorld::AddedIds() const {
  std::vector<int> ids;
  for (const ObjectState& o : objects_) {
    if (IsForeground(o)) ids.push_back(o.spec->id);
  }
  if (!arms_.empty()) ids.push_back(kArmObjectId);
  return ids;
}

std::vector<int> ScenarioWorld::RemovedIds() const {
  std::vector<int> ids;
  for (const ObjectState& o : objects_) {
    if (o.gone_pose) ids.push_back(o.spec->id);
  }
  return ids;
}

}  // namespace novelty::sim
