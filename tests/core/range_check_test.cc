#include "core/range_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace novelty::core {
namespace {

TEST(RangeCheck, AcceptsTheClosedRangeAndNamesTheKeyOtherwise) {
  EXPECT_NO_THROW(CheckInRange(0.0, 0.0, 1.0, "a"));
  EXPECT_NO_THROW(CheckInRange(1.0, 0.0, 1.0, "a"));
  try {
    CheckInRange(1e30, 0.0, 255.0, "initial_tau");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "initial_tau must be in [0, 255], got 1e+30");
  }
  EXPECT_THROW(CheckInRange(std::nan(""), 0.0, 1.0, "--smoothing"), std::invalid_argument);
  EXPECT_THROW(CheckInRange(-1e-9, 0.0, 1.0, "b"), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::core
