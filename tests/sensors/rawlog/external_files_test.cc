#include "sensors/rawlog/external_files.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <vector>

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

// A gzip file of n pseudo-random bytes (incompressible, so a cut removes data, not only the
// trailer), and its size on disk.
std::uintmax_t WriteGzip(const fs::path& path, int n) {
  gzFile f = gzopen(path.c_str(), "wb1");
  std::vector<unsigned char> data(static_cast<std::size_t>(n));
  unsigned x = 12345;
  for (unsigned char& c : data) c = (x = x * 1103515245u + 12345u) >> 24;
  gzwrite(f, data.data(), unsigned(n));
  gzclose(f);
  return fs::file_size(path);
}

TEST(CheckGzipComplete, AcceptsWholeFilesAndRefusesCutOrDamagedOnes) {
  const fs::path file = fs::temp_directory_path() / "novelty_external_depth.bin";
  const std::uintmax_t size = WriteGzip(file, 9608);
  EXPECT_NO_THROW(CheckGzipComplete(file.string()));
  for (const std::uintmax_t cut : {size / 2, size - 4, std::uintmax_t(10)}) {
    WriteGzip(file, 9608);
    fs::resize_file(file, cut);
    try {
      CheckGzipComplete(file.string());
      ADD_FAILURE() << "cut to " << cut << " bytes was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": truncated or corrupt gzip", 0), 0u)
          << e.what();
    }
  }
  WriteGzip(file, 9608);
  {  // one byte of the compressed data flipped: the CRC fails
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(size / 2));
    f.put(char(0x55));
  }
  EXPECT_THROW(CheckGzipComplete(file.string()), std::runtime_error);
  fs::remove(file);
  EXPECT_THROW(CheckGzipComplete(file.string()), std::runtime_error);  // missing
}

}  // namespace
}  // namespace novelty::sensors
