#include "sensors/localization/rgbd_odometry.h"

#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/rgbd.hpp>
#include <stdexcept>

#include "core/range_check.h"

namespace novelty::sensors {

class RgbdOdometry::Impl {
 public:
  Impl(const core::PinholeCamera& camera, const RgbdOdometryOptions& o,
       const Eigen::Isometry3d& initial)
      : camera_(camera), world_from_last_(initial) {
    camera.Check();
    core::CheckInRange(o.max_translation, 1e-3, 10.0, "max_translation");
    core::CheckInRange(o.max_rotation_deg, 0.1, 180.0, "max_rotation_deg");
    core::CheckInRange(o.min_depth, 0.0, 100.0, "min_depth");
    core::CheckInRange(o.max_depth, o.min_depth + 1e-3, 100.0, "max_depth");
    const cv::Mat k =
        (cv::Mat_<double>(3, 3) << camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
    odometry_ = cv::rgbd::RgbdICPOdometry::create(k, float(o.min_depth), float(o.max_depth));
    odometry_->setMaxTranslation(o.max_translation);
    odometry_->setMaxRotation(o.max_rotation_deg);
  }

  std::optional<Eigen::Isometry3d> Track(const cv::Mat& rgb, const cv::Mat& depth,
                                         std::string* why) {
    if (rgb.type() != CV_8UC3 || depth.type() != CV_32FC1 || rgb.size() != depth.size() ||
        rgb.cols != camera_.width || rgb.rows != camera_.height)
      throw std::invalid_argument(
          "RgbdOdometry: an RGB image (CV_8UC3) and a depth image "
          "(CV_32FC1) of the camera's size");
    cv::Mat grey;
    cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
    const cv::Mat known = depth > 0;
    auto frame = cv::makePtr<cv::rgbd::OdometryFrame>(grey, depth, known);
    odometry_->prepareFrameCache(frame, cv::rgbd::OdometryFrame::CACHE_ALL);
    if (last_) {
      cv::Mat rt;
      if (!odometry_->compute(last_, frame, rt)) {
        if (why) *why = "the odometry found no step within its bounds from the last tracked frame";
        return std::nullopt;
      }
      Eigen::Matrix4d m;
      cv::cv2eigen(rt, m);
      // rt maps the last frame's points into this one's: p_this = rt · p_last.
      world_from_last_ = world_from_last_ * Eigen::Isometry3d(m).inverse();
    }
    last_ = frame;
    return world_from_last_;
  }

 private:
  core::PinholeCamera camera_;
  cv::Ptr<cv::rgbd::RgbdICPOdometry> odometry_;
  cv::Ptr<cv::rgbd::OdometryFrame> last_;
  Eigen::Isometry3d world_from_last_;
};

RgbdOdometry::RgbdOdometry(const core::PinholeCamera& camera, const RgbdOdometryOptions& options,
                           const Eigen::Isometry3d& initial_pose)
    : impl_(std::make_unique<Impl>(camera, options, initial_pose)) {}

RgbdOdometry::~RgbdOdometry() = default;

std::optional<Eigen::Isometry3d> RgbdOdometry::Track(const cv::Mat& rgb, const cv::Mat& depth,
                                                     std::string* why) {
  return impl_->Track(rgb, depth, why);
}

}  // namespace novelty::sensors
