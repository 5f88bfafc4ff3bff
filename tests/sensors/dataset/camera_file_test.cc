#include "sensors/dataset/camera_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

class CameraFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("novelty_camera_file_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
};

// The TUM fr3 calibration as ROS's camera_calibration_parsers write it, without the optional
// camera_name.
constexpr const char* kRosYaml = R"(image_width: 640
image_height: 480
camera_matrix:
  rows: 3
  cols: 3
  data: [535.4, 0, 320.1, 0, 539.2, 247.6, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [0, 0, 0, 0, 0]
rectification_matrix:
  rows: 3
  cols: 3
  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]
projection_matrix:
  rows: 3
  cols: 4
  data: [535.4, 0, 320.1, 0, 0, 539.2, 247.6, 0, 0, 0, 1, 0]
)";

TEST_F(CameraFileTest, ReadsARosCameraInfoYaml) {
  const core::PinholeCamera c = ReadCameraFile(Write("fr3.yaml", kRosYaml));
  EXPECT_EQ(c.width, 640);
  EXPECT_EQ(c.height, 480);
  EXPECT_DOUBLE_EQ(c.fx, 535.4);
  EXPECT_DOUBLE_EQ(c.fy, 539.2);
  EXPECT_DOUBLE_EQ(c.cx, 320.1);
  EXPECT_DOUBLE_EQ(c.cy, 247.6);
}

TEST_F(CameraFileTest, ReadsAnMrptCameraIni) {
  const core::PinholeCamera c =
      ReadCameraFile(Write("cam.ini",
                           "[CAMERA_PARAMS]\nresolution = [320 240]\ncx = 160.5\ncy = 120.5\n"
                           "fx = 300\nfy = 301\ndist = [0 0 0 0 0]\n"));
  EXPECT_EQ(c.width, 320);
  EXPECT_DOUBLE_EQ(c.fy, 301.0);
  EXPECT_DOUBLE_EQ(c.cx, 160.5);
}

// Distortion, missing keys and garbage are errors naming the file.
TEST_F(CameraFileTest, WhatTheMapsCannotTakeIsNamed) {
  std::string distorted = kRosYaml;
  distorted.replace(distorted.find("data: [0, 0, 0, 0, 0]"), 21, "data: [0.1, 0, 0, 0, 0]");
  for (const std::string& path :
       {Write("distorted.yaml", distorted), Write("empty.ini", "[CAMERA_PARAMS]\n"),
        Write("junk.yaml", "{{{ not yaml"), (dir_ / "missing.yaml").string()}) {
    try {
      ReadCameraFile(path);
      ADD_FAILURE() << path;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace novelty::sensors
