#include "maps/objects/feature_database.h"

#include <gtest/gtest.h>

#include <cmath>

#include "maps/objects/ratio_matches.h"

namespace novelty::objects {
namespace {

// n random unit descriptors of width 64, far apart from each other (random directions in 64-D).
cv::Mat Descriptors(int n, unsigned seed) {
  cv::Mat d(n, 64, CV_32F);
  cv::RNG(seed).fill(d, cv::RNG::NORMAL, 0.0, 1.0);
  for (int i = 0; i < n; ++i) cv::normalize(d.row(i), d.row(i));
  return d;
}

// `d` with each row moved by noise of standard deviation `sigma` per component.
cv::Mat Perturbed(const cv::Mat& d, double sigma, unsigned seed) {
  cv::Mat noise(d.size(), CV_32F);
  cv::RNG(seed).fill(noise, cv::RNG::NORMAL, 0.0, sigma);
  return d + noise;
}

TEST(RatioMatches, NearestWithinTheRatioOnly) {
  cv::Mat candidates = Descriptors(3, 1);
  cv::Mat reference(3, 64, CV_32F);
  candidates.row(0).copyTo(reference.row(0));  // exact: d1 = 0
  reference.row(1) = 0.5f * (candidates.row(1) + candidates.row(2));  // halfway: d1 ≈ d2
  Descriptors(1, 2).copyTo(reference.row(2));  // unrelated: d1 ≈ d2
  const std::vector<RatioMatch> m = RatioMatches(reference, candidates, 0.65);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].reference, 0);
  EXPECT_EQ(m[0].candidate, 0);
  EXPECT_TRUE(RatioMatches(reference, candidates.row(0), 0.65).empty()) << "one candidate";
  EXPECT_THROW(RatioMatches(reference, candidates, 0.0), std::invalid_argument);
  EXPECT_THROW(RatioMatches(reference, candidates.colRange(0, 32).clone(), 0.65),
               std::invalid_argument);
}

TEST(FeatureDatabase, CountsFollowEquations53To57) {
  FeatureDatabase db;
  const cv::Mat cup = Descriptors(10, 3), box = Descriptors(6, 4);
  const int c0 = db.AddObject(), c1 = db.AddObject();
  db.AddFeatures(cup, c0);  // eq. 5.6
  db.AddFeatures(box, c1);
  EXPECT_EQ(db.features(), 16);
  EXPECT_EQ(db.Count(0, c0), 1);
  EXPECT_EQ(db.Count(0, c1), 0);
  EXPECT_DOUBLE_EQ(db.RelativeFrequency(12, c1), 1.0);  // eq. 5.3
  EXPECT_EQ(db.MostProbableObject(12), c1);

  // A view of the cup: 7 of its features (slightly changed) and 5 clutter features.
  cv::Mat selected;
  selected.push_back(Perturbed(cup.rowRange(0, 7), 0.02, 5));
  selected.push_back(Descriptors(5, 6));
  const FeatureDatabase::Recognition r = db.Recognize(selected);
  EXPECT_EQ(r.matches_per_object, (std::vector<int>{7, 0}));  // N_k
  EXPECT_EQ(r.object, c0);                                     // eq. 5.4
  for (const RatioMatch& m : r.matches) EXPECT_EQ(m.candidate, m.reference);
  for (int h = 0; h < 7; ++h) EXPECT_EQ(db.Count(h, c0), 2) << "n_{h,M} += 1 per match";
  for (int h = 7; h < 10; ++h) EXPECT_EQ(db.Count(h, c0), 1);

  // Learnt on a recognised object (eq. 5.7): n = 1 for c.
  db.AddFeatures(Descriptors(2, 7), r.object);
  EXPECT_EQ(db.Count(16, c0), 1);
  EXPECT_EQ(db.Count(17, c1), 0);

  // Nothing known in view: every N_k = 0, no object.
  const FeatureDatabase::Recognition none = db.Recognize(Descriptors(8, 8));
  EXPECT_EQ(none.object, -1);
  EXPECT_EQ(none.matches_per_object, (std::vector<int>{0, 0}));
}

TEST(FeatureDatabase, BadUseIsRejected) {
  FeatureDatabase db;
  EXPECT_THROW(db.AddFeatures(Descriptors(2, 1), 0), std::invalid_argument) << "no object 0";
  db.AddObject();
  db.AddFeatures(Descriptors(2, 1), 0);
  EXPECT_THROW(db.AddFeatures(Descriptors(2, 1).colRange(0, 32).clone(), 0),
               std::invalid_argument);
  EXPECT_THROW(db.Count(2, 0), std::out_of_range);
  EXPECT_EQ(db.Recognize(cv::Mat()).object, -1);
  EXPECT_THROW(db.AddFeatures(Descriptors(2, 1), 0, {Eigen::Vector3d::Zero()}),
               std::invalid_argument)
      << "one position for two features";
  EXPECT_THROW(db.AddFeatures(Descriptors(2, 1), 0, {}, {LearntKeypoint()}), std::invalid_argument)
      << "one keypoint for two features";
}

