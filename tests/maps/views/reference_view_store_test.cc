#include "maps/views/reference_view_store.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace novelty::views {
namespace {

ReferenceView View() {
  ReferenceView v;
  v.camera = core::PinholeCamera::FromFov(32, 24, 1.0);
  v.depth = cv::Mat(24, 32, CV_32FC1, cv::Scalar(1));
  v.planes["rgb"] = cv::Mat(24, 32, CV_8UC3, cv::Scalar::all(0));
  v.planes["tau"] = cv::Mat(24, 32, CV_16FC3);
  return v;
}

TEST(ReferenceViewStore, StoresChecksAndCountsBytes) {
  ReferenceViewStore store;
  EXPECT_EQ(store.Add(View()), 0);
  EXPECT_EQ(store.Add(View()), 1);
  // depth 4 B + rgb 3 B + tau 3 × 2 B per pixel
  EXPECT_EQ(store.BytesUsed(), 2u * 32 * 24 * (4 + 3 + 6));
  ReferenceView bad = View();
  bad.planes["beta"] = cv::Mat(10, 10, CV_32FC1);
  try {
    store.Add(bad);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("plane 'beta'"), std::string::npos) << e.what();
  }
  ReferenceView sheared = View();
  sheared.T_world_cam.linear()(0, 1) = 0.5;
  EXPECT_THROW(store.Replace(1, sheared), std::invalid_argument);
  ReferenceView wrong_depth = View();
  wrong_depth.depth = cv::Mat(24, 32, CV_16UC1);
  EXPECT_THROW(store.Add(wrong_depth), std::invalid_argument);
  EXPECT_THROW(store.Replace(5, View()), std::out_of_range);
  EXPECT_EQ(store.size(), 2);
}

TEST(ReferenceViewStore, AFrameWithAPoseBecomesAView) {
  core::Frame f;
  f.index = 7;
  f.camera = core::PinholeCamera::FromFov(32, 24, 1.0);
  f.depth = cv::Mat(24, 32, CV_32FC1, cv::Scalar(2));
  f.rgb = cv::Mat(24, 32, CV_8UC3, cv::Scalar(1, 2, 3));
  try {
    ReferenceViewOf(f);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "frame 7: no pose, cannot become a reference view");
  }
  f.T_world_cam = Eigen::Isometry3d(Eigen::Translation3d(1, 2, 3));
  const ReferenceView v = ReferenceViewOf(f, "image");
  EXPECT_NO_THROW(v.Check("view"));
  EXPECT_EQ(v.T_world_cam.translation(), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(v.planes.at("image").data, f.rgb.data);  // shared, not copied
  EXPECT_EQ(v.depth.data, f.depth.data);
}

// A compact store keeps the views used last decoded and the others encoded; a view comes back
// decoded with its values rounded as plane_codec.h says, and the views a caller still uses are
// never evicted.
TEST(ReferenceViewStore, ACompactStoreHoldsTheViewsUsedLastDecoded) {
  ReferenceViewStoreOptions o;
  o.decoded_views = 2;
  ReferenceViewStore compact(o), plain;
  for (int j = 0; j < 5; ++j) {
    ReferenceView v = View();
    v.planes["tau"] = cv::Mat(24, 32, CV_32FC3);
    cv::randu(v.planes["tau"], 0, 255);
    v.T_world_cam.translation().x() = 0.1 * j;
    plain.Add(v);
    compact.Add(v);
    EXPECT_EQ(compact.Trim({0}), j >= 2 && j != 0 ? std::vector<int>{j - 1} : std::vector<int>{})
        << j;
  }
  // View 0 was kept at every Trim; 4 is the last added; 1, 2, 3 are encoded.
  for (int j = 0; j < 5; ++j) EXPECT_EQ(compact.decoded(j), j == 0 || j == 4) << j;
  EXPECT_LT(compact.BytesUsed(), plain.BytesUsed());
  EXPECT_NEAR(compact.pose(2).translation().x(), 0.2, 1e-15);  // geometry stays decoded
  const ReferenceView copy = compact.Decoded(2);               // decoded, but not into the cache
  EXPECT_FALSE(compact.decoded(2));
  const cv::Mat& tau = compact.view(2).planes.at("tau");  // now in the cache
  EXPECT_TRUE(compact.decoded(2));
  EXPECT_EQ(cv::norm(copy.planes.at("tau"), tau, cv::NORM_INF), 0.0);
  EXPECT_LE(cv::norm(tau, plain.view(2).planes.at("tau"), cv::NORM_INF), 255.0 / 32768);
  EXPECT_EQ(
      cv::norm(compact.view(2).planes.at("rgb"), plain.view(2).planes.at("rgb"), cv::NORM_INF),
      0.0);  // integers exactly
  // Encoded twice, the same bytes: an evicted view that did not change is not encoded again.
  EXPECT_EQ(compact.Encoded(2).planes.at("tau").bytes, compact.Encoded(2).planes.at("tau").bytes);
  EXPECT_EQ(compact.Trim({2}).size(), 1u);  // three decoded (0, 2, 4): the oldest but 2 goes
  EXPECT_TRUE(compact.decoded(2));
  EXPECT_EQ(plain.Trim(), std::vector<int>{});  // not compact: nothing is ever evicted
}

}  // namespace
}  // namespace novelty::views
