#include "maps/appearance/view_based_map.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::appearance {
namespace {

const core::PinholeCamera kCamera = core::PinholeCamera::FromFov(32, 24, 1.0);

// A wall 2 m in front of the camera; the payload plane holds (1, 2, 3) in half floats.
struct ViewFrame {
  cv::Mat depth = cv::Mat(24, 32, CV_32FC1, cv::Scalar(2.0f));
  cv::Mat payload;
  ViewFrame() { cv::Mat(24, 32, CV_32FC3, cv::Scalar(1, 2, 3)).convertTo(payload, CV_16F); }
};

cv::Mat Depth(float metres) {
  return cv::Mat(kCamera.height, kCamera.width, CV_32FC1, cv::Scalar(metres));
}
cv::Mat Plane(float value) {
  return cv::Mat(kCamera.height, kCamera.width, CV_32FC3, cv::Scalar::all(value));
}

Eigen::Isometry3d At(double x, double yaw_deg = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()).matrix();
  return T;
}

TEST(ViewBasedMap, AStaticCameraReadsItsViewsOwnPlanes) {
  ViewBasedMap map;
  const ViewFrame f;
  map.Update(kCamera, At(0), f.depth, {{"p", f.payload}}, {});
  const Prediction p = map.Predict(kCamera, At(0), {{"p", 3}});
  ASSERT_EQ(p.selected, std::vector<int>{0});
  EXPECT_EQ(p.value[0].data, map.store().view(0).planes.at("p").data) << "shared, not copied";
  EXPECT_EQ(p.value[0].type(), CV_16FC3);
  EXPECT_EQ(cv::countNonZero(p.valid), 32 * 24);
  EXPECT_FALSE(p.warped);
}

// A slanted wall Z = 2 + 0.25·X (camera frame of a view at the origin) seen from 2 cm to the
// right: there it is Z' = 2.005 + 0.25·X', so the pixel of normalised x' lies at depth
// 2.005 / (1 − 0.25·x') — the closed form the predicted depth must give where a view covers.
TEST(ViewBasedMap, APredictedDepthIsTheWarpedSurfacesDepthAndZeroWhereNothingCovers) {
  ViewBasedMap map;
  cv::Mat depth(kCamera.height, kCamera.width, CV_32FC1);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u)
      depth.at<float>(v, u) = float(2.0 / (1.0 - 0.25 * (u - kCamera.cx) / kCamera.fx));
  map.Update(kCamera, At(0), depth, {{"p", Plane(1)}}, {});
  const Prediction p = map.Predict(kCamera, At(0.02), {{"p", 3}}, /*with_depth=*/true);
  ASSERT_TRUE(p.warped);
  ASSERT_EQ(p.depth.type(), CV_32FC1);
  int covered = 0;
  for (int v = 0; v < p.depth.rows; ++v)
    for (int u = 0; u < p.depth.cols; ++u) {
      const float d = p.depth.at<float>(v, u);
      if (!p.valid.at<uchar>(v, u)) {
        EXPECT_EQ(d, 0.0f) << u << "," << v;
        continue;
      }
      ++covered;
      const double expected = 2.005 / (1.0 - 0.25 * (u - kCamera.cx) / kCamera.fx);
      EXPECT_NEAR(d, expected, 1e-3 * expected) << u << "," << v;
    }
  EXPECT_GT(covered, kCamera.width * kCamera.height / 2);
  EXPECT_TRUE(map.Predict(kCamera, At(0.02), {{"p", 3}}).depth.empty()) << "only when asked";
  const Prediction at_view = map.Predict(kCamera, At(0), {{"p", 3}}, true);
  EXPECT_EQ(cv::norm(at_view.depth, depth, cv::NORM_INF), 0.0) << "a static camera: the view's";
  const Prediction away = map.Predict(kCamera, At(0, 180), {{"p", 3}}, true);
  EXPECT_EQ(cv::countNonZero(away.depth), 0) << "nothing selected: no depth";
}

