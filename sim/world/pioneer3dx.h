// A Pioneer 3-DX in the ODE world: chassis, two driven wheels on hinge joints with velocity
// motors, a rear caster, and a camera mast. Odometry integrates the wheel rotations with the
// nominal wheel radius and track, so it drifts like the real robot's when wheels slip.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>

#include "sim/world/physics_world.h"

namespace novelty::sim {

/// Dimensions from the Pioneer 3-DX operations manual (MobileRobots, 2006), rounded.
struct Pioneer3dxSpec {
  Eigen::Vector3d body_size{0.455, 0.381, 0.237 - 0.06};  ///< chassis box above the axle (m)
  double body_clearance = 0.06;                           ///< chassis underside above the floor (m)
  double body_mass = 7.0;        ///< kg (9 kg robot minus wheels and caster)
  double body_offset = -0.06;    ///< chassis centre behind the axle (m): the weight rests on
                                 ///< the caster, so the robot cannot tip onto its nose
  double wheel_radius = 0.0975;  ///< 195 mm tyres
  double wheel_width = 0.047;
  double wheel_mass = 0.8;
  double track = 0.33;                 ///< distance between the wheel contact centres (m)
  double caster_radius = 0.04;         ///< rear caster, modelled as a frictionless ball
  double caster_offset = -0.19;        ///< caster position along x from the axle (m)
  double motor_torque = 3.0;           ///< N·m per wheel motor (max force of the velocity motor)
  double max_speed = 1.2;              ///< m/s
  double max_acceleration = 0.5;       ///< m/s² per wheel (the firmware's ramp; avoids wheel spin)
  std::int32_t ticks_per_rev = 78400;  ///< encoder ticks per wheel revolution (~128 ticks/mm)
  /// Relative errors of the constants the odometry integrates with (wheel radii, track), like a
  /// real robot's firmware constants that do not match worn or soft tyres. The simulated wheels
  /// barely slip, so without them odometry would be unrealistically exact.
  double odometry_left_radius_error = 0.004;
  double odometry_right_radius_error = -0.003;
  double odometry_track_error = 0.01;
};

/// Wheel-odometry pose in the plane, as MRPT's CPose2D (x, y, φ) plus encoder totals.
struct Odometry {
  double x = 0.0, y = 0.0, phi = 0.0;
  std::int64_t left_ticks = 0, right_ticks = 0;
  double v = 0.0, w = 0.0;  ///< measured linear (m/s) and angular (rad/s) velocity
};

class Pioneer3dx {
 public:
  /// Places the robot on the floor at (x, y) with heading `phi` (rad).
  Pioneer3dx(PhysicsWorld& world, double x, double y, double phi, const Pioneer3dxSpec& spec = {});

  /// Sets the target body velocities (m/s, rad/s), clamped to max_speed.
  void Command(double v, double w);
  /// Steps the world once: ramps the wheel motors toward the target (max_acceleration), steps
  /// physics, integrates odometry.
  void Step();

  /// True pose of the robot base (world ← base), base frame at the axle centre on the floor.
  Eigen::Isometry3d TruePose() const;
  /// True planar pose (x, y, heading).
  Eigen::Vector3d TruePose2D() const;
  const Odometry& odometry() const { return odometry_; }
  const Pioneer3dxSpec& spec() const { return spec_; }

 private:
  void UpdateOdometry(double dt);

  PhysicsWorld& world_;
  Pioneer3dxSpec spec_;
  dBodyID chassis_, left_wheel_, right_wheel_;
  dJointID left_hinge_, right_hinge_;
  double target_left_ = 0.0, target_right_ = 0.0;  // wheel surface speeds (m/s)
  double applied_left_ = 0.0, applied_right_ = 0.0;
  Odometry odometry_;
  double left_angle_ = 0.0, right_angle_ = 0.0;  // unwrapped wheel angles
};

}  // namespace novelty::sim
