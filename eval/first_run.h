// The first run of a phase (thesis 4.3, table 4.1): every phase starts with the robot at Q1, where
// the scene was changed; it drives to Q2 and back. The first run — Q1 to Q2, until every
// reference view on the path has been passed once since the change — is where the findings of
// 4.3 are read (in the thesis, the glass: frames 340–520, fig. 4.8–4.9).
#pragma once

#include <Eigen/Core>
#include <map>

#include "core/eigen_abi.h"

namespace novelty::eval {

/// The last frame of the first run of the phase [first, last]: the frame whose camera position is
/// farthest from the one at `first` (the turning point Q2 on a back-and-forth path). `positions`
/// holds the camera position per frame; frames missing from it are passed over. Throws
/// std::invalid_argument if `first` has no position or first > last.
int FirstRunEnd(const std::map<int, Eigen::Vector3d>& positions, int first, int last);

}  // namespace novelty::eval
