#include "apps/shell/program.h"

#include <gtest/gtest.h>
#include <mrpt/core/exceptions.h>
#include <tclap/ArgException.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "apps/shell/quiet_libpng.h"

namespace novelty::apps {
namespace {

namespace fs = std::filesystem;

// What a call writes on stderr (file descriptor 2, where libraries write too).
template <typename F>
std::string Stderr(F f) {
  std::fflush(stderr);
  const std::string path =
      fs::temp_directory_path() / ("novelty_stderr_" + std::to_string(getpid()));
  FILE* capture = std::fopen(path.c_str(), "w+");
  const int saved = dup(2);
  dup2(fileno(capture), 2);
  f();
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  std::fclose(capture);
  std::ifstream in(path);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  fs::remove(path);
  return text;
}

int Lines(const std::string& s) {
  return int(std::count(s.begin(), s.end(), '\n'));
}

TEST(RunProgram, TheBodysExitCodeAndNothingOnStderr) {
  int code = -1;
  const std::string err = Stderr([&] { code = RunProgram("p", [] { return kExitPartial; }); });
  EXPECT_EQ(code, 3);
  EXPECT_EQ(err, "");
}

TEST(RunProgram, AnMrptExceptionIsOneLineNamingTheProgram) {
  int code = -1;
  const std::string err = Stderr([&] {
    code = RunProgram("novelty-poses", []() -> int {
      MRPT_START
      THROW_EXCEPTION("/dev/zero is not a rawlog");
      MRPT_END
    });
  });
  EXPECT_EQ(code, kExitFailed);
  EXPECT_EQ(Lines(err), 1) << err;
  EXPECT_EQ(err.rfind("novelty-poses: ", 0), 0u) << err;
  EXPECT_NE(err.find("/dev/zero is not a rawlog"), std::string::npos) << err;
}

TEST(RunProgram, CommandLineErrorsExitWithTwo) {
  EXPECT_EQ(RunProgram("p", []() -> int { throw TCLAP::ArgException("bad value", "--frames"); }),
            kExitUsage);
  EXPECT_EQ(RunProgram("p", []() -> int { throw UsageError("--near must be below --far"); }),
            kExitUsage);
  std::string err = Stderr(
      [] { RunProgram("p", []() -> int { throw TCLAP::ArgException("bad value", "--frames"); }); });
  EXPECT_EQ(err, "p: bad value (Argument: --frames)\n");  // TCLAP names the flag so
}

TEST(RunProgram, ALongOrBinaryMessageIsCutToOnePrintableLine) {
  const std::string err = Stderr([] {
    RunProgram("p", []() -> int { throw std::runtime_error(std::string(5000, 'x') + "\n\x01y"); });
  });
  EXPECT_EQ(Lines(err), 1);
  EXPECT_LT(err.size(), 700u);
}

// The "libpng error:" lines: a corrupt PNG read through OpenCV says nothing on stderr,
// and imread returns an empty image for the program to name the file.
TEST(QuietLibpng, ACorruptPngSaysNothingAndDecodesToNothing) {
  const fs::path png =
      fs::temp_directory_path() / ("novelty_corrupt_" + std::to_string(getpid()) + ".png");
  ASSERT_TRUE(cv::imwrite(png.string(), cv::Mat(8, 8, CV_8UC3, cv::Scalar(1, 2, 3))));
  std::vector<char> bytes;
  {
    std::ifstream in(png, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 40u);
  bytes[20] ^= 0x55;  // inside IHDR: its CRC no longer matches, libpng calls png_error
  std::ofstream(png, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  QuietLibpng();
  const int before = SilencedLibpngMessages();
  cv::Mat image;
  const std::string err = Stderr([&] { image = cv::imread(png.string(), cv::IMREAD_UNCHANGED); });
  EXPECT_TRUE(image.empty());
  EXPECT_EQ(err, "");
  EXPECT_GT(SilencedLibpngMessages(), before);  // the handler ran: libpng was not merely quiet
  // A sound PNG still decodes.
  ASSERT_TRUE(cv::imwrite(png.string(), cv::Mat(8, 8, CV_8UC3, cv::Scalar(1, 2, 3))));
  EXPECT_EQ(cv::imread(png.string()).at<cv::Vec3b>(7, 7), cv::Vec3b(1, 2, 3));
  fs::remove(png);
}

}  // namespace
}  // namespace novelty::apps
