// Range checks for numbers from outside — `.ini` options (mrpt_plugins/option_table.h) and
// command-line flags — with one wording: "KEY must be in [lo, hi], got VALUE". NaN fails.
#pragma once

namespace novelty::core {

/// Throws std::invalid_argument "KEY must be in [lo, hi], got VALUE" unless lo ≤ value ≤ hi.
void CheckInRange(double value, double lo, double hi, const char* key);

}  // namespace novelty::core
