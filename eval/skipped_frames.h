// The one summary of skipped frames every program prints: a frame that cannot be used (no pose,
// an unreadable image, a size that does not match) is skipped and counted, never a crash, and
// the user reads one line that says how many and why, not one line per frame.
#pragma once

#include <string>
#include <vector>

namespace novelty::eval {

/// "skipped 3 of 120 frames: 2 no pose (first: frame 4), 1 depth 80x60, not 320x240 (frame 9)"
/// from reasons written "WHERE: WHY" (RawlogMapPlayer::skip_reasons, RawlogFrameReader's), grouped
/// by WHY in the order they first came, at most `kinds` groups ("…, and 2 other reasons").
/// Empty if nothing was skipped.
std::string SkippedFramesSummary(int frames, const std::vector<std::string>& reasons,
                                 std::size_t kinds = 3);

}  // namespace novelty::eval
