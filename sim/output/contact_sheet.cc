#include "sim/output/contact_sheet.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::sim {

cv::Mat ContactSheet(const std::vector<std::pair<std::string, cv::Mat>>& tiles, int columns) {
  if (tiles.empty()) throw std::invalid_argument("ContactSheet: no tiles");
  const cv::Size size = tiles.front().second.size();
  const int gap = 4, label = 18;
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  cv::Mat sheet(rows * (size.height + label + gap) + gap, columns * (size.width + gap) + gap,
                CV_8UC3, cv::Scalar(30, 30, 30));
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int r = int(i) / columns, c = int(i) % columns;
    const int x = gap + c * (size.width + gap), y = gap + r * (size.height + label + gap);
    tiles[i].second.copyTo(sheet(cv::Rect(x, y + label, size.width, size.height)));
    cv::putText(sheet, tiles[i].first, {x + 2, y + label - 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(235, 235, 235), 1, cv::LINE_AA);
  }
  return sheet;
}

}  // namespace novelty::sim
