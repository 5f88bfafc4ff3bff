#include "sensors/tracker/led_pose_estimator.h"

#include "sensors/tracker/rigid_fit.h"

namespace novelty::sensors {

std::optional<LedPose> EstimateCameraPose(const LedPlate& plate, const LedSample& sample,
                                          const LedPoseOptions& options, std::string* why) {
  std::vector<Eigen::Vector3d> model, measured;
  for (int k = 0; k < 4; ++k) {
    if (!sample.leds[k]) continue;
    model.push_back(plate.leds[k]);
    measured.push_back(*sample.leds[k]);
  }
  if (model.size() < 3) {
    if (why) *why = std::to_string(model.size()) + " of 4 LEDs seen (3 needed)";
    return std::nullopt;
  }
  const auto fit = FitRigid(model, measured, {}, why);
  if (!fit) return std::nullopt;
  // The LEDs are coplanar, so the SVD's sign fix is routine here; a truly mirrored or mislabelled
  // plate shows in the residual.
  if (fit->rms > options.max_rms) {
    if (why)
      *why = "LED fit residual " + std::to_string(fit->rms * 1000) + " mm exceeds " +
             std::to_string(options.max_rms * 1000) + " mm";
    return std::nullopt;
  }
  LedPose pose;
  pose.time = sample.time;
  pose.world_from_camera = fit->transform * plate.camera_from_plate.inverse();  // eq. 3.5
  pose.leds_used = int(model.size());
  pose.rms = fit->rms;
  return pose;
}

}  // namespace novelty::sensors
