#include "eval/novelty_panel.h"

#include <cstdio>

#include "eval/false_color.h"

namespace novelty::eval {

namespace {

std::string Scale(const char* name, double max_value, const char* how = "") {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s (%s0-%g)", name, how, max_value);
  return buf;
}

}  // namespace

cv::Mat NoveltyPanel(const cv::Mat& rgb, const appearance::AppearanceProducts& surprise,
                     const appearance::DifferencingProducts& differencing,
                     const std::string& label, const NoveltyPanelScales& scales) {
  return SideBySide({rgb, surprise.expected_rgb, FalseColor(surprise.surprise, scales.surprise),
                     FalseColor(surprise.uncertainty, scales.uncertainty, true),
                     FalseColor(differencing.difference, scales.differencing)},
                    4,
                    {"camera " + label, "expected (tau)", Scale("surprise", scales.surprise),
                     Scale("uncertainty", scales.uncertainty, "log, "),
                     Scale("differencing", scales.differencing)});
}

}  // namespace novelty::eval
