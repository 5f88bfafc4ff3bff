#include "sensors/dataset/cdnet_folder.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

TEST(CdnetFolder, FramesByNumberTruthsRoiAndTemporalRoi) {
  const fs::path dir = fs::temp_directory_path() / ("cdnet_folder_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "input");
  fs::create_directories(dir / "groundtruth");
  const cv::Mat grey(6, 8, CV_8UC1, cv::Scalar(90));
  for (int k : {10, 2, 1})
    cv::imwrite((dir / "input" / cv::format("in%06d.jpg", k)).string(), grey);
  cv::imwrite((dir / "input" / "notes.png").string(), grey);  // not a frame
  cv::imwrite((dir / "groundtruth" / "gt000002.png").string(), grey);
  cv::Mat roi(6, 8, CV_8UC1, cv::Scalar(0));
  roi(cv::Rect(0, 0, 4, 6)).setTo(1);
  cv::imwrite((dir / "ROI.bmp").string(), roi);
  std::ofstream(dir / "temporalROI.txt") << "2 10\n";
  const CdnetFolder f = ReadCdnetFolder(dir.string());
  EXPECT_EQ(f.numbers, (std::vector<int>{1, 2, 10}));
  EXPECT_TRUE(f.truths[0].empty());
  EXPECT_NE(f.truths[1].find("gt000002.png"), std::string::npos);
  EXPECT_EQ(cv::countNonZero(f.roi), 24);
  EXPECT_EQ(f.roi.at<uchar>(0, 0), 255);
  EXPECT_FALSE(f.scored(1));
  EXPECT_TRUE(f.scored(2) && f.scored(10));
  EXPECT_FALSE(f.scored(11));
  std::ofstream(dir / "temporalROI.txt") << "5 3\n";
  EXPECT_THROW(ReadCdnetFolder(dir.string()), std::runtime_error);
  fs::remove_all(dir / "input");
  fs::create_directories(dir / "input");
  EXPECT_THROW(ReadCdnetFolder(dir.string()), std::runtime_error) << "no frame";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sensors
