#include "sensors/dataset/timestamp_association.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/regular_file.h"

namespace novelty::sensors {
namespace {

constexpr std::uintmax_t kMaxListBytes = std::uintmax_t(1) << 28;  // 256 MB: days at 30 Hz
constexpr double kMaxTimestamp = 1e10;                             // the year 2286
constexpr int kNeighbours = 3;  // candidates on either side of an entry: bounded work

}  // namespace

std::vector<TimedLine> ReadTimedLines(const std::string& path, int fields) {
  core::CheckRegularFile(path, kMaxListBytes);
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
    const bool decimal =
        !stamp.empty() && stamp.find_first_not_of("0123456789.") == std::string::npos;
    try {
      t.time = decimal ? std::stod(stamp, &used) : 0.0;
    } catch (const std::exception&) {
      used = 0;
    }
    if (!decimal || used != stamp.size() || !(t.time <= kMaxTimestamp))
      throw std::runtime_error(path + ":" + std::to_string(n) + ": '" + stamp +
                               "' is no timestamp (seconds since 1970, a decimal number up to " +
                               "1e10)");
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
  // Candidates: each a[i]'s nearest b on either side within the window (a few, so that repeated
  // or dense timestamps cannot make the work quadratic).
  std::vector<int> order(b.size());
  for (std::size_t j = 0; j < b.size(); ++j) order[j] = int(j);
  std::sort(order.begin(), order.end(), [&](int x, int y) { return b[x] < b[y]; });
  std::vector<std::tuple<double, int, int>> candidates;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto at = std::lower_bound(order.begin(), order.end(), a[i],
                                     [&](int j, double t) { return b[j] < t; });
    for (auto it = at; it != order.end() && it - at < kNeighbours; ++it)
      if (b[*it] - a[i] <= max_difference) candidates.emplace_back(b[*it] - a[i], int(i), *it);
    for (auto it = at; it != order.begin() && at - it < kNeighbours;) {
      --it;
      if (a[i] - b[*it] <= max_difference) candidates.emplace_back(a[i] - b[*it], int(i), *it);
    }
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
