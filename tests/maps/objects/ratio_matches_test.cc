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

}  // namespace
}  // namespace novelty::objects