TEST(ViewBasedMap, APredictionNeverWritesIntoAViewsPlanes) {
  ViewBasedMap map;
  ViewFrame f;
  cv::Mat(24, 32, CV_32FC3, cv::Scalar(1, 2, 3)).copyTo(f.payload);  // the type of a prediction
  map.Update(kCamera, At(0), f.depth, {{"p", f.payload}}, {});
  const Prediction shared = map.Predict(kCamera, At(0), {{"p", 3}});
  ASSERT_EQ(shared.value[0].data, map.store().view(0).planes.at("p").data);
  const Prediction p = map.Predict(kCamera, At(0, 180), {{"p", 3}});  // facing away
  EXPECT_TRUE(p.selected.empty());
  EXPECT_TRUE(std::isnan(p.value[0].at<cv::Vec3f>(5, 5)[0]));
  EXPECT_EQ(map.store().view(0).planes.at("p").at<cv::Vec3f>(5, 5), cv::Vec3f(1, 2, 3))
      << "the view's plane must survive";
}

TEST(ViewBasedMap, ADeferredPredictionBlendedRowsAtATimeEqualsPredict) {
  // Two views turned 15° left and right with irregular payloads, seen from between them: the
  // left rays pick one, the right ones the other; both warped and blended.
  ViewBasedMapOptions options;
  options.new_view_distance = 0.1;
  ViewBasedMap map(options);
  cv::RNG rng(3);
  for (const auto& [x, yaw] : std::vector<std::pair<double, double>>{{-0.05, -15}, {0.05, 15}}) {
    ViewFrame f;
    cv::Mat values(24, 32, CV_32FC3);
    rng.fill(values, cv::RNG::UNIFORM, 0.0, 100.0);
    values.convertTo(f.payload, CV_16F);
    cv::Mat tau(24, 32, CV_32FC1);
    rng.fill(tau, cv::RNG::UNIFORM, 0.0, 100.0);
    map.Update(kCamera, At(x, yaw), f.depth, {{"p", f.payload}, {"q", tau}}, {});
  }
  const std::vector<std::pair<std::string, int>> names = {{"p", 3}, {"q", 1}};
  const Prediction whole = map.Predict(kCamera, At(0.0), names);
  ASSERT_EQ(whole.selected.size(), 2u);
  const std::vector<cv::Mat> expected = {whole.value[0].clone(), whole.value[1].clone()};
  const cv::Mat expected_valid = whole.valid.clone();
  EXPECT_GT(cv::countNonZero(expected_valid), 32 * 20);
  const Prediction deferred = map.PredictDeferred(kCamera, At(0.0), names);
  for (const cv::Range rows : {cv::Range(16, 24), cv::Range(0, 5), cv::Range(5, 16)}) {
    deferred.BlendRows(rows);
  }
  for (std::size_t k = 0; k < names.size(); ++k) {
    // Bit for bit, NaN (uncovered) where the whole prediction has NaN.
    cv::Mat a = deferred.value[k].clone(), b = expected[k].clone();
    const cv::Mat a_nan = a.reshape(1) != a.reshape(1), b_nan = b.reshape(1) != b.reshape(1);
    EXPECT_EQ(cv::norm(a_nan, b_nan, cv::NORM_INF), 0.0) << names[k].first;
    cv::patchNaNs(a, -1.0);
    cv::patchNaNs(b, -1.0);
    EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << names[k].first;
  }
  EXPECT_EQ(cv::norm(deferred.valid, expected_valid, cv::NORM_INF), 0.0);
  // A static camera's prediction comes complete: nothing to blend.
  const Prediction at_view = map.PredictDeferred(kCamera, At(0.05, 15), names);
  EXPECT_EQ(at_view.value[1].data, map.store().view(1).planes.at("q").data);
  EXPECT_TRUE(at_view.complete());
  at_view.BlendRows(cv::Range(0, 24));  // a no-op
  EXPECT_EQ(cv::countNonZero(at_view.valid), 32 * 24);
  EXPECT_FALSE(deferred.complete());
  EXPECT_TRUE(whole.complete());
}

