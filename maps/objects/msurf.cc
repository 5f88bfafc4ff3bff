#include "maps/objects/msurf.h"

#include <cmath>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "maps/objects/box_filters.h"
#include "maps/objects/msurf_descriptor.h"

namespace novelty::objects {

namespace {

// The keypoint size for scale s, and back.
constexpr float kSizePerScale = 10.0f;

}  // namespace

MSurf::MSurf(const MSurfOptions& options) : options_(options) {}

cv::Ptr<MSurf> MSurf::create(const MSurfOptions& options) {
  return cv::makePtr<MSurf>(options);
}

void MSurf::detectAndCompute(cv::InputArray image, cv::InputArray mask,
                             std::vector<cv::KeyPoint>& keypoints, cv::OutputArray descriptors,
                             bool use_provided_keypoints) {
  const cv::Mat integral = UnitIntegral(image);
  if (!use_provided_keypoints) {
    const cv::Mat m = mask.getMat();
    CV_Assert(m.empty() ||
              (m.type() == CV_8UC1 && m.rows == integral.rows - 1 && m.cols == integral.cols - 1));
    keypoints.clear();
    // Only where the mask is: the detector computes responses near its bounding box alone.
    const cv::Rect region = m.empty() ? cv::Rect() : cv::boundingRect(m);
    if (!m.empty() && region.empty()) {  // nothing masked in
      if (descriptors.needed()) descriptors.release();
      return;
    }
    for (const HessianPoint& p : DetectFastHessian(integral, options_.detector, region)) {
      const int x = int(std::lround(p.pt.x)), y = int(std::lround(p.pt.y));
      if (!m.empty() && (x < 0 || y < 0 || x >= m.cols || y >= m.rows || !m.at<uchar>(y, x)))
        continue;
      keypoints.emplace_back(p.pt, kSizePerScale * p.scale, 0.0f, p.response, p.octave,
                             p.laplacian);
    }
    if (!options_.upright) {  // the orientations, keypoints spread over the cores
      cv::parallel_for_(cv::Range(0, int(keypoints.size())), [&](const cv::Range& range) {
        for (int i = range.start; i < range.end; ++i) {
          cv::KeyPoint& k = keypoints[std::size_t(i)];
          float degrees =
              SurfOrientation(integral, k.pt, k.size / kSizePerScale) * float(180.0 / M_PI);
          k.angle = degrees < 0.0f ? degrees + 360.0f : degrees;
        }
      });
    }
  }
  if (!descriptors.needed()) return;
  for (std::size_t i = 0; i < keypoints.size(); ++i) {  // given keypoints may be anything
    const cv::KeyPoint& k = keypoints[i];
    if (!(std::isfinite(k.pt.x) && std::isfinite(k.pt.y) && std::isfinite(k.angle) &&
          k.size > 0.0f && std::isfinite(k.size)))
      CV_Error(cv::Error::StsBadArg, "MSurf: keypoint " + std::to_string(i) +
                                         " has a non-finite position or angle, or no size");
  }
  descriptors.create(int(keypoints.size()), 64, CV_32F);
  cv::Mat d = descriptors.getMat();
  cv::parallel_for_(cv::Range(0, int(keypoints.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const cv::KeyPoint& k = keypoints[std::size_t(i)];
      const float angle = options_.upright ? 0.0f : k.angle * float(M_PI / 180.0);
      MSurfDescriptor(integral, k.pt, k.size / kSizePerScale, angle, d.ptr<float>(i));
    }
  });
}

}  // namespace novelty::objects
