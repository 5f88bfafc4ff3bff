// Test helper: a photo of random discs (blobs every extractor finds, in any size), and a scene
// with one photo pasted into another through a homography.
#pragma once

#include <opencv2/imgproc.hpp>

namespace novelty::objects {

/// CV_8UC1 `size` of ~one disc per 170 px², radii 2–9 px, grey levels from `seed`.
inline cv::Mat BlobPhoto(cv::Size size, unsigned seed) {
  cv::Mat img(size, CV_8UC1, cv::Scalar(128));
  cv::RNG rng(seed);
  for (int i = 0; i < size.area() / 170; ++i)
    cv::circle(img, {rng.uniform(0, size.width), rng.uniform(0, size.height)}, rng.uniform(2, 9),
               cv::Scalar(rng.uniform(0, 256)), cv::FILLED, cv::LINE_AA);
  return img;
}

/// `photo` warped by `h` (3×3 CV_64F, photo pixels → scene pixels) over `background`.
inline cv::Mat PastePhoto(const cv::Mat& background, const cv::Mat& photo, const cv::Mat& h) {
  cv::Mat scene = background.clone(), pasted, where;
  cv::warpPerspective(photo, pasted, h, scene.size(), cv::INTER_LINEAR);
  cv::warpPerspective(cv::Mat(photo.size(), CV_8UC1, cv::Scalar(255)), where, h, scene.size(),
                      cv::INTER_NEAREST);
  pasted.copyTo(scene, where);
  return scene;
}

}  // namespace novelty::objects
