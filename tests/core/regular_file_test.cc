#include "core/regular_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace novelty::core {
namespace {

namespace fs = std::filesystem;

std::string Message(const std::string& path, std::uintmax_t max_bytes = 1 << 20) {
  try {
    CheckRegularFile(path, max_bytes);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(RegularFile, RefusesWhatAReaderWouldHangOnOrNeverFinish) {
  const fs::path dir =
      fs::temp_directory_path() / ("novelty_regular_file_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "rgb.txt").string();
  std::ofstream(file) << "1.0 rgb/a.png\n";
  EXPECT_EQ(Message(file), "");
  const std::string link = (dir / "link.txt").string();
  fs::create_symlink(file, link);
  EXPECT_EQ(Message(link), "") << "a link to a regular file is one";
  const std::string fifo = (dir / "fifo.txt").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(Message(fifo), fifo + ": not a regular file (a folder, device or FIFO)");
  const std::string zero = (dir / "zero.txt").string();
  fs::create_symlink("/dev/zero", zero);
  EXPECT_NE(Message(zero).find("not a regular file"), std::string::npos);
  EXPECT_NE(Message(dir.string()).find("not a regular file"), std::string::npos);
  EXPECT_EQ(Message((dir / "none").string()), (dir / "none").string() + ": no such file");
  EXPECT_NE(Message(file, 4).find("14 bytes, more than the 4"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::core
