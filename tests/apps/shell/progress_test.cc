#include "apps/shell/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace novelty::apps {
namespace {

TEST(FormatProgress, RateAndTimeLeftFromTheCounts) {
  // 120 of 300 in 8 s: 15 frames/s, 180 frames left -> 12 s.
  EXPECT_EQ(FormatProgress("learning", 120, 300, 8.0, 10),
            "learning [####......]  120/300 frames  15.0 frames/s  12 s left");
  EXPECT_EQ(FormatProgress("judging", 120, 300, 8.0, 0),
            "judging  120/300 frames  15.0 frames/s  12 s left");
  EXPECT_EQ(FormatProgress("playing", 40, 0, 4.0, 10), "playing  40 frames  10.0 frames/s");
  EXPECT_EQ(FormatProgress("x", 300, 300, 10.0, 4), "x [####]  300/300 frames  30.0 frames/s");
  EXPECT_EQ(FormatProgress("x", 0, 10, 0.0, 4), "x [....]  0/10 frames");
}

std::string Drawn(ProgressOptions o, int updates) {
  char buffer[4096] = {};
  std::FILE* out = fmemopen(buffer, sizeof buffer - 1, "w");
  {
    Progress p("playing", updates, o, out);
    for (int k = 1; k <= updates; ++k) p.Update(k);
  }
  std::fclose(out);
  return buffer;
}

TEST(Progress, PlainLinesOnlyEveryFewSecondsAndNothingWhenQuiet) {
  ProgressOptions plain;
  plain.terminal = false;
  plain.line_every_s = 3600;
  EXPECT_EQ(Drawn(plain, 100), "") << "a short run off a terminal prints nothing";
  plain.line_every_s = 0;
  const std::string every = Drawn(plain, 3);
  EXPECT_EQ(every.substr(0, every.find('\n')).rfind("playing  1/3 frames", 0), 0u) << every;
  EXPECT_EQ(std::count(every.begin(), every.end(), '\n'), 4);  // three updates and the last state
  ProgressOptions quiet = plain;
  quiet.quiet = true;
  EXPECT_EQ(Drawn(quiet, 3), "");
}

TEST(Progress, OnATerminalOneLineRedrawnInPlace) {
  ProgressOptions tty;
  tty.terminal = true;
  tty.redraw_every_s = 0;
  const std::string s = Drawn(tty, 3);
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 1);
  EXPECT_EQ(std::count(s.begin(), s.end(), '\r'), 4);
  EXPECT_NE(s.find("3/3 frames"), std::string::npos);
}

}  // namespace
}  // namespace novelty::apps
