#include "eval/novelty_panel.h"

#include "eval/side_by_side.h"

namespace novelty::eval {

cv::Mat NoveltyPanel(const cv::Mat& rgb, const appearance::AppearanceProducts& surprise,
                     const appearance::DifferencingProducts& differencing, const std::string& label,
                     const appearance::ProductScales& scales) {
  using namespace appearance;
  return SideBySide({rgb, surprise.expected_rgb, SurpriseImage(surprise, scales),
                     UncertaintyImage(surprise, scales), DifferenceImage(differencing, scales)},
                    4,
                    {"camera " + label, "expected (tau)", SurpriseCaption(scales),
                     UncertaintyCaption(scales), DifferenceCaption(scales)});
}

}  // namespace novelty::eval
