#include "sensors/rawlog/led_observation.h"

#include <cmath>
#include <stdexcept>

#include "sensors/rawlog/rawlog_input.h"

namespace novelty::sensors {

mrpt::obs::CObservationBearingRange MakeLedObservation(double time, const LedMeasurement& leds,
                                                       double noise_std) {
  mrpt::obs::CObservationBearingRange obs;
  obs.timestamp = mrpt::Clock::fromDouble(time);
  obs.sensorLabel = kLedTrackerLabel;
  obs.minSensorDistance = 0.0f;
  obs.maxSensorDistance = 20.0f;
  obs.fieldOfView_yaw = float(2 * M_PI);
  obs.fieldOfView_pitch = float(M_PI);
  obs.sensor_std_range = float(noise_std);
  for (int i = 0; i < 4; ++i) {
    if (!leds[i]) continue;
    const Eigen::Vector3d p = *leds[i];
    mrpt::obs::CObservationBearingRange::TMeasurement m;
    m.range = float(p.norm());
    m.yaw = float(std::atan2(p.y(), p.x()));
    m.pitch = float(std::atan2(-p.z(), std::hypot(p.x(), p.y())));
    m.landmarkID = i + 1;
    obs.sensedData.push_back(m);
  }
  return obs;
}

LedSample DecodeLedObservation(const mrpt::obs::CObservationBearingRange& obs) {
  LedSample sample;
  sample.time = mrpt::Clock::toDouble(obs.timestamp);
  for (const auto& m : obs.sensedData) {
    if (m.landmarkID < 1 || m.landmarkID > 4)
      throw std::runtime_error("LED id " + std::to_string(m.landmarkID) + " (1…4 expected)");
    auto& led = sample.leds[m.landmarkID - 1];
    if (led) throw std::runtime_error("LED " + std::to_string(m.landmarkID) + " given twice");
    const double r = m.range, elevation = -m.pitch;
    led = Eigen::Vector3d(r * std::cos(elevation) * std::cos(m.yaw),
                          r * std::cos(elevation) * std::sin(m.yaw), r * std::sin(elevation));
  }
  return sample;
}

std::vector<LedSample> ReadLedSamples(const std::string& rawlog,
                                      std::vector<std::string>* skipped) {
  RawlogInput input(rawlog);
  std::vector<LedSample> samples;
  while (const auto obj = input.Next()) {
    auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(obj);
    if (!obs || obs->sensorLabel != kLedTrackerLabel) continue;
    try {
      samples.push_back(DecodeLedObservation(*obs));
    } catch (const std::exception& e) {
      if (skipped)
        skipped->push_back(rawlog + ": object " + std::to_string(input.object()) + ": " + e.what());
    }
  }
  return samples;
}

}  // namespace novelty::sensors
