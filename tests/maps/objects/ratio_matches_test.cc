#include "maps/objects/ratio_matches.h"

#include <gtest/gtest.h>

namespace novelty::objects {
namespace {

cv::Mat Descriptor(int seed, float noise = 0.0f, const cv::Mat& base = cv::Mat()) {
  cv::Mat d(1, 64, CV_32F);
  cv::RNG rng(seed);
  if (base.empty())
    rng.fill(d, cv::RNG::NORMAL, 0.0, 1.0);
  else {
    rng.fill(d, cv::RNG::NORMAL, 0.0, noise);
    d += base;
  }
  return d;
}

cv::KeyPoint At(float x, float y) {
  return cv::KeyPoint(cv::Point2f(x, y), 20.0f);
}

TEST(RatioMatches, TheSecondOfAnotherPlaceIgnoresDuplicatesOfTheNearestsBlob) {
  const cv::Mat reference = Descriptor(1);
  cv::Mat candidates;
  candidates.push_back(Descriptor(2, 0.05f, reference));  // the match
  candidates.push_back(Descriptor(3, 0.07f, reference));  // the same blob, 2 px away
  candidates.push_back(Descriptor(4));                    // something else, far away
  const std::vector<cv::KeyPoint> places = {At(10, 10), At(12, 10), At(100, 100)};
  // The thesis's test compares with the duplicate and rejects the match.
  EXPECT_TRUE(RatioMatches(reference, candidates, 0.65).empty());
  const std::vector<RatioMatch> m = RatioMatches(reference, candidates, 0.65, places);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].candidate, 0);
  // A look-alike at another place (30 px, beyond the radius 10) is a real ambiguity: rejected.
  const std::vector<cv::KeyPoint> apart = {At(10, 10), At(40, 10), At(100, 100)};
  EXPECT_TRUE(RatioMatches(reference, candidates, 0.65, apart).empty());
}

TEST(RatioMatches, CandidatesAllAtOnePlaceLeaveNothingToConfuseAndBadInputThrows) {
  const cv::Mat reference = Descriptor(1);
  cv::Mat candidates;
  candidates.push_back(Descriptor(2, 0.05f, reference));
  candidates.push_back(Descriptor(3, 0.07f, reference));
  EXPECT_EQ(RatioMatches(reference, candidates, 0.65, {At(10, 10), At(11, 11)}).size(), 1u);
  EXPECT_THROW(RatioMatches(reference, candidates, 0.65, {At(10, 10)}), std::invalid_argument);
  EXPECT_TRUE(RatioMatches(reference, candidates.row(0), 0.65, {At(10, 10)}).empty())
      << "a single candidate passes no ratio test";
}

TEST(NearestMatches, GivesEachReferenceItsKNearestInOrderWithoutARatioTest) {
  cv::Mat reference;
  reference.push_back(Descriptor(1));
  reference.push_back(Descriptor(5));
  cv::Mat candidates;
  candidates.push_back(Descriptor(4));                                   // unrelated
  candidates.push_back(Descriptor(3, 0.07f, reference.row(0).clone()));  // the blob again
  candidates.push_back(Descriptor(2, 0.05f, reference.row(0).clone()));  // the match
  const std::vector<RatioMatch> m = NearestMatches(reference, candidates, 2);
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0].reference, 0);
  EXPECT_EQ(m[0].candidate, 2) << "nearest first";
  EXPECT_EQ(m[1].candidate, 1);
  EXPECT_LE(m[0].distance, m[1].distance);
  EXPECT_NEAR(m[0].distance, cv::norm(reference.row(0), candidates.row(2)), 1e-4);
  EXPECT_EQ(m[2].reference, 1);
  EXPECT_LE(m[2].distance, m[3].distance);
  // The ratio test rejects the match the nearest pairs keep.
  EXPECT_TRUE(RatioMatches(reference.row(0), candidates, 0.65).empty());
  EXPECT_EQ(NearestMatches(reference, candidates.row(2), 3).size(), 2u) << "fewer candidates";
  EXPECT_TRUE(NearestMatches(cv::Mat(), candidates, 2).empty());
  EXPECT_THROW(NearestMatches(reference, candidates, 0), std::invalid_argument);
  EXPECT_THROW(NearestMatches(reference, cv::Mat::ones(3, 32, CV_32F), 1), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
