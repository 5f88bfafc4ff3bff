// The maps' per-frame products as MRPT images: to show with MRPT's GUI classes
// (mrpt::gui::CDisplayWindow::showImage) or to write back into a rawlog as CObservationImage, which
// RawLogViewer shows beside the camera. The pictures and their scales come from
// maps/appearance/product_images.h (false colour, fixed scales).
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/obs/CObservationImage.h>

#include <opencv2/core.hpp>
#include <string>

namespace novelty::mrpt_plugins {

/// A picture (CV_8UC3 R, G, B) as an MRPT colour image (a deep copy); empty → empty image.
mrpt::img::CImage ToCImage(const cv::Mat& rgb);

/// `image` as an observation of the sensor `label` at `timestamp`, seen from `sensor_pose` (on the
/// robot) with `camera`'s intrinsics: e.g. the surprise of an RGB-D frame, labelled "SURPRISE",
/// with that frame's timestamp, sensor pose and camera.
mrpt::obs::CObservationImage::Ptr ProductObservation(const mrpt::img::CImage& image,
                                                     const std::string& label,
                                                     mrpt::Clock::time_point timestamp,
                                                     const mrpt::poses::CPose3D& sensor_pose,
                                                     const mrpt::img::TCamera& camera);

}  // namespace novelty::mrpt_plugins
