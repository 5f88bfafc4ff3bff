#include "sensors/dataset/image_header.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

class ImageHeaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("novelty_image_header_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const cv::Mat& image) {
    const std::string path = (dir_ / name).string();
    EXPECT_TRUE(cv::imwrite(path, image));
    return path;
  }
  fs::path dir_;
};

// What OpenCV decodes is what the header says, for each format and layout.
TEST_F(ImageHeaderTest, AgreesWithWhatOpenCvDecodes) {
  const cv::Mat colour(37, 53, CV_8UC3, cv::Scalar(1, 2, 3));
  const cv::Mat grey16(41, 29, CV_16UC1, cv::Scalar(5000));
  const cv::Mat rgba(11, 13, CV_8UC4, cv::Scalar(1, 2, 3, 4));
  struct Case {
    std::string name;
    cv::Mat image;
  };
  for (const Case& c :
       {Case{"c.png", colour}, Case{"g16.png", grey16}, Case{"a.png", rgba}, Case{"c.jpg", colour},
        Case{"g.jpg", cv::Mat(9, 7, CV_8UC1, 10)}, Case{"c.bmp", colour}}) {
    const std::string path = Write(c.name, c.image);
    const ImageHeader h = ReadImageHeader(path);
    const cv::Mat decoded = cv::imread(path, cv::IMREAD_UNCHANGED);
    EXPECT_EQ(h.size, decoded.size()) << c.name;
    EXPECT_EQ(h.channels, decoded.channels()) << c.name;
    EXPECT_EQ(h.bit_depth, decoded.depth() == CV_16U ? 16 : 8) << c.name;
  }
}

// A PNG claiming 20 000 × 20 000 pixels in a few bytes is refused from its header: the limit
// and the file are named, and nothing is decoded.
TEST_F(ImageHeaderTest, AHugeImageIsRefusedBeforeDecoding) {
  const std::string path = Write("small.png", cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(9)));
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  const unsigned char size[8] = {0, 0, 0x4E, 0x20, 0, 0, 0x4E, 0x20};  // 20000, 20000
  f.seekp(16);
  f.write(reinterpret_cast<const char*>(size), 8);
  f.close();
  EXPECT_EQ(ReadImageHeader(path).size, cv::Size(20000, 20000));
  try {
    CheckImageHeader(path, kDefaultMaxImagePixels);
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("400000000 pixels"), std::string::npos) << what;
  }
}

TEST_F(ImageHeaderTest, WhatIsNoImageIsNamed) {
  const std::string text = (dir_ / "notes.png").string();
  std::ofstream(text) << "not an image";
  EXPECT_THROW(ReadImageHeader(text), std::runtime_error);
  const std::string empty = (dir_ / "empty.jpg").string();
  std::ofstream(empty).close();
  EXPECT_THROW(ReadImageHeader(empty), std::runtime_error);
  EXPECT_THROW(ReadImageHeader((dir_ / "missing.png").string()), std::runtime_error);
  // A JPEG cut after its first bytes has no frame header.
  const std::string jpeg = Write("cut.jpg", cv::Mat(16, 16, CV_8UC3, cv::Scalar::all(50)));
  fs::resize_file(jpeg, 20);
  EXPECT_THROW(ReadImageHeader(jpeg), std::runtime_error);
  // Cut later, each format decodes without an error in OpenCV: the end is checked.
  cv::Mat noise(64, 64, CV_8UC3);
  cv::randu(noise, 0, 256);
  for (const char* name : {"late.jpg", "late.png", "late.bmp"}) {
    const std::string path = Write(name, noise);
    EXPECT_NO_THROW(ReadImageHeader(path)) << name;
    fs::resize_file(path, fs::file_size(path) * 2 / 3);
    try {
      ReadImageHeader(path);
      ADD_FAILURE() << name;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("cut short"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace novelty::sensors
