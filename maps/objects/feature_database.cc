#include "maps/objects/feature_database.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace novelty::objects {

namespace {
// A feature seen on every frame of a year at 30 Hz stays far below; sums over the objects of a
// feature stay within 64 bits.
constexpr int kMaxCount = 1 << 30;

// An angle in [0, 360) and a positive finite size, each or both unknown (NaN).
bool Valid(const LearntKeypoint& k) {
  return (std::isnan(k.angle_deg) || (k.angle_deg >= 0.0 && k.angle_deg < 360.0)) &&
         (std::isnan(k.size_m) || (std::isfinite(k.size_m) && k.size_m > 0.0));
}
}  // namespace

// A name that would break a CSV row or a terminal line, or an outline that is no polygon.
std::string FeatureDatabase::InfoError(const ObjectInfo& info) {
  if (info.name.size() > FeatureDatabase::kMaxNameLength)
    return "a name of " + std::to_string(info.name.size()) + " characters";
  for (const char c : info.name)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "a name with a control character";
  if (info.outline.size() > FeatureDatabase::kMaxOutline ||
      (!info.outline.empty() && info.outline.size() < 3))
    return "an outline of " + std::to_string(info.outline.size()) + " points";
  for (const Eigen::Vector2d& p : info.outline)
    if (!p.allFinite()) return "an outline point that is not finite";
  return "";
}
int FeatureDatabase::AddObject(ObjectInfo info) {
  const std::string error = InfoError(info);
  if (!error.empty()) throw std::invalid_argument("FeatureDatabase::AddObject: " + error);
  info_.push_back(std::move(info));
  return objects_++;
}

const ObjectInfo& FeatureDatabase::Info(int k) const {
  if (k < 0 || k >= objects_)
    throw std::out_of_range("FeatureDatabase: object " + std::to_string(k) + " of " +
                            std::to_string(objects_));
  return info_[std::size_t(k)];
}

std::string FeatureDatabase::DisplayName(int k) const {
  const std::string& name = Info(k).name;
  return name.empty() ? "object " + std::to_string(k) : name;
}

void FeatureDatabase::AddFeatures(const cv::Mat& descriptors, int object,
                                  const std::vector<Eigen::Vector3d>& positions,
                                  const std::vector<LearntKeypoint>& keypoints) {
  if (object < 0 || object >= objects_)
    throw std::invalid_argument("FeatureDatabase::AddFeatures: object " + std::to_string(object) +
                                " of " + std::to_string(objects_));
  if (descriptors.empty()) return;
  if (descriptors.type() != CV_32FC1 ||
      (!descriptors_.empty() && descriptors.cols != descriptors_.cols))
    throw std::invalid_argument(
        "FeatureDatabase::AddFeatures: descriptors must be CV_32F rows of "
        "the database's width");
  if (!positions.empty() && int(positions.size()) != descriptors.rows)
    throw std::invalid_argument(
        "FeatureDatabase::AddFeatures: " + std::to_string(positions.size()) + " positions for " +
        std::to_string(descriptors.rows) + " descriptors");
  if (!std::all_of(keypoints.begin(), keypoints.end(), Valid))
    throw std::invalid_argument(
        "FeatureDatabase::AddFeatures: a keypoint angle outside [0, 360) "
        "or a size that is not positive");
  if (!keypoints.empty() && int(keypoints.size()) != descriptors.rows)
    throw std::invalid_argument(
        "FeatureDatabase::AddFeatures: " + std::to_string(keypoints.size()) + " keypoints for " +
        std::to_string(descriptors.rows) + " descriptors");
  descriptors_.push_back(descriptors);
  for (int i = 0; i < descriptors.rows; ++i) {
    n_.push_back({{object, 1}});  // eq. 5.6, 5.7
    positions_.push_back(positions.empty()
                             ? Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN())
                             : positions[std::size_t(i)]);
    keypoints_.push_back(keypoints.empty() ? LearntKeypoint() : keypoints[std::size_t(i)]);
  }
}

