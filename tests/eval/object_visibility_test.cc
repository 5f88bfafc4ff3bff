#include "eval/object_visibility.h"

#include <gtest/gtest.h>

namespace novelty::eval {
namespace {

TEST(ObjectVisibility, CountsPixelsAndFindsTheAddedObjectsBox) {
  cv::Mat ids(60, 80, CV_32SC1, cv::Scalar(0)), novelty(60, 80, CV_8UC1, cv::Scalar(0));
  ids(cv::Rect(10, 5, 20, 10)).setTo(3);  // object 3, 200 px, added
  novelty(cv::Rect(10, 5, 20, 10)).setTo(255);
  ids(cv::Rect(50, 30, 5, 4)).setTo(4);  // object 4, 20 px, added
  novelty(cv::Rect(50, 30, 5, 4)).setTo(255);
  ids(cv::Rect(0, 40, 30, 20)).setTo(7);     // object 7, 600 px, there from the start
  ids(cv::Rect(60, 0, 10, 10)).setTo(1000);  // the arm, 100 px (novelty 255 too)
  novelty(cv::Rect(60, 0, 10, 10)).setTo(255);
  EXPECT_EQ(VisiblePixels(ids, 3), 200);
  EXPECT_EQ(VisiblePixels(ids, 7), 600);
  EXPECT_EQ(VisiblePixels(ids, 9), 0);
  const NewObjectView v = NewObjectInView(ids, novelty, 1000, 255);
  EXPECT_EQ(v.id, 3);
  EXPECT_EQ(v.pixels, 200);
  EXPECT_EQ(v.box, cv::Rect(10, 5, 20, 10));
  EXPECT_EQ(v.arm_pixels, 100);
}

TEST(ObjectVisibility, NoAddedObjectAndBadInput) {
  const cv::Mat ids(10, 10, CV_32SC1, cv::Scalar(2)), novelty(10, 10, CV_8UC1, cv::Scalar(0));
  EXPECT_EQ(NewObjectInView(ids, novelty, 1000, 255).id, -1);
  EXPECT_THROW(NewObjectInView(ids, cv::Mat(9, 10, CV_8UC1), 1000, 255), std::invalid_argument);
  EXPECT_THROW(VisiblePixels(cv::Mat(3, 3, CV_8UC1), 1), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
