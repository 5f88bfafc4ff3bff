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
    const bool ok = rule == PlaneValues::kPositive ? std::isfinite(v[i]) && v[i] > 0
                    : rule == PlaneValues::kFinite ? std::isfinite(v[i])
                                                   : !std::isinf(v[i]);
    if (!ok) return std::to_string(v[i]) + " at value " + std::to_string(i);
  }
  return "";
}

}  // namespace

void CheckPlanes(const ReferenceViewStore& store, const std::vector<PlaneRule>& rules) {
  for (int j = 0; j < store.size(); ++j) {
    const ReferenceView v = store.Decoded(j);  // one at a time: a compact map stays compact
    for (const PlaneRule& rule : rules) {
      const std::string what = "view " + std::to_string(j) + ": plane '" + rule.name + "'";
      const auto it = v.planes.find(rule.name);
      if (it == v.planes.end()) throw std::invalid_argument(what + " is missing");
      const cv::Mat& p = it->second;
      if (p.channels() != rule.channels || (p.depth() != CV_32F && p.depth() != CV_16F)) {
        throw std::invalid_argument(what + " must have " + std::to_string(rule.channels) +
                                    " float channels, has " + std::to_string(p.channels()) +
                                    " of depth " + std::to_string(p.depth()));
      }
      if (const std::string bad = FirstBadValue(p, rule.values); !bad.empty())
        throw std::invalid_argument(what + " holds an invalid value " + bad);
    }
  }
}

}  // namespace novelty::views
