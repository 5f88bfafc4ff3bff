#include "sensors/dataset/timestamp_association.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace novelty::sensors {

std::vector<TimedLine> ReadTimedLines(const std::string& path, int fields) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<TimedLine> lines;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    const std::size_t start = text.find_first_not_of(" \t\r");
    if (start == std::string::npos || text[start] == '#') continue;
    std::istringstream s(text);
    std::string stamp;
    s >> stamp;
    TimedLine t;
    t.line = n;
    std::size_t used = 0;
    try {
      t.time = std::stod(stamp, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != stamp.size() || !std::isfinite(t.time))
      throw std::runtime_error(path + ":" + std::to_string(n) + ": '" + stamp +
                               "' is no timestamp (seconds)");
    for (std::string f; s >> f;) t.fields.push_back(f);
    if (int(t.fields.size()) < fields)
      throw std::runtime_error(path + ":" + std::to_string(n) + ": expected a timestamp and " +
                               std::to_string(fields) + " fields, got " +
                               std::to_string(t.fields.size()));
    lines.push_back(std::move(t));
  }
  if (lines.empty()) throw std::runtime_error(path + ": no timestamped line");
  return lines;
}

std::vector<std::pair<int, int>> AssociateByTime(const std::vector<double>& a,
                                                 const std::vector<double>& b,
                                                 double max_difference) {
  if (!(max_difference >= 0) || !std::isfinite(max_difference))
    throw std::invalid_argument("max time difference must be a finite number >= 0");
  // Candidates within the window; b sorted by time makes each a[i]'s window a range.
  std::vector<int> order(b.size());
  for (std::size_t j = 0; j < b.size(); ++j) order[j] = int(j);
  std::sort(order.begin(), order.end(), [&](int x, int y) { return b[x] < b[y]; });
  std::vector<std::tuple<double, int, int>> candidates;
  for (std::size_t i = 0; i < a.size(); ++i) {
    auto it = std::lower_bound(order.begin(), order.end(), a[i] - max_difference,
                               [&](int j, double t) { return b[j] < t; });
    for (; it != order.end() && b[*it] <= a[i] + max_difference; ++it)
      candidates.emplace_back(std::abs(a[i] - b[*it]), int(i), *it);
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> used_a(a.size(), false), used_b(b.size(), false);
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [dt, i, j] : candidates) {
    if (used_a[i] || used_b[j]) continue;
    used_a[i] = used_b[j] = true;
    pairs.emplace_back(i, j);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace novelty::sensors
