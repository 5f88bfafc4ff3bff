#include "eval/skipped_frames.h"

#include <gtest/gtest.h>

namespace novelty::eval {
namespace {

TEST(SkippedFramesSummary, GroupedByReasonInTheOrderTheyCame) {
  EXPECT_EQ(SkippedFramesSummary(120, {}), "");
  EXPECT_EQ(SkippedFramesSummary(120, {"frame 4: no pose", "frame 9: depth 80x60, not 320x240",
                                       "frame 11: no pose"}),
            "skipped 3 of 120 frames: 2 no pose (first: frame 4), 1 depth 80x60, not 320x240 "
            "(frame 9)");
  EXPECT_EQ(SkippedFramesSummary(5, {"a: r1", "b: r2", "c: r3", "d: r4", "e: r5"}, 2),
            "skipped 5 of 5 frames: 1 r1 (a), 1 r2 (b), and 3 other reasons");
  EXPECT_EQ(SkippedFramesSummary(0, {"unreadable"}), "skipped 1 of 1 frames: 1 unreadable");
  // The players' form: the rawlog, the frame and its sensor, then why.
  EXPECT_EQ(SkippedFramesSummary(12, {"/d/r.rawlog: frame 3 (RGBD): no pose",
                                      "/d/r.rawlog: frame 7 (RGBD): no pose"}),
            "skipped 2 of 12 frames: 2 no pose (first: frame 3)");
}

}  // namespace
}  // namespace novelty::eval
