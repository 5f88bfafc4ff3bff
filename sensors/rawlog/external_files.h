// Files an observation keeps outside the rawlog (MRPT's external storage: images, gzip'd depth
// matrices), checked before the observation is loaded. MRPT reads a truncated gzip depth file in
// part without complaint, and the frame would be used with a depth map that is half garbage.
#pragma once

#include <mrpt/obs/CObservation.h>

#include <string>

namespace novelty::sensors {

/// Throws std::runtime_error "`where`: image folder F is missing" if an image of `obs` (a
/// CObservation3DRangeScan or CObservationStereoImages) is stored in a file whose folder does not
/// exist: a reader then stops, since every frame would be skipped one by one for that reason.
void CheckImageFolder(const mrpt::obs::CObservation& obs, const std::string& where);

/// Throws std::runtime_error naming the file if a depth matrix of `obs` (a
/// CObservation3DRangeScan) is stored in a gzip file that is missing, truncated or corrupt.
void CheckExternalDepth(const mrpt::obs::CObservation& obs);

/// Throws std::runtime_error naming `path` unless it is a complete gzip file (every member
/// decompresses to its end and its checksums hold).
void CheckGzipComplete(const std::string& path);

}  // namespace novelty::sensors
