#include "eval/first_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace novelty::eval {
namespace {

// A camera on a 70° arc of radius 1.6 m (4.3): Q1 → Q2 in 150 frames, a stop of 14 frames, back
// to Q1 in 150 frames; then the next phase.
std::map<int, Eigen::Vector3d> BackAndForth(int frames) {
  std::map<int, Eigen::Vector3d> positions;
  for (int f = 1; f <= frames; ++f) {
    const int k = (f - 1) % 328;
    const double s = k < 150 ? k / 150.0 : k < 164 ? 1.0 : k < 314 ? 1.0 - (k - 164) / 150.0 : 0.0;
    const double a = (-125.0 + 70.0 * s) * M_PI / 180.0;
    positions[f] = {1.6 * std::cos(a), 1.6 * std::sin(a), 1.1};
  }
  return positions;
}

TEST(FirstRunEnd, IsTheTurningPointOfEachPhase) {
  const auto positions = BackAndForth(1000);
  EXPECT_EQ(FirstRunEnd(positions, 1, 328), 151);  // Q2 reached; the stop keeps the distance
  EXPECT_EQ(FirstRunEnd(positions, 329, 656), 329 + 150);
  EXPECT_EQ(FirstRunEnd(positions, 329, 400), 400);  // a phase cut short ends farthest out
}

TEST(FirstRunEnd, PassesOverFramesWithoutPositionAndRejectsBadPhases) {
  auto positions = BackAndForth(400);
  positions.erase(151);
  EXPECT_EQ(FirstRunEnd(positions, 1, 328), 152);
  EXPECT_THROW(FirstRunEnd(positions, 151, 328), std::invalid_argument);
  EXPECT_THROW(FirstRunEnd(positions, 10, 5), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
