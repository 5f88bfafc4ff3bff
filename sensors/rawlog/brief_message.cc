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
    // MRPT takes a trailing "[...]" of a message for its location, so a message that ends in
    // one ("… No such file [path") arrives as an empty Message: and that Location:.
    std::istringstream lines(what);
    bool empty_message = false;
    for (std::string line; std::getline(lines, line);) {
      const auto banner = line.find("==== MRPT exception ====");
      if (banner != std::string::npos) {
        line = Trim(line.substr(0, banner));
      } else if (const auto m = line.find("Message:"); m != std::string::npos) {
        line = Trim(line.substr(m + 8));
        empty_message = line.empty();
      } else if (const auto l = line.find("Location:"); l != std::string::npos && empty_message) {
        line = Trim(line.substr(l + 9));
        empty_message = false;
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
    if (c == '\n' || c == '\t')
      c = ' ';
    else if (u < 32 || u > 126)
      c = '?';
  }
  if (brief.size() > max_length) brief = brief.substr(0, max_length) + "…";
  return brief;
}

std::string BriefMessage(const std::exception& e, std::size_t max_length) {
  return BriefMessage(std::string(e.what()), max_length);
}

}  // namespace novelty::sensors
