#include "eval/matches_on_object.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "core/nearest_pixel.h"
#include "maps/objects/ratio_matches.h"

namespace novelty::eval {

MatchesOnObject MatchOnObject(const objects::FeatureDatabase& database, int object,
                              const objects::FrameFeatures& frame, const cv::Mat& on_object,
                              int margin_px, double ratio) {
  if (on_object.empty() || on_object.type() != CV_8UC1)
    throw std::invalid_argument("MatchOnObject: the object's mask must be a CV_8U image");
  if (object < 0 || object >= database.objects())
    throw std::invalid_argument("MatchOnObject: object " + std::to_string(object) +
                                " is not in the database of " + std::to_string(database.objects()));
  if (margin_px < 0)
    throw std::invalid_argument("MatchOnObject: margin_px must be >= 0, got " +
                                std::to_string(margin_px));
  if (int(frame.keypoints.size()) != frame.descriptors.rows)
    throw std::invalid_argument("MatchOnObject: " + std::to_string(frame.keypoints.size()) +
                                " keypoints for " + std::to_string(frame.descriptors.rows) +
                                " descriptors");
  if (frame.descriptors.rows > 0 && database.features() > 0 &&
      frame.descriptors.cols != database.descriptors().cols)
    throw std::invalid_argument("MatchOnObject: the frame's descriptors have width " +
                                std::to_string(frame.descriptors.cols) + ", the database's " +
                                std::to_string(database.descriptors().cols));

  cv::Mat near_object = on_object != 0;
  if (margin_px > 0)
    cv::dilate(near_object, near_object,
               cv::getStructuringElement(cv::MORPH_ELLIPSE,
                                         cv::Size(2 * margin_px + 1, 2 * margin_px + 1)));
  cv::Mat descriptors;
  for (std::size_t i = 0; i < frame.keypoints.size(); ++i) {
    const std::optional<cv::Point> p =
        core::NearestPixel(frame.keypoints[i].pt, near_object.size());
    if (p && near_object.at<uchar>(*p)) descriptors.push_back(frame.descriptors.row(int(i)));
  }

  MatchesOnObject out;
  out.keypoints = descriptors.rows;
  out.matches = database.Match(descriptors, ratio).matches_per_object[std::size_t(object)];
  double sum = 0.0;
  int n = 0;
  for (const objects::RatioMatch& m :
       objects::NearestMatches(database.descriptors(), descriptors, 1))
    if (database.MostProbableObject(m.reference) == object) sum += m.distance, ++n;
  out.mean_nearest_distance = n ? sum / n : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace novelty::eval
