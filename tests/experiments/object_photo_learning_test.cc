#include "experiments/object_photo_learning.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "tests/maps/objects/blob_photo.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

TEST(ParseObjectPhotoSpec, NameFileAndBox) {
  const ObjectPhotoSpec a = ParseObjectPhotoSpec("cup=photos/cup.jpg@10,20,30,40");
  EXPECT_EQ(a.name, "cup");
  EXPECT_EQ(a.path, "photos/cup.jpg");
  ASSERT_TRUE(a.box);
  EXPECT_EQ(*a.box, cv::Rect(10, 20, 30, 40));
  EXPECT_EQ(ParseObjectPhotoSpec("photos/tea box.png").name, "tea box");
  EXPECT_FALSE(ParseObjectPhotoSpec("photos/tea box.png").box);
  EXPECT_EQ(ParseObjectPhotoSpec("photos/mugs/").name, "mugs");
  EXPECT_EQ(ParseObjectPhotoSpec("a=b=c.png").path, "b=c.png");
  for (const char* bad : {"=x.png", "cup=", "a=b@1,2,3", "a=b@1,2,0,4", "a=b@1,2,x,4",
                          "a=b@-1,2,3,4", "a=b@1,2,3,4,5", "a=b@", "a\tb=x.png"})
    EXPECT_THROW(ParseObjectPhotoSpec(bad), std::invalid_argument) << bad;
  const auto message = [](const std::string& spec) {
    try {
      ParseObjectPhotoSpec(spec);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("a=b@-1,2,3,4").find("corner X,Y must be >= 0"), std::string::npos);
  EXPECT_NE(message("a=b@1,2,3").find("four numbers X,Y,W,H (pixels), got 3"), std::string::npos);
  EXPECT_NE(message("a=b@1,2,0,4").find("width W and height H must be > 0"), std::string::npos);
  EXPECT_NE(message("a\nb=x.png").find("a name with a control character"), std::string::npos);
}

class ObjectPhotoLearning : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("object_photos_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "mugs");
    cv::imwrite((dir_ / "mugs" / "a.png").string(), objects::BlobPhoto({240, 180}, 1));
    cv::imwrite((dir_ / "mugs" / "b.png").string(), objects::BlobPhoto({200, 200}, 2));
    cv::Mat mask(200, 200, CV_8UC1, cv::Scalar(0));
    mask(cv::Rect(50, 60, 100, 80)).setTo(255);
    cv::imwrite((dir_ / "mugs" / "b.mask.png").string(), mask);
    cv::imwrite((dir_ / "box.png").string(), objects::BlobPhoto({160, 120}, 3));
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(ObjectPhotoLearning, AFolderIsOneObjectOfOneClassAPhoto) {
  mrpt_plugins::CObjectDatabaseMap map;
  ObjectPhotoLearningOptions o;
  o.objects = {ParseObjectPhotoSpec((dir_ / "mugs").string()),
               ParseObjectPhotoSpec("crate=" + (dir_ / "box.png").string() + "@20,10,100,90")};
  const auto learnt = LearnObjectPhotos(map, o);
  ASSERT_EQ(learnt.size(), 3u) << "the mask is no photo";
  const objects::FeatureDatabase& db = map.database();
  ASSERT_EQ(db.objects(), 3);
  EXPECT_EQ(db.DisplayName(0), "mugs");
  EXPECT_EQ(db.DisplayName(1), "mugs");
  EXPECT_EQ(db.DisplayName(2), "crate");
  // b.png's outline is its mask's rectangle (99 × 79 px between pixel centres, at 1 mm), the
  // crate's its box's.
  const auto extent = [&](int k) {
    Eigen::Vector2d hi(0, 0);
    for (const Eigen::Vector2d& p : db.Info(k).outline) hi = hi.cwiseMax(p);
    return hi;
  };
  EXPECT_NEAR(extent(1).x(), 0.099, 1e-9);
  EXPECT_NEAR(extent(1).y(), 0.079, 1e-9);
  EXPECT_NEAR(extent(2).x(), 0.099, 1e-9);
  EXPECT_NEAR(extent(2).y(), 0.089, 1e-9);
  EXPECT_NEAR(extent(0).x(), 0.239, 1e-9) << "a.png has no mask: the whole photo";
}

TEST_F(ObjectPhotoLearning, ErrorsNameTheFile) {
  mrpt_plugins::CObjectDatabaseMap map;
  ObjectPhotoLearningOptions o;
  const auto message = [&](const std::string& spec) {
    o.objects = {ParseObjectPhotoSpec(spec)};
    try {
      LearnObjectPhotos(map, o);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message((dir_ / "box.png").string() + "@100,100,100,100").find("box.png: the box"),
            std::string::npos);
  EXPECT_NE(message((dir_ / "none.png").string()).find("none.png"), std::string::npos);
  cv::imwrite((dir_ / "box.mask.png").string(), cv::Mat(10, 10, CV_8UC1, cv::Scalar(255)));
  EXPECT_NE(message((dir_ / "box.png").string()).find("box.mask.png is 10x10"), std::string::npos);
  EXPECT_NE(message((dir_ / "nosuch").string() + "/").find("no such photo or folder"),
            std::string::npos);
  cv::imwrite((dir_ / "box.mask.png").string(), [] {
    cv::Mat m(120, 160, CV_8UC1, cv::Scalar(0));
    m(cv::Rect(100, 80, 40, 30)).setTo(255);
    return m;
  }());
  EXPECT_NE(message((dir_ / "box.png").string() + "@0,0,50,50").find("select no common pixel"),
            std::string::npos);
  fs::create_directories(dir_ / "empty");
  EXPECT_NE(message((dir_ / "empty").string()).find("no photo of empty"), std::string::npos);
}

}  // namespace
}  // namespace novelty::experiments
