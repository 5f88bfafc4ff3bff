#include "maps/views/plane_check.h"

#include <cmath>
#include <stdexcept>

namespace novelty::views {

namespace {

// The first value breaking `rule`, as text; empty if none does.
std::string FirstBadValue(const cv::Mat& plane, PlaneValues rule) {
  cv::Mat f;
  plane.convertTo(f, CV_32F);  // half floats widen exactly
  const cv::Mat flat = f.reshape(1, 1);
  const float* v = flat.ptr<float>();
  for (int i = 0; i < flat.cols; ++i) {
    const bool ok = rule == PlaneValues::kPositive  ? std::isfinite(v[i]) && v[i] > 0
                    : rule == PlaneValues::kFinite ? std::isfinite(v[i])
                                                   : !std::isinf(v[i]);
    if (!ok) return std::to_string(v[i]) + " at value " + std::to_string(i);
  }
  return "";
}

}  // namespace

void CheckPlane(const ReferenceViewStore& store, const std::string& name, int channels,
                PlaneValues values) {
  for (int j = 0; j < store.size(); ++j) {
    const std::string what = "view " + std::to_string(j) + ": plane '" + name + "'";
    const auto it = store.view(j).planes.find(name);
    if (it == store.view(j).planes.end()) throw std::invalid_argument(what + " is missing");
    const cv::Mat& p = it->second;
    if (p.channels() != channels || (p.depth() != CV_32F && p.depth() != CV_16F)) {
      throw std::invalid_argument(what + " must have " + std::to_string(channels) +
                                  " float channels, has " + std::to_string(p.channels()) +
                                  " of depth " + std::to_string(p.depth()));
    }
    if (const std::string bad = FirstBadValue(p, values); !bad.empty())
      throw std::invalid_argument(what + " holds an invalid value " + bad);
  }
}

}  // namespace novelty::views
