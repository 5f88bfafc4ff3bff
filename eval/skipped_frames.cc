#include "eval/skipped_frames.h"

#include <algorithm>
#include <regex>
#include <utility>

namespace novelty::eval {

std::string SkippedFramesSummary(int frames, const std::vector<std::string>& reasons,
                                 std::size_t kinds) {
  if (reasons.empty()) return "";
  struct Group {
    std::string why, first_where;
    int count = 0;
  };
  std::vector<Group> groups;
  // "RAWLOG: frame 3 (RGBD): WHY" (the players') or "WHERE: WHY": grouped by WHY, shown by frame.
  static const std::regex framed(R"(^.*?(frame \d+)(?: \([^)]*\))?: (.*)$)");
  for (const std::string& r : reasons) {
    std::smatch m;
    const std::size_t colon = r.find(": ");
    std::string where, why = r;
    if (std::regex_match(r, m, framed)) {
      where = m[1];
      why = m[2];
    } else if (colon != std::string::npos) {
      where = r.substr(0, colon);
      why = r.substr(colon + 2);
    }
    auto g = groups.begin();
    while (g != groups.end() && g->why != why) ++g;
    if (g == groups.end()) g = groups.insert(g, Group{why, where, 0});
    ++g->count;
  }
  std::string s = "skipped " + std::to_string(reasons.size()) + " of " +
                  std::to_string(std::max<std::size_t>(std::size_t(frames), reasons.size())) +
                  " frames: ";
  for (std::size_t k = 0; k < groups.size() && k < kinds; ++k) {
    const Group& g = groups[k];
    if (k) s += ", ";
    s += std::to_string(g.count) + " " + g.why;
    if (!g.first_where.empty())
      s += " (" + std::string(g.count > 1 ? "first: " : "") + g.first_where + ")";
  }
  if (groups.size() > kinds)
    s += ", and " + std::to_string(groups.size() - kinds) + " other reason" +
         (groups.size() - kinds > 1 ? "s" : "");
  return s;
}

}  // namespace novelty::eval
