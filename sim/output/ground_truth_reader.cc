#include "sim/output/ground_truth_reader.h"
#include "core/rigid_pose.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/frame_stem.h"
#include "sim/output/ground_truth_format.h"

namespace novelty::sim {

namespace {

// Rows of a CSV file after its header, split at commas (no field of these files holds one
// before the columns read here); calls `row(fields, line_number)`. A missing optional file
// gives no rows.
template <class Row>
void ReadRows(const std::string& path, bool required, Row row) {
  std::ifstream in(path);
  if (!in) {
    if (required) throw std::runtime_error(path + ": cannot open");
    return;
  }
  std::string line;
  std::getline(in, line);  // header
  for (int n = 2; std::getline(in, line); ++n) {
    std::vector<std::string> f;
    std::stringstream s(line);
    for (std::string item; std::getline(s, item, ',');) f.push_back(item);
    try {
      row(f);
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ":" + std::to_string(n) + ": malformed row (" + e.what() +
                               ")");
    }
  }
}

cv::Mat ReadPng(const std::string& dir, const char* sub, int frame) {
  return cv::imread(dir + "/" + sub + "/" + core::FrameStem(frame) + ".png", cv::IMREAD_UNCHANGED);
}

}  // namespace

GroundTruthReader::GroundTruthReader(const std::string& dir) : dir_(dir) {
  ReadRows(dir + "/poses.csv", true, [&](const std::vector<std::string>& f) {
    if (f.size() < 10) throw std::invalid_argument("too few columns");
    const Eigen::Quaterniond q(std::stod(f[9]), std::stod(f[6]), std::stod(f[7]), std::stod(f[8]));
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = q.normalized().toRotationMatrix();
    T.translation() = Eigen::Vector3d(std::stod(f[3]), std::stod(f[4]), std::stod(f[5]));
    // A NaN or zero quaternion normalises to NaN: the pose would warp every view to nowhere.
    if (!(std::abs(q.norm() - 1.0) < 1e-3) || !core::IsRigid(T, 1e-6))
      throw std::invalid_argument("not a rigid pose (quaternion norm " + std::to_string(q.norm()) +
                                  ")");
    poses_[std::stoi(f[0])] = T;
  });
  ReadRows(dir + "/objects.csv", false, [&](const std::vector<std::string>& f) {
    if (f.size() >= 2) objects_[std::stoi(f[0])] = f[1];
  });
  ReadRows(dir + "/events.csv", false, [&](const std::vector<std::string>& f) {
    if (f.size() >= 4 && f[0] == "phase")
      phases_.push_back({f[1], std::stoi(f[2]), std::stoi(f[3])});
  });
}

std::string GroundTruthReader::PhaseOf(int frame) const {
  for (const Phase& p : phases_) {
    if (frame >= p.first && frame <= p.last) return p.name;
  }
  return "";
}

cv::Mat GroundTruthReader::Depth(int frame) const {
  const cv::Mat png = ReadPng(dir_, "depth", frame);
  cv::Mat depth;
  if (!png.empty()) png.convertTo(depth, CV_32F, 1.0 / ground_truth::kDepthUnitsPerMetre);
  return depth;
}

cv::Mat GroundTruthReader::Ids(int frame) const {
  const cv::Mat png = ReadPng(dir_, "ids", frame);
  cv::Mat ids;
  if (!png.empty()) png.convertTo(ids, CV_32S, 1.0, -ground_truth::kIdOffset);
  return ids;
}

cv::Mat GroundTruthReader::Novelty(int frame) const {
  return ReadPng(dir_, "novelty", frame);
}

std::map<std::string, cv::Mat> GroundTruthReader::ChangedRegions(int frame, int min_pixels) const {
  std::map<std::string, cv::Mat> regions;
  const cv::Mat novelty = Novelty(frame), ids = Ids(frame);
  if (novelty.empty() || ids.empty()) return regions;
  const cv::Mat added_mask = novelty == ground_truth::kNoveltyAdded;
  std::set<int> added;
  for (int i = 0; i < int(novelty.total()); ++i) {
    if (added_mask.at<uint8_t>(i)) added.insert(ids.at<int>(i));
  }
  for (int id : added) {
    const cv::Mat region = added_mask & (ids == id);
    if (cv::countNonZero(region) < min_pixels) continue;
    const auto n = objects_.find(id);
    regions[n == objects_.end() ? "object " + std::to_string(id) : n->second] = region;
  }
  const cv::Mat removed = novelty == ground_truth::kNoveltyRemoved;
  if (cv::countNonZero(removed) >= min_pixels) regions["removed"] = removed;
  return regions;
}

}  // namespace novelty::sim
