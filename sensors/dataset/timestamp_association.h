// Timestamped lists as the TUM RGB-D benchmark writes them ("timestamp field…" per line, '#'
// comments), and their association by nearest time, as the benchmark's associate.py does it: of
// the pairs within `max_difference` seconds, the closest first, each entry used once (the
// candidates of an entry are its three nearest on either side).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace novelty::sensors {

struct TimedLine {
  double time = 0.0;                ///< seconds
  std::vector<std::string> fields;  ///< what follows the timestamp
  int line = 0;                     ///< 1-based, for messages
};

/// The lines of `path` with at least `fields` fields after the timestamp, in file order. Throws
/// std::runtime_error naming the file and line for a line that has fewer, a timestamp that is no
/// plain decimal number of seconds up to 1e10, or a file that is no regular file of at most
/// 256 MB, cannot be opened or holds no line.
std::vector<TimedLine> ReadTimedLines(const std::string& path, int fields);

/// Pairs (i, j) of a[i] and b[j] with |a[i] − b[j]| ≤ max_difference, the closest pairs first and
/// every index at most once; sorted by i. Throws std::invalid_argument for a negative or
/// non-finite max_difference.
std::vector<std::pair<int, int>> AssociateByTime(const std::vector<double>& a,
                                                 const std::vector<double>& b,
                                                 double max_difference);

}  // namespace novelty::sensors
