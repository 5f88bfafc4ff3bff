#include "core/same_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace novelty::core {
namespace {

namespace fs = std::filesystem;

// The ways one file is written that once let an output overwrite its input ("IN --out ./IN").
TEST(SameFile, HoweverThePathIsWritten) {
  const fs::path dir = fs::temp_directory_path() / "novelty_same_file";
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "in.rawlog") << "x";
  const fs::path cwd = fs::current_path();
  fs::current_path(dir);
  EXPECT_TRUE(SameFile("in.rawlog", "./in.rawlog"));
  EXPECT_TRUE(SameFile("in.rawlog", "sub/../in.rawlog"));
  EXPECT_TRUE(SameFile("in.rawlog", (dir / "in.rawlog").string()));
  fs::create_symlink(dir / "in.rawlog", dir / "link.rawlog");
  EXPECT_TRUE(SameFile("in.rawlog", "link.rawlog"));
  EXPECT_TRUE(SameFile("new.rawlog", "./sub/../new.rawlog"));  // neither exists yet
  EXPECT_FALSE(SameFile("in.rawlog", "out.rawlog"));
  EXPECT_FALSE(SameFile("in.rawlog", "sub/in.rawlog"));
  fs::current_path(cwd);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::core
