#include "eval/novelty_panel.h"

#include "eval/side_by_side.h"

namespace novelty::eval {

cv::Mat NoveltyPanel(const cv::Mat& rgb, const appearance::AppearanceProducts& surprise,
                     const appearance::DifferencingProducts* differencing, const std::string& label,
                     const appearance::ProductScales& scales) {
  using namespace appearance;
  std::vector<cv::Mat> tiles = {rgb, surprise.expected_rgb, SurpriseImage(surprise, scales),
                                UncertaintyImage(surprise, scales)};
  std::vector<std::string> captions = {"camera " + label, "expected (tau)", SurpriseCaption(scales),
                                       UncertaintyCaption(scales)};
  if (differencing) {
    tiles.push_back(DifferenceImage(*differencing, scales));
    captions.push_back(DifferenceCaption(scales));
  }
  return SideBySide(tiles, 4, captions);
}

}  // namespace novelty::eval
