#include "sensors/rawlog/tracker_trajectory.h"

#include <stdexcept>
#include <vector>

#include "sensors/rawlog/led_observation.h"
#include "sensors/tracker/led_pose_estimator.h"

namespace novelty::sensors {

TrackerTrajectory ReadTrackerTrajectory(const std::string& rawlog) {
  std::vector<std::string> skipped;
  const std::vector<LedSample> samples = ReadLedSamples(rawlog, &skipped);
  if (samples.empty()) throw std::runtime_error(rawlog + ": no LED_TRACKER observations");
  std::string why;
  const auto interval = FindStaticInterval(samples, {}, &why);
  if (!interval) throw std::runtime_error(rawlog + ": cannot calibrate the LED plate: " + why);
  const std::vector<LedSample> still(samples.begin() + interval->first,
                                     samples.begin() + interval->second);
  TrackerTrajectory t;
  t.plate = CalibratePlateGeometry(still, LedPlate::Nominal().camera_from_plate);
  t.still_samples = int(still.size());
  t.still_seconds = still.back().time - still.front().time;
  t.rejected = int(skipped.size());
  std::vector<TimedPose> poses;
  for (const LedSample& s : samples) {
    if (auto p = EstimateCameraPose(t.plate, s, {}, nullptr))
      poses.push_back({p->time, p->world_from_camera});
    else
      ++t.rejected;
  }
  t.poses = PoseTrajectory(std::move(poses));
  return t;
}

}  // namespace novelty::sensors