// The prior is a value: a deferred prediction blended after the map has moved on (a newer
// prediction made, the views it used replaced) gives what it would have given at once.
TEST(ViewBasedMap, AHeldPredictionOutlivesTheMapsNextFrame) {
  ViewBasedMap map;
  const std::vector<std::pair<std::string, int>> names = {{"p", 3}};
  map.Update(kCamera, At(0.0), Depth(1.0), {{"p", Plane(1.0f)}}, {});
  map.Update(kCamera, At(0.05, 15), Depth(1.0), {{"p", Plane(2.0f)}}, {});
  const cv::Mat expected = map.Predict(kCamera, At(0.02), names).value[0].clone();
  const Prediction held = map.PredictDeferred(kCamera, At(0.02), names);
  ASSERT_FALSE(held.complete());
  // The map moves on: a prediction elsewhere, then both views replaced by other values.
  const Prediction next = map.PredictDeferred(kCamera, At(0.04), names);
  next.BlendRows(cv::Range(0, kCamera.height));
  map.Update(kCamera, At(0.0), Depth(1.0), {{"p", Plane(7.0f)}}, {0});
  map.Update(kCamera, At(0.05, 15), Depth(1.0), {{"p", Plane(9.0f)}}, {1});
  held.BlendRows(cv::Range(0, kCamera.height));
  cv::Mat a = held.value[0].clone(), b = expected.clone();
  cv::patchNaNs(a, -1.0);
  cv::patchNaNs(b, -1.0);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_NE(held.value[0].data, next.value[0].data);
}

TEST(ViewBasedMap, AViewKeepsThePlanGivenWithItUnlessMadeForOtherOptions) {
  // The plan decides which quads a warp draws. A wall's depth given with the plan of a depth
  // without surface draws nothing — the plan is kept and used; the same plan made with other
  // block options is made anew from the wall, which then covers the frame.
  const ViewFrame f;
  const cv::Mat no_surface(24, 32, CV_32FC1, cv::Scalar(0.0f));
  const views::WarpOptions map_warp = ViewBasedMapOptions{}.warp;
  for (const int block : {map_warp.planar_block, map_warp.planar_block / 2}) {
    ViewBasedMap map;
    views::WarpOptions plan_options = map_warp;
    plan_options.planar_block = block;
    map.Update(kCamera, At(0), f.depth, {{"p", f.payload}}, {},
               views::MeshPlanFor(no_surface, plan_options));
    const Prediction p = map.Predict(kCamera, At(0.02), {{"p", 3}});  // warped
    ASSERT_EQ(p.selected, std::vector<int>{0});
    EXPECT_TRUE(p.warped);
    if (block == map_warp.planar_block) {
      EXPECT_EQ(cv::countNonZero(p.valid), 0) << "the plan given was not used";
    } else {
      EXPECT_GT(cv::countNonZero(p.valid), 32 * 20) << "a plan for other options was used";
    }
  }
}

TEST(ViewBasedMap, FarFramesAddViewsNearOnesReplaceTheSelected) {
  ViewBasedMapOptions options;
  options.new_view_distance = 0.1;
  ViewBasedMap map(options);
  const ViewFrame f;
  EXPECT_TRUE(map.Update(kCamera, At(0), f.depth, {{"p", f.payload}}, {}).added);
  EXPECT_TRUE(map.Update(kCamera, At(0.2), f.depth, {{"p", f.payload}}, {0}).added);
  const ViewBasedMap::UpdateResult r =
      map.Update(kCamera, At(0.05), f.depth, {{"p", f.payload}}, {1});
  EXPECT_FALSE(r.added);
  EXPECT_EQ(r.view, 1);  // the selected view, moved to the frame's pose; its anchor stays
  EXPECT_EQ(map.store().size(), 2);
  EXPECT_NEAR(map.store().view(1).T_world_cam.translation().x(), 0.05, 1e-12);
  EXPECT_NEAR(map.anchors()[1].translation().x(), 0.2, 1e-12);
}

}  // namespace
}  // namespace novelty::appearance
