#include "maps/illumination/illumination_novelty.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "maps/illumination/missing_texture.h"
#include "maps/stats/tail_information.h"

namespace novelty::illumination {

namespace {

// Connected regions of a binary image with at least `min_pixels` pixels.
std::vector<StoredShape> Regions(const cv::Mat& binary, int min_pixels) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(binary, labels, stats, centroids, 8, CV_32S);
  std::vector<StoredShape> out;
  for (int i = 1; i < n; ++i) {
    if (stats.at<int>(i, cv::CC_STAT_AREA) < min_pixels) continue;
    const cv::Rect box(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                       stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
    out.push_back({box, labels(box) == i, {}});
  }
  return out;
}

// The part of `shape` inside `window` (image coordinates), as a mask of window's size.
cv::Mat Within(const StoredShape& shape, const cv::Rect& window) {
  cv::Mat out = cv::Mat::zeros(window.size(), CV_8U);
  const cv::Rect common = shape.box & window;
  if (!common.empty()) shape.mask(common - shape.box.tl()).copyTo(out(common - window.tl()));
  return out;
}

struct ShapeMatch {
  double distance = 0.0;  // e of steps 3c-d
  double empty = 0.0;     // the region's distance to the empty shape, |d'|
  cv::Rect window;        // BB_I of the best match
  bool matched = false;   // a stored shape explains the region better than none
};

// Steps 3a-c for one region: the stored shape whose descriptor inside the intersection of the
// two boxes is nearest the region's there. No stored shape in the window is a shape too — the
// empty one, whose descriptor is 0: a region unlike anything stored keeps e = |d'|.
ShapeMatch BestMatch(const StoredShape& region, const std::vector<StoredShape>& stored_shapes,
                     const ZernikeMoments& zernike, double min_share) {
  const std::vector<float> own = zernike.Magnitudes(region.mask);
  const double empty = DescriptorDistance(own, std::vector<float>(own.size(), 0.0f));
  ShapeMatch best{empty, empty, region.box, false};
  const int region_pixels = cv::countNonZero(region.mask);
  for (const StoredShape& stored : stored_shapes) {
    const cv::Rect window = region.box & stored.box;  // BB_I (step 3a)
    if (window.empty()) continue;
    const cv::Mat mine = Within(region, window), theirs = Within(stored, window);
    if (cv::countNonZero(mine) < std::max(1.0, min_share * region_pixels) ||
        cv::countNonZero(theirs) < std::max(1.0, min_share * cv::countNonZero(stored.mask)))
      continue;
    // Steps 3b-c; a window that is either shape's own box reuses its descriptor.
    const bool stored_whole =
        window == stored.box && stored.descriptor.size() == size_t(zernike.size());
    const double distance =
        DescriptorDistance(window == region.box ? own : zernike.Magnitudes(mine),
                           stored_whole ? stored.descriptor : zernike.Magnitudes(theirs));
    if (distance < best.distance) best = {distance, empty, window, true};
  }
  return best;
}

}  // namespace

ViewpointIllumination MakeViewpoint(const InvariantImage& invariant, IlluminationModel model,
                                    int min_region_pixels, const ZernikeMoments* zernike) {
  ViewpointIllumination v;
  v.log_invariant = invariant.log_invariant;
  v.covered = invariant.covered;
  for (const cv::Mat& s : model.shapes) {
    auto regions = Regions(s, min_region_pixels);
    if (zernike)
      for (StoredShape& r : regions) r.descriptor = zernike->Magnitudes(r.mask);
    v.shapes.insert(v.shapes.end(), regions.begin(), regions.end());
  }
  v.model = std::move(model);
  return v;
}

IlluminationNovelty DetectIlluminationNovelty(const cv::Mat& image,
                                              const ViewpointIllumination& viewpoint,
                                              const ZernikeMoments& zernike,
                                              const IlluminationNoveltyOptions& options) {
  if (viewpoint.model.luminance.alpha <= 0.0)
    throw std::invalid_argument("DetectIlluminationNovelty: the viewpoint has no gamma model");
  // Steps 1-2: illumination image, information, regions above T_Y.
  const cv::Mat log_l =
      LogIllumination(image, viewpoint.log_invariant, options.min_intensity);  // eq. 6.19
  const IlluminationComponents c = ComputeIlluminationComponents(log_l);
  const IlluminationModel& model = viewpoint.model;
  IlluminationNovelty out;
  out.information_y = InformationMap(c.luminance, model.luminance_step, model.luminance);
  out.information_s = c.saturation.empty() || model.saturation.alpha <= 0.0
                          ? cv::Mat::zeros(image.size(), CV_32F)
                          : InformationMap(c.saturation, model.saturation_step, model.saturation);
  if (!model.texture.empty()) {
    if (model.texture_scale.size() != image.size() || model.texture_scale.type() != CV_32FC1)
      throw std::invalid_argument(
          "DetectIlluminationNovelty: the model's missing texture has no CV_32FC1 scale of the "
          "image's size");
    MissingTextureOptions texture;
    texture.block = model.texture_block;
    const cv::Mat hidden =
        cv::max(HiddenTextureShare(log_l + viewpoint.log_invariant, viewpoint.log_invariant,
                                   viewpoint.covered, model.texture_floor, texture),
                0.0f);
    out.information_t = hidden / model.texture_scale;
    out.information_t.forEach<float>(
        [&](float& u, const int*) { u = float(stats::TailInformation(model.texture, u)); });
  } else {
    out.information_t = cv::Mat::zeros(image.size(), CV_32F);
  }
  out.regions = (out.information_y > viewpoint.model.threshold) & viewpoint.covered;
  // Step 3: each region against the stored shapes whose boxes meet its own.
  const std::vector<StoredShape> regions = Regions(out.regions, options.min_region_pixels);
  out.region_count = int(regions.size());
  // Regions are matched independently (in parallel); each writes only its own pixels after.
  std::vector<ShapeMatch> matches(regions.size());
  cv::parallel_for_(cv::Range(0, int(regions.size())), [&](const cv::Range& range) {
    for (int k = range.start; k < range.end; ++k)
      matches[k] = BestMatch(regions[k], viewpoint.shapes, zernike, options.min_window_share);
  });
  // Step 3d: e/ê goes to the region's pixels inside its window; elsewhere 1.
  double e_max = 0.0;
  for (const ShapeMatch& m : matches) e_max = std::max(e_max, m.distance);
  out.shape_factor = cv::Mat(image.size(), CV_32F, cv::Scalar(1.0f));
  for (size_t k = 0; k < regions.size(); ++k) {
    const ShapeMatch& m = matches[k];
    out.matched_count += m.matched;
    const double scale =
        options.shape_scale == IlluminationNoveltyOptions::ShapeScale::kFrameMaximum ? e_max
                                                                                     : m.empty;
    const float factor = scale > 0.0 ? float(m.distance / scale) : 0.0f;
    out.shape_factor(m.window).setTo(factor, Within(regions[k], m.window));
  }
  // Step 4, eq. 6.24.
  cv::Mat magnitude;
  cv::magnitude(out.information_y, out.information_s, magnitude);
  if (!model.texture.empty()) cv::magnitude(magnitude, out.information_t, magnitude);
  out.novelty = out.shape_factor.mul(magnitude);
  out.novelty.setTo(0.0f, viewpoint.covered == 0);
  return out;
}

}  // namespace novelty::illumination
