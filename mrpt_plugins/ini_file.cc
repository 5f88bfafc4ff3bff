#include "mrpt_plugins/ini_file.h"

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "sensors/rawlog/brief_message.h"

namespace novelty::mrpt_plugins {

std::string ConfigSourceName(const mrpt::config::CConfigFileBase& config) {
  const auto* file = dynamic_cast<const mrpt::config::CConfigFile*>(&config);
  return file ? file->getAssociatedFile() : "map definition";
}

void CheckIniText(const std::string& content, const std::string& path) {
  // An image or a map file given as a config must not read as no options.
  if (content.find('\0') != std::string::npos)
    throw std::runtime_error(path + ": not a text .ini file");
  // Nor may a line MRPT's parser would skip (an unclosed "[section", a key without '=', a key
  // before any section) drop its options in silence.
  std::istringstream lines(content);
  std::string line;
  bool in_section = false;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string where = path + ":" + std::to_string(number) + ": ";
    const std::string text = StripIniComment(line);
    if (text.empty()) continue;
    if (text.front() == '[') {
      if (text.back() != ']' || text.size() < 3 || text.find(']') != text.size() - 1)
        throw std::runtime_error(where + "bad section header '" + text + "'");
      in_section = true;
    } else if (text.find('=') == std::string::npos || text.front() == '=') {
      throw std::runtime_error(where + "expected 'key = value' or '[section]', got '" + text + "'");
    } else if (!in_section) {
      throw std::runtime_error(where + "'" + text + "' is outside any [section]");
    }
  }
}

std::unique_ptr<mrpt::config::CConfigFileBase> OpenConfigFile(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error(path + ": no such config file");
  std::ifstream in(path, std::ios::binary);
  CheckIniText({std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()}, path);
  try {
    return std::make_unique<mrpt::config::CConfigFile>(path);
  } catch (const std::exception& e) {  // MRPT's message spans lines of parser detail
    throw std::runtime_error(path + ": not a readable .ini file (" + sensors::BriefMessage(e, 120) +
                             ")");
  }
}

std::string StripIniComment(std::string text) {
  for (const char* mark : {";", "#", "//"}) text = text.substr(0, text.find(mark));
  text.erase(text.find_last_not_of(" \t\r") + 1);
  text.erase(0, std::min(text.size(), text.find_first_not_of(" \t")));
  return text;
}

}  // namespace novelty::mrpt_plugins
