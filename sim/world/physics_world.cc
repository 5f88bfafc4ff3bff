#include "sim/world/physics_world.h"

#include <stdexcept>
#include <vector>

namespace novelty::sim {

namespace {

Surface SurfaceOf(dGeomID g) {
  return static_cast<Surface>(reinterpret_cast<std::intptr_t>(dGeomGetData(g)));
}

void PlaceGeomOrBody(dBodyID body, dGeomID geom, const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const dQuaternion dq = {q.w(), q.x(), q.y(), q.z()};
  const Eigen::Vector3d t = pose.translation();
  if (body) {
    dBodySetPosition(body, t.x(), t.y(), t.z());
    dBodySetQuaternion(body, dq);
  } else {
    dGeomSetPosition(geom, t.x(), t.y(), t.z());
    dGeomSetQuaternion(geom, dq);
  }
}

}  // namespace

PhysicsWorld::PhysicsWorld(const PhysicsOptions& options) : options_(options) {
  if (!(options.time_step > 0.0)) {
    throw std::invalid_argument("PhysicsOptions: time_step must be > 0");
  }
  dInitODE2(0);  // reference-counted by ODE; paired with dCloseODE in the destructor
  world_ = dWorldCreate();
  space_ = dHashSpaceCreate(nullptr);
  contacts_ = dJointGroupCreate(0);
  dWorldSetGravity(world_, 0, 0, -options.gravity);
  dWorldSetERP(world_, 0.2);
  dWorldSetCFM(world_, 1e-6);
  dWorldSetContactSurfaceLayer(world_, 0.0005);
  dCreatePlane(space_, 0, 0, 1, 0);  // the floor z = 0
}

PhysicsWorld::~PhysicsWorld() {
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(space_);
  dWorldDestroy(world_);
  dCloseODE();
}

void PhysicsWorld::NearCallback(void* data, dGeomID a, dGeomID b) {
  auto* self = static_cast<PhysicsWorld*>(data);
  const dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
  if (ba && bb && dAreConnectedExcluding(ba, bb, dJointTypeContact)) return;
  std::vector<dContact> contact(self->options_.max_contacts);
  const int n = dCollide(a, b, int(contact.size()), &contact[0].geom, sizeof(dContact));
  const bool slippery =
      SurfaceOf(a) == Surface::kFrictionless || SurfaceOf(b) == Surface::kFrictionless;
  for (int i = 0; i < n; ++i) {
    dSurfaceParameters& s = contact[i].surface;
    s.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
    s.mu = slippery ? 0.0 : self->options_.friction;
    s.soft_erp = self->options_.contact_erp;
    s.soft_cfm = self->options_.contact_cfm;
    const dJointID j = dJointCreateContact(self->world_, self->contacts_, &contact[i]);
    dJointAttach(j, ba, bb);
  }
}

void PhysicsWorld::Step() {
  if (before_step_) before_step_(time_);
  dSpaceCollide(space_, this, &PhysicsWorld::NearCallback);
  dWorldStep(world_, options_.time_step);
  dJointGroupEmpty(contacts_);
  time_ += options_.time_step;
}

void PhysicsWorld::Advance(double seconds) {
  const double end = time_ + seconds - 0.5 * options_.time_step;
  while (time_ < end) Step();
}

dGeomID PhysicsWorld::AddStaticBox(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size) {
  dGeomID g = dCreateBox(space_, size.x(), size.y(), size.z());
  PlaceGeomOrBody(nullptr, g, pose);
  return g;
}

dBodyID PhysicsWorld::AddBody(const dMass& mass, dGeomID geom, const Eigen::Isometry3d& pose) {
  dBodyID body = dBodyCreate(world_);
  dBodySetMass(body, &mass);
  dGeomSetBody(geom, body);
  PlaceGeomOrBody(body, nullptr, pose);
  return body;
}

dBodyID PhysicsWorld::AddBox(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size,
                             double mass) {
  dMass m;
  dMassSetBoxTotal(&m, mass, size.x(), size.y(), size.z());
  return AddBody(m, dCreateBox(space_, size.x(), size.y(), size.z()), pose);
}

dBodyID PhysicsWorld::AddCylinder(const Eigen::Isometry3d& pose, double radius, double height,
                                  double mass) {
  dMass m;
  dMassSetCylinderTotal(&m, mass, 3, radius, height);  // axis 3 = z, as dCreateCylinder
  return AddBody(m, dCreateCylinder(space_, radius, height), pose);
}

dBodyID PhysicsWorld::AddWheel(const Eigen::Isometry3d& pose, double radius, double width,
                               double mass) {
  dMass m;
  dMassSetCylinderTotal(&m, mass, 3, radius, width);
  return AddBody(m, dCreateSphere(space_, radius), pose);
}

void PhysicsWorld::RemoveBody(dBodyID body) {
  for (dGeomID g = dBodyGetFirstGeom(body); g; g = dBodyGetFirstGeom(body)) dGeomDestroy(g);
  dBodyDestroy(body);
}

void PhysicsWorld::SetSurface(dGeomID geom, Surface surface) {
  dGeomSetData(geom, reinterpret_cast<void*>(static_cast<std::intptr_t>(surface)));
}

Eigen::Isometry3d PhysicsWorld::PoseOf(dBodyID body) {
  const dReal* p = dBodyGetPosition(body);
  const dReal* q = dBodyGetQuaternion(body);  // w, x, y, z
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  return pose;
}

void PhysicsWorld::SetPose(dBodyID body, const Eigen::Isometry3d& pose) {
  PlaceGeomOrBody(body, nullptr, pose);
  dBodySetLinearVel(body, 0, 0, 0);
  dBodySetAngularVel(body, 0, 0, 0);
}

}  // namespace novelty::sim
