// LED tracker samples ⇄ MRPT's CObservationBearingRange, as novelty-sim writes them: the tracker
// is fixed to the room, so the "robot" is the world origin and each seen LED is one (range, yaw,
// pitch) entry with landmarkID = LED number 1…4 (MRPT: pitch = −elevation); unseen LEDs are absent.
#pragma once

#include <mrpt/obs/CObservationBearingRange.h>

#include <string>
#include <vector>

#include "sensors/tracker/led_plate.h"

namespace novelty::sensors {

inline constexpr const char* kLedTrackerLabel = "LED_TRACKER";

/// `time` is seconds since the Unix epoch.
mrpt::obs::CObservationBearingRange MakeLedObservation(double time, const LedMeasurement& leds,
                                                       double noise_std);

/// Throws std::runtime_error for a landmark ID outside 1…4 or one given twice.
LedSample DecodeLedObservation(const mrpt::obs::CObservationBearingRange& obs);

/// Every LED_TRACKER observation of a rawlog in file order. Throws std::runtime_error naming the
/// file and object for a file that cannot be read; an observation that cannot be decoded is
/// skipped and its reason appended to `skipped` (may be null).
std::vector<LedSample> ReadLedSamples(const std::string& rawlog, std::vector<std::string>* skipped);

}  // namespace novelty::sensors
