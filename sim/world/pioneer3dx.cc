#include "sim/world/pioneer3dx.h"

#include <algorithm>
#include <cmath>

namespace novelty::sim {

namespace {

Eigen::Isometry3d Pose(double x, double y, double z, const Eigen::Matrix3d& r) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = r;
  t.translation() = Eigen::Vector3d(x, y, z);
  return t;
}

}  // namespace

Pioneer3dx::Pioneer3dx(PhysicsWorld& world, double x, double y, double phi,
                       const Pioneer3dxSpec& spec)
    : world_(world), spec_(spec) {
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d axle(x, y, spec.wheel_radius);
  // Chassis: its box centre sits above the axle; the caster hangs below its rear.
  const double body_z = spec.body_clearance + spec.body_size.z() / 2;
  const Eigen::Vector3d centre =
      Eigen::Vector3d(x, y, body_z) + yaw * Eigen::Vector3d(spec.body_offset, 0, 0);
  chassis_ =
      world.AddBox(Pose(centre.x(), centre.y(), centre.z(), yaw), spec.body_size, spec.body_mass);
  dGeomID caster = dCreateSphere(world.space(), spec.caster_radius);
  dGeomSetBody(caster, chassis_);
  dGeomSetOffsetPosition(caster, spec.caster_offset - spec.body_offset, 0,
                         spec.caster_radius - body_z);
  PhysicsWorld::SetSurface(caster, Surface::kFrictionless);

  // Wheels: cylinders with their axis (local z) along the robot's y axis.
  const Eigen::Matrix3d wheel_rot =
      yaw * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  auto make_wheel = [&](double side, dBodyID& body, dJointID& hinge) {
    const Eigen::Vector3d c = axle + yaw * Eigen::Vector3d(0, side * spec.track / 2, 0);
    body = world.AddWheel(Pose(c.x(), c.y(), c.z(), wheel_rot), spec.wheel_radius, spec.wheel_width,
                          spec.wheel_mass);
    hinge = dJointCreateHinge(world.world(), nullptr);
    dJointAttach(hinge, chassis_, body);
    dJointSetHingeAnchor(hinge, c.x(), c.y(), c.z());
    const Eigen::Vector3d axis = yaw * Eigen::Vector3d::UnitY();
    dJointSetHingeAxis(hinge, axis.x(), axis.y(), axis.z());
    dJointSetHingeParam(hinge, dParamFMax, spec.motor_torque);
    dJointSetHingeParam(hinge, dParamVel, 0.0);
  };
  make_wheel(+1.0, left_wheel_, left_hinge_);
  make_wheel(-1.0, right_wheel_, right_hinge_);
  odometry_.x = x;
  odometry_.y = y;
  odometry_.phi = phi;
}

void Pioneer3dx::Command(double v, double w) {
  const double fastest = std::abs(v) + std::abs(w) * spec_.track / 2;
  const double scale = fastest > spec_.max_speed ? spec_.max_speed / fastest : 1.0;
  target_left_ = scale * (v - w * spec_.track / 2);
  target_right_ = scale * (v + w * spec_.track / 2);
}

void Pioneer3dx::Step() {
  const double dt = world_.options().time_step;
  const double dv = spec_.max_acceleration * dt;
  applied_left_ += std::clamp(target_left_ - applied_left_, -dv, dv);
  applied_right_ += std::clamp(target_right_ - applied_right_, -dv, dv);
  // Hinge axis +y (left). ODE's hinge rate is that of body 1 (the chassis) relative to body 2
  // (the wheel), so a wheel rolling forward (+ω about +y) has a negative hinge rate.
  dJointSetHingeParam(left_hinge_, dParamVel, -applied_left_ / spec_.wheel_radius);
  dJointSetHingeParam(right_hinge_, dParamVel, -applied_right_ / spec_.wheel_radius);
  world_.Step();
  UpdateOdometry(dt);
}

void Pioneer3dx::UpdateOdometry(double dt) {
  // Wheel rotation over the step from the hinge rates (negative = forward, see Step).
  const double dl = -dJointGetHingeAngleRate(left_hinge_) * dt;
  const double dr = -dJointGetHingeAngleRate(right_hinge_) * dt;
  left_angle_ += dl;
  right_angle_ += dr;
  const double sl = dl * spec_.wheel_radius * (1.0 + spec_.odometry_left_radius_error);
  const double sr = dr * spec_.wheel_radius * (1.0 + spec_.odometry_right_radius_error);
  const double ds = 0.5 * (sl + sr);
  const double dphi = (sr - sl) / (spec_.track * (1.0 + spec_.odometry_track_error));
  const double mid = odometry_.phi + 0.5 * dphi;  // midpoint integration of the unicycle
  odometry_.x += ds * std::cos(mid);
  odometry_.y += ds * std::sin(mid);
  odometry_.phi = std::remainder(odometry_.phi + dphi, 2.0 * M_PI);
  odometry_.left_ticks = std::llround(left_angle_ / (2.0 * M_PI) * spec_.ticks_per_rev);
  odometry_.right_ticks = std::llround(right_angle_ / (2.0 * M_PI) * spec_.ticks_per_rev);
  odometry_.v = ds / dt;
  odometry_.w = dphi / dt;
}

Eigen::Isometry3d Pioneer3dx::TruePose() const {
  const Eigen::Isometry3d chassis = PhysicsWorld::PoseOf(chassis_);
  // Base frame: at the axle centre on the floor, x forward, z up.
  const double body_z = spec_.body_clearance + spec_.body_size.z() / 2;
  return chassis * Eigen::Translation3d(-spec_.body_offset, 0, -body_z);
}

Eigen::Vector3d Pioneer3dx::TruePose2D() const {
  const Eigen::Isometry3d p = TruePose();
  const Eigen::Vector3d fwd = p.linear() * Eigen::Vector3d::UnitX();
  return {p.translation().x(), p.translation().y(), std::atan2(fwd.y(), fwd.x())};
}

}  // namespace novelty::sim
