// Rigid poses in the project's conventions (MRPT's: world x forward, y left, z up; camera +Z
// forward, +X right, +Y down; T_world_cam maps camera coordinates to world coordinates).
#pragma once

#include <Eigen/Geometry>

#include "core/eigen_abi.h"

namespace novelty::core {

/// True if T is a rigid transform (orthonormal rotation with det +1, finite translation).
bool IsRigid(const Eigen::Isometry3d& T, double tolerance = 1e-6);

/// The pose of a camera at `eye` looking at `target`, with image "up" as close to world +z as
/// possible (camera +Y down ≈ world -z). Throws if eye == target or the view is vertical.
Eigen::Isometry3d LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target);

}  // namespace novelty::core
