#include "sensors/rawlog/brief_message.h"

#include <sstream>

namespace novelty::sensors {

namespace {

std::string Trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::string BriefMessage(const std::string& what, std::size_t max_length) {
  std::string brief;
  if (what.find("Message:") == std::string::npos) {
    brief = what;
  } else {
    // Text before the first banner (our own "file: frame N:" prefix) and every Message: line.
    std::istringstream lines(what);
    for (std::string line; std::getline(lines, line);) {
      const auto banner = line.find("==== MRPT exception ====");
      if (banner != std::string::npos) {
        line = Trim(line.substr(0, banner));
      } else if (const auto m = line.find("Message:"); m != std::string::npos) {
        line = Trim(line.substr(m + 8));
      } else {
        continue;  // location, call stack
      }
      if (line.empty()) continue;
      if (!brief.empty() && brief.back() != ':') brief += ":";
      if (!brief.empty()) brief += " ";
      brief += line;
    }
  }
  for (char& c : brief) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n' || c == '\t') c = ' ';
    else if (u < 32 || u > 126) c = '?';
  }
  if (brief.size() > max_length) brief = brief.substr(0, max_length) + "…";
  return brief;
}

std::string BriefMessage(const std::exception& e, std::size_t max_length) {
  return BriefMessage(std::string(e.what()), max_length);
}

}  // namespace novelty::sensors
