#include "core/temporary_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace novelty::core {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class TemporaryFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("novelty_temporary_file_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(TemporaryFileTest, CommitReplacesTheFinalFile) {
  const fs::path out = dir_ / "out.map";
  std::ofstream(out) << "old";
  {
    TemporaryFile tmp(out.string());
    EXPECT_NE(tmp.path(), out.string());
    EXPECT_EQ(fs::path(tmp.path()).parent_path(), dir_);
    EXPECT_EQ(Read(out), "old");  // nothing changes before Commit
    std::ofstream(tmp.path()) << "new";
    tmp.Commit();
    EXPECT_FALSE(fs::exists(tmp.path()));
  }
  EXPECT_EQ(Read(out), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(TemporaryFileTest, WithoutCommitNothingIsPublishedAndNothingLeft) {
  const fs::path out = dir_ / "out.map";
  std::ofstream(out) << "old";
  {
    TemporaryFile tmp(out.string());
    std::ofstream(tmp.path()) << "half";
  }
  EXPECT_EQ(Read(out), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

// The case: "out.map.tmp -> precious.rawlog" must not destroy the rawlog.
TEST_F(TemporaryFileTest, ALinkAtTheOldTemporaryNameIsNeverFollowed) {
  const fs::path precious = dir_ / "precious.rawlog";
  std::ofstream(precious) << "precious";
  fs::create_symlink(precious, dir_ / "out.map.tmp");
  TemporaryFile tmp((dir_ / "out.map").string());
  std::ofstream(tmp.path()) << "map";
  tmp.Commit();
  EXPECT_EQ(Read(precious), "precious");
  EXPECT_EQ(Read(dir_ / "out.map"), "map");
  EXPECT_TRUE(fs::is_symlink(dir_ / "out.map.tmp"));
}

TEST_F(TemporaryFileTest, ALinkAtTheFinalNameIsReplacedNotWrittenThrough) {
  const fs::path precious = dir_ / "precious.rawlog";
  std::ofstream(precious) << "precious";
  fs::create_symlink(precious, dir_ / "out.map");
  TemporaryFile tmp((dir_ / "out.map").string());
  std::ofstream(tmp.path()) << "map";
  tmp.Commit();
  EXPECT_EQ(Read(precious), "precious");
  EXPECT_FALSE(fs::is_symlink(dir_ / "out.map"));
  EXPECT_EQ(Read(dir_ / "out.map"), "map");
}

TEST_F(TemporaryFileTest, TwoAtOnceGetDifferentNames) {
  TemporaryFile a((dir_ / "x").string()), b((dir_ / "x").string());
  EXPECT_NE(a.path(), b.path());
}

TEST_F(TemporaryFileTest, ReadableAsAnyFileTheUserWrites) {
  const mode_t mask = umask(022);
  TemporaryFile tmp((dir_ / "x").string());
  umask(mask);
  struct stat st {};
  ASSERT_EQ(stat(tmp.path().c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST_F(TemporaryFileTest, AMissingFolderIsAnErrorNamingTheFile) {
  const std::string out = (dir_ / "missing" / "out.map").string();
  try {
    TemporaryFile tmp(out);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(out), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace novelty::core
