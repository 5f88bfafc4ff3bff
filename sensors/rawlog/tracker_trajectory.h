// The LED tracker's camera trajectory from a rawlog (3.1.2): the plate calibrated from the first
// interval in which it stands still, then a camera pose from every tracker sample. What
// novelty-poses --source tracker gives each image, and what a test or an experiment needs to
// play a rawlog with the tracker's poses in memory.
#pragma once

#include <string>

#include "sensors/tracker/led_plate.h"
#include "sensors/tracker/pose_trajectory.h"

namespace novelty::sensors {

struct TrackerTrajectory {
  PoseTrajectory poses{{}};
  LedPlate plate;            ///< as calibrated
  int still_samples = 0;     ///< samples the calibration used
  double still_seconds = 0;  ///< the time they span
  int rejected = 0;          ///< samples that gave no pose (undecodable, too few LEDs)
};

/// Throws std::runtime_error naming the rawlog when it has no LED_TRACKER observations or the
/// plate never stands still long enough to calibrate.
TrackerTrajectory ReadTrackerTrajectory(const std::string& rawlog);

}  // namespace novelty::sensors
