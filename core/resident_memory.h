// The process's resident memory, for soak runs that watch it over thousands of frames.
#pragma once

namespace novelty::core {

/// Resident set size in MiB (/proc/self/statm); NaN where /proc is not available.
double ResidentMegabytes();

}  // namespace novelty::core
