#include "eval/html_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

namespace novelty::eval {
namespace {

TEST(NiceTicks, AreRoundMultiplesCoveringTheRange) {
  EXPECT_EQ(NiceTicks(0, 1283), (std::vector<double>{0, 500, 1000}));
  EXPECT_EQ(NiceTicks(340, 482), (std::vector<double>{350, 400, 450}));
  EXPECT_EQ(NiceTicks(-2.3, 4.1), (std::vector<double>{-2, 0, 2, 4}));
  // The step is the least of 1, 2, 5 × 10^k not below range / count: 0.058 / 5 → 0.02.
  const std::vector<double> small = NiceTicks(0.013, 0.071);
  ASSERT_EQ(small.size(), 3u);
  EXPECT_NEAR(small[0], 0.02, 1e-15);
  EXPECT_NEAR(small[1], 0.04, 1e-15);
  EXPECT_NEAR(small[2], 0.06, 1e-15);
  EXPECT_EQ(NiceTicks(-1e-17, 1).front(), 0.0);  // never "-0" or -1e-17
  EXPECT_EQ(NiceTicks(-1e-17, 1).size(), 6u);
}

// Count of pen-down moves ("M") in the series' SVG path.
int Strokes(const std::string& svg) {
  const std::smatch m = [&] {
    std::smatch r;
    std::regex_search(svg, r, std::regex("<path d='([^']*)' fill='none' stroke='#c00'"));
    return r;
  }();
  const std::string d = m[1];
  int n = 0;
  for (char c : d) n += c == 'M';
  return n;
}

TEST(SvgLinePlot, LeavesGapsWhereFramesAreMissingOrNaN) {
  PlotSeries s{"s", "#c00", {{1, 0.5}, {2, 0.7}, {3, 0.6}, {10, 1.0}, {11, 1.2}}, 0.0};
  EXPECT_EQ(Strokes(SvgLinePlot("t", "frame", "dB", {s})), 1);  // joined: no limit
  s.max_step = 1.0;
  EXPECT_EQ(Strokes(SvgLinePlot("t", "frame", "dB", {s})), 2);  // frames 4–9 not shown
  s.points.insert(s.points.begin() + 1, {1.5, NAN});
  // A NaN breaks the line too: frame 1 stands alone, drawn as a dot, not as an empty stroke.
  const std::string svg = SvgLinePlot("t", "frame", "dB", {s});
  EXPECT_EQ(Strokes(svg), 2);
  EXPECT_NE(svg.find("<circle"), std::string::npos);
}

}  // namespace
}  // namespace novelty::eval
