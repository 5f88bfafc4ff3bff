#include "sensors/dataset/cdnet_folder.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <stdexcept>

namespace novelty::sensors {

namespace fs = std::filesystem;

CdnetFolder ReadCdnetFolder(const std::string& dir) {
  CdnetFolder f;
  f.dir = dir;
  const fs::path input = fs::path(dir) / "input";
  if (!fs::is_directory(input))
    throw std::runtime_error(dir + ": no input/ folder (CDnet layout: input/in000001.jpg ...)");
  static const std::regex name(R"(in(\d{1,9})\.(jpg|jpeg|png|bmp))", std::regex::icase);
  std::vector<std::pair<int, std::string>> frames;
  for (const auto& e : fs::directory_iterator(input)) {
    std::smatch m;
    const std::string file = e.path().filename().string();
    if (!e.is_regular_file() || !std::regex_match(file, m, name)) continue;
    frames.emplace_back(std::stoi(m[1].str()), e.path().string());
  }
  if (frames.empty()) throw std::runtime_error(input.string() + ": no frame inNNNNNN.jpg or .png");
  std::sort(frames.begin(), frames.end());
  for (const auto& [number, path] : frames) {
    f.numbers.push_back(number);
    f.inputs.push_back(path);
    char gt[32];
    std::snprintf(gt, sizeof gt, "gt%06d.png", number);
    const fs::path truth = fs::path(dir) / "groundtruth" / gt;
    f.truths.push_back(fs::exists(truth) ? truth.string() : "");
  }
  const fs::path roi = fs::path(dir) / "ROI.bmp";
  if (fs::exists(roi)) {
    f.roi = cv::imread(roi.string(), cv::IMREAD_GRAYSCALE);
    if (f.roi.empty()) throw std::runtime_error(roi.string() + ": cannot be read");
    f.roi = f.roi > 0;
  }
  const fs::path temporal = fs::path(dir) / "temporalROI.txt";
  if (fs::exists(temporal)) {
    std::ifstream in(temporal);
    long long first = 0, last = 0;
    std::string rest;
    if (!(in >> first >> last) || (in >> rest) || first < 1 || last < first || last > 1000000000)
      throw std::runtime_error(temporal.string() + ": not two frame numbers FIRST LAST (1-based)");
    f.temporal_first = int(first), f.temporal_last = int(last);
  }
  return f;
}

cv::Mat ReadCdnetTruth(const std::string& path) {
  const cv::Mat truth = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (truth.empty()) throw std::runtime_error(path + ": cannot be read as a ground-truth image");
  return truth;
}

}  // namespace novelty::sensors
