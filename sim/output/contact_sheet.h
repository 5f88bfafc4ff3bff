// A contact sheet: frames as labelled thumbnails on a grid, for a quick look at a whole run.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

namespace novelty::sim {

/// RGB tiles (all the same size) → one RGB image, `columns` wide, each tile labelled.
cv::Mat ContactSheet(const std::vector<std::pair<std::string, cv::Mat>>& tiles, int columns);

}  // namespace novelty::sim
