#include "sensors/dataset/lighting_folder_reader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

fs::path FreshFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("novelty_lighting_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void WriteBgr(const fs::path& path, cv::Scalar bgr, cv::Size size = {12, 8}) {
  ASSERT_TRUE(cv::imwrite(path.string(), cv::Mat(size, CV_8UC3, bgr)));
}

std::string ErrorOf(const std::string& folder) {
  try {
    ReadLightingFolder(folder);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(LightingFolderReader, ReadsLightingsInNameOrderAsRgbWithMaskAndGroundTruth) {
  const fs::path dir = FreshFolder("good");
  WriteBgr(dir / "b.png", {10, 20, 30});
  WriteBgr(dir / "a.png", {1, 2, 3});
  WriteBgr(dir / "reflectance.png", {5, 5, 5});
  cv::Mat mask = cv::Mat::zeros(8, 12, CV_8U);
  mask.at<uchar>(2, 3) = 7;
  ASSERT_TRUE(cv::imwrite((dir / "mask.png").string(), mask));
  std::ofstream(dir / "notes.txt") << "not an image";
  const LightingFolder f = ReadLightingFolder(dir.string());
  ASSERT_EQ(f.images.size(), 2u);
  EXPECT_EQ(f.names[0], "a.png");
  EXPECT_EQ(f.images[0].at<cv::Vec3b>(0, 0), cv::Vec3b(3, 2, 1));  // R G B
  EXPECT_EQ(cv::countNonZero(f.mask), 1);
  EXPECT_EQ(f.mask.at<uchar>(2, 3), 255);
  EXPECT_EQ(f.reflectance.type(), CV_32FC3);
  EXPECT_TRUE(f.shading.empty());
}

// A folder that holds more than the lightings: patterns pick them, and say what they left out.
TEST(LightingFolderReader, PatternsPickTheLightings) {
  const fs::path dir = FreshFolder("patterns");
  for (const char* name :
       {"dir1.png", "dir2.png", "dir3.jpg", "all_Ambient.png", "depth_valid.png"})
    WriteBgr(dir / name, {1, 2, 3});
  EXPECT_EQ(ReadLightingFolder(dir.string()).images.size(), 5u) << "every image by default";
  LightingFolderOptions o;
  o.exclude = {"*_Ambient*", "depth*"};
  LightingFolder f = ReadLightingFolder(dir.string(), o);
  EXPECT_EQ(f.names, (std::vector<std::string>{"dir1.png", "dir2.png", "dir3.jpg"}));
  EXPECT_EQ(f.left_out, (std::vector<std::string>{"all_Ambient.png", "depth_valid.png"}));
  o.include = {"dir[12].*"};
  f = ReadLightingFolder(dir.string(), o);
  EXPECT_EQ(f.names, (std::vector<std::string>{"dir1.png", "dir2.png"}));
  o.include = {"dir1.png"};
  try {
    ReadLightingFolder(dir.string(), o);
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("1 image(s) of lightings (4 left out by the "),
              std::string::npos)
        << e.what();
  }
}

TEST(LightingFolderReader, NamesTheProblem) {
  EXPECT_NE(ErrorOf("/nonexistent/lights").find("no such folder"), std::string::npos);
  const fs::path one = FreshFolder("one");
  WriteBgr(one / "only.png", {1, 1, 1});
  EXPECT_NE(ErrorOf(one.string()).find("single lighting"), std::string::npos);
  const fs::path sizes = FreshFolder("sizes");
  WriteBgr(sizes / "a.png", {1, 1, 1});
  WriteBgr(sizes / "b.png", {1, 1, 1}, {13, 8});
  EXPECT_NE(ErrorOf(sizes.string()).find("b.png is 13x8"), std::string::npos)
      << ErrorOf(sizes.string());
  const fs::path broken = FreshFolder("broken");
  WriteBgr(broken / "a.png", {1, 1, 1});
  std::ofstream(broken / "b.png") << "not a png";
  EXPECT_NE(ErrorOf(broken.string()).find("b.png: cannot be read"), std::string::npos);
}

TEST(LightingFolderReader, ReadsAnMitObject) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const std::string dir = std::string(shared ? shared : "") + "/mit-intrinsic/cup1";
  if (!shared || !fs::exists(dir)) GTEST_SKIP() << "mit-intrinsic/ of the shared data is absent";
  const LightingFolder f = ReadLightingFolder(dir);
  EXPECT_EQ(f.images.size(), 10u);
  EXPECT_EQ(f.names.front(), "light01.png");
  EXPECT_EQ(f.images.front().type(), CV_16UC3);
  EXPECT_GT(cv::countNonZero(f.mask), 1000);
  EXPECT_FALSE(f.reflectance.empty());
  EXPECT_FALSE(f.shading.empty());
  EXPECT_FALSE(f.diffuse.empty());
}

}  // namespace
}  // namespace novelty::sensors
