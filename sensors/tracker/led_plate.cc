#include "sensors/tracker/led_plate.h"

#include <Eigen/SVD>
#include <stdexcept>

namespace novelty::sensors {

LedPlate LedPlate::Nominal(double a, double b, double height) {
  LedPlate plate;
  plate.leds = {Eigen::Vector3d(a, 0, 0), Eigen::Vector3d(a, b, 0), Eigen::Vector3d(0, b, 0),
                Eigen::Vector3d(0, 0, 0)};
  // Plate axes in camera coordinates: x → +Z (forward), y → +X (right), z = x × y → +Y (down:
  // the LED side faces up, the frame is right-handed).
  Eigen::Isometry3d cam_from_plate = Eigen::Isometry3d::Identity();
  cam_from_plate.linear().col(0) = Eigen::Vector3d::UnitZ();
  cam_from_plate.linear().col(1) = Eigen::Vector3d::UnitX();
  cam_from_plate.linear().col(2) = Eigen::Vector3d::UnitY();
  cam_from_plate.translation() = Eigen::Vector3d(-b / 2, -height, -a / 2);
  plate.camera_from_plate = cam_from_plate;
  return plate;
}

Eigen::Isometry3d PlateFrameFromLeds(const std::array<Eigen::Vector3d, 4>& leds) {
  const Eigen::Vector3d origin = leds[3];
  const Eigen::Vector3d x = (leds[0] - origin).normalized();
  const Eigen::Vector3d to3 = leds[2] - origin;
  const Eigen::Vector3d y = (to3 - to3.dot(x) * x).normalized();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear().col(0) = x;
  t.linear().col(1) = y;
  t.linear().col(2) = x.cross(y);
  t.translation() = origin;
  return t;
}

std::optional<std::pair<size_t, size_t>> FindStaticInterval(const std::vector<LedSample>& samples,
                                                            const StaticIntervalOptions& options,
                                                            std::string* why) {
  auto complete = [&](size_t i) {
    for (const auto& led : samples[i].leds)
      if (!led) return false;
    return true;
  };
  std::optional<std::pair<size_t, size_t>> best;
  double best_duration = 0.0;
  size_t start = 0;
  while (start < samples.size()) {
    if (!complete(start)) {
      ++start;
      continue;
    }
    // Grow the run while every LED seen stays near its mean over the run so far. A sample
    // missing an LED (a dropout, 2 % per LED in the simulator) neither ends the run nor counts
    // for that LED: at 25 Hz, runs of complete samples rarely last a second.
    std::array<Eigen::Vector3d, 4> sum;
    std::array<int, 4> count;
    for (int k = 0; k < 4; ++k) sum[k] = *samples[start].leds[k], count[k] = 1;
    size_t end = start + 1;
    for (; end < samples.size(); ++end) {
      const auto& leds = samples[end].leds;
      bool still = true;
      for (int k = 0; k < 4 && still; ++k)
        still = !leds[k] || (*leds[k] - sum[k] / double(count[k])).norm() <= options.tolerance;
      if (!still) break;
      for (int k = 0; k < 4; ++k)
        if (leds[k]) sum[k] += *leds[k], ++count[k];
    }
    while (!complete(end - 1)) --end;  // the run ends on a complete sample
    const double duration = samples[end - 1].time - samples[start].time;
    if (duration > best_duration) {
      best_duration = duration;
      best = std::make_pair(start, end);
    }
    start = end;
  }
  if (!best || best_duration < options.min_duration) {
    if (why)
      *why = "no static interval of " + std::to_string(options.min_duration) +
             " s with all four LEDs (longest " + std::to_string(best_duration) + " s)";
    return std::nullopt;
  }
  return best;
}

LedPlate CalibratePlateGeometry(const std::vector<LedSample>& static_samples,
                                const Eigen::Isometry3d& mount) {
  std::array<Eigen::Vector3d, 4> mean;
  for (int k = 0; k < 4; ++k) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (const LedSample& s : static_samples)
      if (s.leds[k]) sum += *s.leds[k], ++count;
    if (count == 0)
      throw std::runtime_error("LED plate calibration: LED " + std::to_string(k + 1) +
                               " is never seen in the static interval");
    mean[k] = sum / count;
  }
  const double side_x = (mean[0] - mean[3]).norm(), side_y = (mean[2] - mean[3]).norm();
  const double cross =
      (mean[0] - mean[3]).normalized().cross((mean[2] - mean[3]).normalized()).norm();
  if (side_x < 0.02 || side_y < 0.02 || cross < 0.5)
    throw std::runtime_error(
        "LED plate calibration: the averaged LEDs do not form a plate (sides " +
        std::to_string(side_x) + " m and " + std::to_string(side_y) + " m, sin angle " +
        std::to_string(cross) + ")");
  const Eigen::Isometry3d plate_in_world = PlateFrameFromLeds(mean);
  LedPlate plate;
  for (int k = 0; k < 4; ++k) plate.leds[k] = plate_in_world.inverse() * mean[k];
  plate.camera_from_plate = mount;
  return plate;
}

Eigen::Isometry3d EstimateCameraFromPlate(
    const std::vector<std::pair<Eigen::Isometry3d, Eigen::Isometry3d>>& world_plate_and_cam) {
  if (world_plate_and_cam.empty())
    throw std::runtime_error("camera-from-plate calibration: no pose pairs");
  Eigen::Matrix3d rotation_sum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d translation_sum = Eigen::Vector3d::Zero();
  for (const auto& [world_plate, world_cam] : world_plate_and_cam) {
    const Eigen::Isometry3d cam_plate = world_cam.inverse() * world_plate;
    rotation_sum += cam_plate.linear();
    translation_sum += cam_plate.translation();
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(rotation_sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) d(2, 2) = -1;
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.linear() = svd.matrixU() * d * svd.matrixV().transpose();
  result.translation() = translation_sum / double(world_plate_and_cam.size());
  return result;
}

}  // namespace novelty::sensors
