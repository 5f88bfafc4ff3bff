#include "eval/first_run.h"

#include <stdexcept>
#include <string>

namespace novelty::eval {

int FirstRunEnd(const std::map<int, Eigen::Vector3d>& positions, int first, int last) {
  const auto start = positions.find(first);
  if (first > last || start == positions.end()) {
    throw std::invalid_argument("FirstRunEnd: no camera position at frame " +
                                std::to_string(first) + " (phase " + std::to_string(first) + "-" +
                                std::to_string(last) + ")");
  }
  int farthest = first;
  double best = 0.0;
  for (auto it = start; it != positions.end() && it->first <= last; ++it) {
    const double d = (it->second - start->second).squaredNorm();
    if (d > best) best = d, farthest = it->first;
  }
  return farthest;
}

}  // namespace novelty::eval
