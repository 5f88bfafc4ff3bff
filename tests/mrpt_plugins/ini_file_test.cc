#include "mrpt_plugins/ini_file.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace novelty::mrpt_plugins {
namespace {

// Lines MRPT's parser skips in silence would drop their options: each is an error naming the
// file and line.
TEST(OpenConfigFile, LinesMrptWouldSkipAreErrorsNamingFileAndLine) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "novelty_lint.ini";
  const std::pair<std::string, const char*> cases[] = {
      {"[map]\nCAppearanceMap_count = 1\n[map_CAppearanceMap_00_options\nxi = 1\n",
       ":3: bad section header '[map_CAppearanceMap_00_options'"},
      {"xi = 1\n[map]\n", ":1: 'xi = 1' is outside any [section]"},
      {"[map]\nCAppearanceMap_count 1\n", ":2: expected 'key = value' or '[section]'"},
      {"[map]]\n", ":1: bad section header"},
      {std::string("\x89PNG\r\n\x1a\n\0\0", 10), "not a text .ini file"},
  };
  for (const auto& [text, says] : cases) {
    std::ofstream(file, std::ios::binary) << text;
    try {
      OpenConfigFile(file.string());
      ADD_FAILURE() << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
  std::ofstream(file) << "; comment\n\n[map]  ; why\nCAppearanceMap_count = 1 # one\n";
  EXPECT_NO_THROW(OpenConfigFile(file.string()));
  std::filesystem::remove(file);
}

TEST(StripIniComment, LeavesTheValue) {
  EXPECT_EQ(StripIniComment("0.8   ; f (thesis 4.1.2)"), "0.8");
  EXPECT_EQ(StripIniComment("1 # one"), "1");
  EXPECT_EQ(StripIniComment("a // b"), "a");
  EXPECT_EQ(StripIniComment("  x  "), "x");
}

TEST(ConfigSourceName, TheFileOrWhatItIs) {
  EXPECT_EQ(ConfigSourceName(mrpt::config::CConfigFileMemory("[a]\nb = 1\n")), "map definition");
}

}  // namespace
}  // namespace novelty::mrpt_plugins
