#include "sensors/rawlog/brief_message.h"

#include <sstream>

namespace novelty::sensors {

namespace {

std::string Trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// Length of the well-formed UTF-8 sequence at s[i] (our messages say "…", "→", "×"), 0 if none.
std::size_t Utf8Length(const std::string& s, std::size_t i) {
  const auto u = static_cast<unsigned char>(s[i]);
  const std::size_t n = u >= 0xC2 && u <= 0xDF   ? 2
                        : u >= 0xE0 && u <= 0xEF ? 3
                        : u >= 0xF0 && u <= 0xF4 ? 4
                                                 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  return n;
}

// Newlines and tabs as spaces, other control bytes and bytes that are not UTF-8 as '?': texts
// read from a foreign file may hold anything.
std::string Printable(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const auto u = static_cast<unsigned char>(s[i]);
    if (u == '\n' || u == '\t') {
      out += ' ';
    } else if (u >= 32 && u <= 126) {
      out += s[i];
    } else if (const std::size_t n = Utf8Length(s, i); n > 0) {
      out.append(s, i, n);
      i += n;
      continue;
    } else {
      out += '?';
    }
    ++i;
  }
  return out;
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
  brief = Printable(brief);
  if (brief.size() > max_length) {
    std::size_t cut = max_length;  // not inside a UTF-8 sequence
    while (cut > 0 && (static_cast<unsigned char>(brief[cut]) & 0xC0) == 0x80) --cut;
    brief = brief.substr(0, cut) + "…";
  }
  return brief;
}

std::string BriefMessage(const std::exception& e, std::size_t max_length) {
  return BriefMessage(std::string(e.what()), max_length);
}

}  // namespace novelty::sensors
