// The ODE rigid-body world of the simulator: gravity, a floor, contacts with friction, static
// furniture and dynamic objects that settle by physics. Fixed time step, single-threaded, so a
// run is deterministic. ODE is built with double precision (dDOUBLE) on Debian.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <functional>

namespace novelty::sim {

struct PhysicsOptions {
  double time_step = 0.002;   ///< seconds per ODE step (500 Hz: wheels on a floor stay stable)
  double gravity = 9.81;      ///< m/s²
  double friction = 0.9;      ///< Coulomb μ of rubber/wood contacts
  double contact_erp = 0.2;   ///< error reduction of contacts
  double contact_cfm = 1e-5;  ///< softness of contacts
  int max_contacts = 8;       ///< per touching geometry pair
};

/// What a geometry is made of, for contact friction: casters roll without friction.
enum class Surface { kNormal = 0, kFrictionless = 1 };

class PhysicsWorld {
 public:
  explicit PhysicsWorld(const PhysicsOptions& options = {});
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  dWorldID world() const { return world_; }
  dSpaceID space() const { return space_; }
  const PhysicsOptions& options() const { return options_; }
  double time() const { return time_; }

  /// One step of options().time_step; `before_step` hooks (motor control) run first.
  void Step();
  /// Steps until `seconds` more have passed.
  void Advance(double seconds);
  /// Called before every step with the current time (e.g. a robot's wheel controller).
  void SetBeforeStep(std::function<void(double)> hook) { before_step_ = std::move(hook); }

  /// A fixed box (furniture, walls): collides but never moves.
  dGeomID AddStaticBox(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size);
  /// A dynamic box / upright cylinder of the given total mass at `pose`.
  dBodyID AddBox(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size, double mass);
  dBodyID AddCylinder(const Eigen::Isometry3d& pose, double radius, double height, double mass);
  /// A wheel: a cylinder's mass and inertia with a sphere's contact (one contact point, no
  /// scrubbing of a rim edge when turning; ODE's cylinder-plane contacts make robots veer).
  dBodyID AddWheel(const Eigen::Isometry3d& pose, double radius, double width, double mass);
  /// Removes a dynamic body and its geometries.
  void RemoveBody(dBodyID body);

  static void SetSurface(dGeomID geom, Surface surface);
  static Eigen::Isometry3d PoseOf(dBodyID body);
  static void SetPose(dBodyID body, const Eigen::Isometry3d& pose);

 private:
  static void NearCallback(void* data, dGeomID a, dGeomID b);
  dBodyID AddBody(const dMass& mass, dGeomID geom, const Eigen::Isometry3d& pose);

  PhysicsOptions options_;
  dWorldID world_;
  dSpaceID space_;
  dJointGroupID contacts_;
  double time_ = 0.0;
  std::function<void(double)> before_step_;
};

}  // namespace novelty::sim
