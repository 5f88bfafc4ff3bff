// The RGB-D frame an MRPT observation holds, as the maps read it.
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <optional>

#include "core/frame.h"

namespace novelty::mrpt_plugins {

/// The frame of a CObservation3DRangeScan with an intensity image (loading external images),
/// its camera at robot_pose ⊕ sensor pose (robot at the origin if no pose). Returns false for
/// other observations; throws std::invalid_argument naming the sensor if the scan is unusable.
bool DecodeObservation(const mrpt::obs::CObservation& obs,
                       const std::optional<const mrpt::poses::CPose3D>& robot_pose,
                       core::Frame& frame);

}  // namespace novelty::mrpt_plugins