FeatureDatabase FeatureDatabase::FromParts(int objects, const cv::Mat& descriptors,
                                           const Counts& counts,
                                           const std::vector<Eigen::Vector3d>& positions,
                                           const std::vector<LearntKeypoint>& keypoints,
                                           const std::vector<ObjectInfo>& info) {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument("feature database: " + what);
  };
  if (objects < 0) fail("a negative object count");
  if (!descriptors.empty() && descriptors.type() != CV_32FC1) fail("descriptors are not CV_32F");
  const std::size_t n = std::size_t(descriptors.rows);
  if (counts.size() != n || positions.size() != n)
    fail(std::to_string(n) + " descriptors, " + std::to_string(counts.size()) + " count lists, " +
         std::to_string(positions.size()) + " positions");
  if (!keypoints.empty() && keypoints.size() != n)
    fail(std::to_string(n) + " descriptors, " + std::to_string(keypoints.size()) + " keypoints");
  for (std::size_t h = 0; h < keypoints.size(); ++h)
    if (!Valid(keypoints[h]))
      fail("feature " + std::to_string(h) + ": a keypoint angle of " +
           std::to_string(keypoints[h].angle_deg) + " deg or size of " +
           std::to_string(keypoints[h].size_m) + " m");
  for (std::size_t h = 0; h < n; ++h) {
    if (counts[h].empty()) fail("feature " + std::to_string(h) + " belongs to no object");
    for (std::size_t a = 0; a < counts[h].size(); ++a)
      for (std::size_t b = a + 1; b < counts[h].size(); ++b)
        if (counts[h][a].first == counts[h][b].first)
          fail("feature " + std::to_string(h) + " counts object " +
               std::to_string(counts[h][a].first) + " twice");
    for (const auto& [object, count] : counts[h])
      if (object < 0 || object >= objects || count < 1 || count > kMaxCount)
        fail("feature " + std::to_string(h) + ": count " + std::to_string(count) + " on object " +
             std::to_string(object) + " of " + std::to_string(objects));
  }
  if (!descriptors.empty() && !cv::checkRange(descriptors)) fail("a descriptor is not finite");
  if (!info.empty() && info.size() != std::size_t(objects))
    fail(std::to_string(objects) + " objects, " + std::to_string(info.size()) + " names");
  for (std::size_t k = 0; k < info.size(); ++k)
    if (const std::string error = InfoError(info[k]); !error.empty())
      fail("object " + std::to_string(k) + ": " + error);
  FeatureDatabase db;
  db.info_ = info.empty() ? std::vector<ObjectInfo>(std::size_t(objects)) : info;
  db.objects_ = objects;
  db.descriptors_ = descriptors.clone();
  db.n_ = counts;
  db.positions_ = positions;
  db.keypoints_ = keypoints.empty() ? std::vector<LearntKeypoint>(n) : keypoints;
  return db;
}

const Eigen::Vector3d& FeatureDatabase::Position(int h) const {
  CheckFeature(h);
  return positions_[std::size_t(h)];
}

const LearntKeypoint& FeatureDatabase::Keypoint(int h) const {
  CheckFeature(h);
  return keypoints_[std::size_t(h)];
}

void FeatureDatabase::CheckFeature(int h) const {
  if (h < 0 || h >= features())
    throw std::out_of_range("FeatureDatabase: feature " + std::to_string(h) + " of " +
                            std::to_string(features()));
}

int FeatureDatabase::Count(int h, int k) const {
  CheckFeature(h);
  for (const auto& [object, n] : n_[std::size_t(h)])
    if (object == k) return n;
  return 0;
}

double FeatureDatabase::RelativeFrequency(int h, int k) const {
  CheckFeature(h);
  long long total = 0;
  for (const auto& entry : n_[std::size_t(h)]) total += entry.second;
  return total > 0 ? double(Count(h, k)) / total : 0.0;  // eq. 5.3
}

int FeatureDatabase::MostProbableObject(int h) const {
  CheckFeature(h);
  int best = -1, best_n = 0;
  for (const auto& [object, n] : n_[std::size_t(h)]) {
    if (n > best_n || (n == best_n && object < best)) best = object, best_n = n;
  }
  return best;
}

FeatureDatabase::Recognition FeatureDatabase::Match(
    const cv::Mat& selected, double ratio, const std::vector<cv::KeyPoint>* keypoints) const {
  return Tally(keypoints ? RatioMatches(descriptors_, selected, ratio, *keypoints)
                         : RatioMatches(descriptors_, selected, ratio));
}

FeatureDatabase::Recognition FeatureDatabase::Tally(std::vector<RatioMatch> matches) const {
  Recognition r;
  r.matches_per_object.assign(std::size_t(objects_), 0);
  r.matches = std::move(matches);
  for (const RatioMatch& m : r.matches)
    ++r.matches_per_object[std::size_t(MostProbableObject(m.reference))];
  int best = 0;
  for (int k = 0; k < objects_; ++k) {  // eq. 5.4
    const int n = r.matches_per_object[std::size_t(k)];
    if (n > best) best = n, r.object = k;
  }
  return r;
}

FeatureDatabase::Recognition FeatureDatabase::Recognize(
    const cv::Mat& selected, double ratio, const std::vector<cv::KeyPoint>* keypoints) {
  Recognition r = Match(selected, ratio, keypoints);
  // Each database feature matches at most once, so its increment cannot change another's M.
  for (const RatioMatch& m : r.matches) {
    const int k = MostProbableObject(m.reference);
    for (auto& entry : n_[std::size_t(m.reference)])
      if (entry.first == k && entry.second < kMaxCount) ++entry.second;  // n_{h,M} += 1
  }
  return r;
}

}  // namespace novelty::objects
