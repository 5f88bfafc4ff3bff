#include "sensors/rawlog/led_observation.h"

#include <gtest/gtest.h>

namespace novelty::sensors {
namespace {

TEST(LedObservation, RoundTripKeepsPositionsAndDropouts) {
  LedMeasurement leds;
  leds[0] = Eigen::Vector3d(1.2, -0.4, 1.18);
  leds[2] = Eigen::Vector3d(-2.0, 0.3, 1.25);
  leds[3] = Eigen::Vector3d(0.01, 2.5, 0.9);
  const auto obs = MakeLedObservation(1293840000.5, leds, 0.001);
  EXPECT_EQ(obs.sensorLabel, kLedTrackerLabel);
  EXPECT_EQ(obs.sensedData.size(), 3u);
  const LedSample s = DecodeLedObservation(obs);
  EXPECT_NEAR(s.time, 1293840000.5, 1e-6);
  EXPECT_FALSE(s.leds[1]);
  for (int k : {0, 2, 3}) {
    ASSERT_TRUE(s.leds[k]);
    EXPECT_LT((*s.leds[k] - *leds[k]).norm(), 2e-6) << k;  // float range/angles
  }
}

TEST(LedObservation, RefusesUnknownOrRepeatedLeds) {
  LedMeasurement leds;
  leds[0] = Eigen::Vector3d(1, 0, 1);
  auto obs = MakeLedObservation(0.0, leds, 0.001);
  obs.sensedData[0].landmarkID = 7;
  EXPECT_THROW(DecodeLedObservation(obs), std::runtime_error);
  obs.sensedData[0].landmarkID = 1;
  obs.sensedData.push_back(obs.sensedData[0]);
  EXPECT_THROW(DecodeLedObservation(obs), std::runtime_error);
}

}  // namespace
}  // namespace novelty::sensors