// Tally counts N_k and c of eq. 5.4 as Match does, for any subset of its matches.
TEST(FeatureDatabase, TallyCountsASubsetOfMatchesAsMatchDoes) {
  FeatureDatabase db;
  const cv::Mat cup = Descriptors(5, 3), box = Descriptors(4, 4);
  db.AddFeatures(cup, db.AddObject());
  db.AddFeatures(box, db.AddObject());
  cv::Mat seen;
  cv::vconcat(Perturbed(cup.rowRange(0, 2), 0.02, 5), Perturbed(box.rowRange(0, 3), 0.02, 6), seen);
  const FeatureDatabase::Recognition all = db.Match(seen);
  ASSERT_EQ(all.matches_per_object, std::vector<int>({2, 3}));
  EXPECT_EQ(all.object, 1);
  const FeatureDatabase::Recognition same = db.Tally(all.matches);
  EXPECT_EQ(same.matches_per_object, all.matches_per_object);
  EXPECT_EQ(same.object, 1);
  std::vector<RatioMatch> cup_only;
  for (const RatioMatch& m : all.matches)
    if (m.reference < 5) cup_only.push_back(m);
  const FeatureDatabase::Recognition subset = db.Tally(cup_only);
  EXPECT_EQ(subset.matches_per_object, std::vector<int>({2, 0}));
  EXPECT_EQ(subset.object, 0);
  EXPECT_EQ(db.Tally({}).object, -1);
}

// A database rebuilt from its parts (what a map file holds) is the same database, and parts that
// cannot belong together are refused.
TEST(FeatureDatabase, RebuiltFromItsPartsItIsTheSame) {
  FeatureDatabase db;
  const cv::Mat cup = Descriptors(5, 3);
  db.AddFeatures(cup, db.AddObject(), {{0, 0, 1}, {0, 0.1, 1}, {0.1, 0, 1}, {0, 0, 1.1}, {1, 1, 1}});
  db.AddFeatures(Descriptors(3, 4), db.AddObject());
  db.Recognize(Perturbed(cup.rowRange(0, 3), 0.02, 5));
  const FeatureDatabase copy = FeatureDatabase::FromParts(
      db.objects(), db.descriptors(), db.counts(),
      {db.Position(0), db.Position(1), db.Position(2), db.Position(3), db.Position(4),
       db.Position(5), db.Position(6), db.Position(7)});
  EXPECT_EQ(copy.objects(), 2);
  EXPECT_EQ(cv::norm(copy.descriptors(), db.descriptors(), cv::NORM_INF), 0.0);
  for (int h = 0; h < 8; ++h)
    for (int k = 0; k < 2; ++k) EXPECT_EQ(copy.Count(h, k), db.Count(h, k)) << h << "," << k;
  EXPECT_EQ(copy.Count(0, 0), 2);
  EXPECT_EQ(copy.Position(1), Eigen::Vector3d(0, 0.1, 1));
  EXPECT_TRUE(std::isnan(copy.Position(6).x())) << "learnt without a position";
  EXPECT_TRUE(std::isnan(copy.Keypoint(6).angle_deg)) << "rebuilt without keypoints";
  LearntKeypoint k;
  k.angle_deg = 30;
  k.size_m = 0.02;
  const FeatureDatabase with =
      FeatureDatabase::FromParts(1, Descriptors(1, 9), {{{0, 1}}}, {Eigen::Vector3d::Zero()}, {k});
  EXPECT_EQ(with.Keypoint(0).angle_deg, 30);
  EXPECT_EQ(with.Keypoint(0).size_m, 0.02);
  EXPECT_THROW(FeatureDatabase::FromParts(1, Descriptors(1, 9), {{{0, 1}}},
                                          {Eigen::Vector3d::Zero()}, {k, k}),
               std::invalid_argument)
      << "two keypoints for one feature";
  for (const auto& [angle, size] :
       {std::pair<double, double>{-1, 0.02}, {360, 0.02}, {30, 0}, {30, -0.1}, {30, INFINITY}}) {
    k.angle_deg = angle;
    k.size_m = size;
    EXPECT_THROW(FeatureDatabase::FromParts(1, Descriptors(1, 9), {{{0, 1}}},
                                            {Eigen::Vector3d::Zero()}, {k}),
                 std::invalid_argument)
        << angle << " deg, " << size << " m";
    FeatureDatabase direct;
    EXPECT_THROW(direct.AddFeatures(Descriptors(1, 9), direct.AddObject(), {}, {k}),
                 std::invalid_argument)
        << angle << " deg, " << size << " m";
  }

  const std::vector<Eigen::Vector3d> one(1, Eigen::Vector3d::Zero());
  const cv::Mat d = Descriptors(1, 9);
  EXPECT_THROW(FeatureDatabase::FromParts(1, d, {{{1, 1}}}, one), std::invalid_argument)
      << "object 1 of 1";
  EXPECT_THROW(FeatureDatabase::FromParts(1, d, {{{0, 0}}}, one), std::invalid_argument)
      << "a zero count";
  EXPECT_THROW(FeatureDatabase::FromParts(1, d, {{}}, one), std::invalid_argument) << "no owner";
  EXPECT_THROW(FeatureDatabase::FromParts(1, d, {{{0, (1 << 30) + 1}}}, one), std::invalid_argument)
      << "a count no run gives (and sums of which would overflow)";
  EXPECT_THROW(FeatureDatabase::FromParts(1, d, {}, one), std::invalid_argument) << "no counts";
  EXPECT_THROW(FeatureDatabase::FromParts(2, d, {{{0, 3}, {0, 2}}}, one), std::invalid_argument)
      << "one object counted twice";
  cv::Mat nan = d.clone();
  nan.at<float>(0, 3) = std::nanf("");
  EXPECT_THROW(FeatureDatabase::FromParts(1, nan, {{{0, 1}}}, one), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
