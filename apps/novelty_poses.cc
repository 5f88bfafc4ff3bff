// novelty-poses: camera poses for a rawlog's camera observations (thesis 3.1).
//
//   novelty-poses IN.rawlog --source tracker|visual --out OUT.rawlog [--smoothing 0.4]
//                 [--visual-method direct|features] [--groundtruth DIR/groundtruth]
//
// --source tracker: the LED plate is calibrated from the longest static interval of the LED
// tracker samples (LEDs averaged, plate frame with LED 4 as origin; sensors/tracker/led_plate.h),
// mounted on the camera head as LedPlate::Nominal() describes; every sample with three or four
// LEDs gives a camera pose (SVD fit); poses are interpolated (SLERP, local linear smoothing) to
// the timestamps of the camera observations. OUT is IN with a CObservationRobotPose
// "POSE_TRACKER" before every camera observation that got a pose
// (sensors/rawlog/camera_pose_observation.h); novelty-run --poses rawlog uses them.
// --source visual: visual localization on the rig's stereo or trinocular images
// (sensors/localization): --visual-method direct (default) aligns every frame photometrically to
// keyframes with stereo depth; features is the thesis's KLT features, stereo triangulation and
// PnP + RANSAC. Both re-localize against keyframes after tracking is lost. The first frame is the
// origin (as the thesis's VGPS) unless --groundtruth gives its true pose.
// Poses go to the observations of the rig frames (same timestamps). Run it before
// novelty-depth, which copies the pose observations through to its RGB-D scans.
// With --groundtruth the pose error against novelty-sim's poses.csv is printed.
#include <tclap/CmdLine.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "core/range_check.h"
#include "core/same_file.h"
#include "eval/pose_error.h"
#include "sensors/localization/direct_odometry.h"
#include "sensors/localization/visual_odometry.h"
#include "sensors/rawlog/camera_pose_annotator.h"
#include "sensors/rawlog/rig_frame_reader.h"
#include "sensors/rawlog/tracker_trajectory.h"
#include "sensors/tracker/pose_trajectory.h"
#include "sim/output/ground_truth_reader.h"

namespace {

using namespace novelty;

// The tracker's trajectory, with the plate's calibration on stderr.
sensors::PoseTrajectory TrackerPoses(const std::string& rawlog, int* rejected) {
  const sensors::TrackerTrajectory t = sensors::ReadTrackerTrajectory(rawlog);
  const auto& leds = t.plate.leds;
  std::fprintf(stderr,
               "[novelty-poses] plate calibrated from %d samples (%.1f s still): LED1 (%.4f, "
               "%.4f, %.4f) LED2 (%.4f, %.4f, %.4f) LED3 (%.4f, %.4f, %.4f) m\n",
               t.still_samples, t.still_seconds, leds[0].x(), leds[0].y(), leds[0].z(), leds[1].x(),
               leds[1].y(), leds[1].z(), leds[2].x(), leds[2].y(), leds[2].z());
  *rejected = t.rejected;
  return t.poses;
}

// One visual odometry behind one call: the pose of a stereo pair, or nullopt with the reason.
using VisualTracker =
    std::function<std::optional<Eigen::Isometry3d>(const sensors::StereoPair&, std::string*)>;

template <typename Odometry, typename Options>
VisualTracker MakeTracker(const Eigen::Isometry3d& first) {
  auto vo = std::make_shared<Odometry>(Options{}, first);
  return [vo](const sensors::StereoPair& pair, std::string* why) {
    const auto r = vo->Track(pair, why);
    return r ? std::optional<Eigen::Isometry3d>(r->world_from_camera) : std::nullopt;
  };
}

// Camera poses of the rig frames by visual localization, keyed by timestamp.
std::map<double, Eigen::Isometry3d> VisualPoses(const std::string& rawlog,
                                                const std::string& method,
                                                const std::optional<Eigen::Isometry3d>& first,
                                                int* lost) {
  sensors::RigFrameReader reader(rawlog);
  const Eigen::Isometry3d origin = first.value_or(Eigen::Isometry3d::Identity());
  const VisualTracker track =
      method == "direct"
          ? MakeTracker<sensors::DirectOdometry, sensors::DirectOdometryOptions>(origin)
          : MakeTracker<sensors::VisualOdometry, sensors::VisualOdometryOptions>(origin);
  std::map<double, Eigen::Isometry3d> poses;
  int frames = 0;
  apps::Progress progress("[novelty-poses] stereo frames", 0);
  for (sensors::RigFrame f; reader.Next(f, nullptr);) {
    sensors::StereoPair pair{f.time,       f.images[0],  f.images[1],
                             f.cameras[0], f.cameras[1], f.ref_from_camera[1]};
    std::string why;
    if (const auto pose = track(pair, &why))
      poses[f.time] = *pose;
    else
      ++*lost, std::fprintf(stderr, "[novelty-poses] frame %d: %s\n", f.index, why.c_str());
    progress.Update(++frames);
  }
  progress.Finish();
  if (frames == 0) throw std::runtime_error(rawlog + ": no stereo or trinocular frames");
  return poses;
}

// The pose error against novelty-sim's ground truth (its frames are the camera times in order).
void ReportPoseError(const sensors::CameraPoseAnnotation& a, const std::string& truth) {
  std::map<int, Eigen::Isometry3d> estimated;
  int frame = 0;
  for (const auto& [t, pose] : a.poses) {
    ++frame;
    if (pose) estimated.emplace(frame, *pose);
  }
  const auto e = eval::ComparePoses(estimated, sim::GroundTruthReader(truth).CameraPoses());
  if (!e) return;
  std::printf("last frame %d: %.3f°, %.1f mm off\n", e->last_frame, e->last_deg, e->last_mm);
  std::printf(
      "error against ground truth over %d frames: rotation median %.3f° (95 %%: %.3f°), "
      "translation median %.2f mm (95 %%: %.2f mm)\n",
      e->frames, e->median_deg, e->p95_deg, e->median_mm, e->p95_mm);
}

int Run(int argc, char** argv) {
  novelty::apps::CommandLine cmd("Adds camera poses (LED tracker or vision) to a rawlog.", "0.1");
  TCLAP::UnlabeledValueArg<std::string> in("input", "Input rawlog", true, "", "IN.rawlog", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output rawlog", true, "", "OUT.rawlog", cmd);
  std::vector<std::string> sources = {"tracker", "visual"};
  TCLAP::ValuesConstraint<std::string> allowed(sources);
  TCLAP::ValueArg<std::string> source("", "source", "Where poses come from", true, "", &allowed,
                                      cmd);
  std::vector<std::string> methods = {"direct", "features"};
  TCLAP::ValuesConstraint<std::string> allowed_methods(methods);
  TCLAP::ValueArg<std::string> method("", "visual-method",
                                      "Visual localization: direct (photometric, default) or "
                                      "features (KLT + PnP, as the thesis)",
                                      false, "direct", &allowed_methods, cmd);
  TCLAP::ValueArg<double> smoothing(
      "", "smoothing", "Half-width (s) of the local linear pose fit; 0 = plain SLERP", false,
      sensors::PoseInterpolationOptions().smoothing_half_window, "S", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth", "Report errors against this folder", false,
                                     "", "DIR", cmd);
  cmd.Parse(argc, argv);
  core::CheckInRange(smoothing.getValue(), 0, 60, "--smoothing");
  if (core::SameFile(in.getValue(), out.getValue()))
    throw std::invalid_argument("--out " + out.getValue() + " is the input rawlog " +
                                in.getValue() + ": it would be overwritten");
  // Nothing but a rawlog is replaced, and nothing inside an input's folder (the ground truth).
  apps::CheckOutputFile("--out", out.getValue(), {in.getValue(), truth.getValue()},
                        apps::HasExtension(".rawlog"));

  const bool visual = source.getValue() == "visual";
  int rejected = 0;
  std::optional<sensors::PoseTrajectory> trajectory;
  std::map<double, Eigen::Isometry3d> visual_poses;
  if (visual) {
    std::optional<Eigen::Isometry3d> first;
    if (truth.isSet()) {
      const auto gt = sim::GroundTruthReader(truth.getValue()).CameraPoses();
      if (!gt.empty()) first = gt.begin()->second;
    }
    visual_poses = VisualPoses(in.getValue(), method.getValue(), first, &rejected);
  } else {
    trajectory = TrackerPoses(in.getValue(), &rejected);
  }
  sensors::PoseInterpolationOptions interpolation;
  interpolation.smoothing_half_window = smoothing.getValue();
  auto pose_at = [&](double t, std::string* why) -> std::optional<Eigen::Isometry3d> {
    if (!visual) return trajectory->At(t, interpolation, why);
    const auto it = visual_poses.find(t);
    if (it != visual_poses.end()) return it->second;
    *why = "no visual pose at " + std::to_string(t) + " s";
    return std::nullopt;
  };
  const std::string label = visual ? "POSE_VISUAL" : "POSE_TRACKER";

  const sensors::CameraPoseAnnotation a =
      sensors::AnnotateCameraPoses(in.getValue(), out.getValue(), pose_at, label);
  std::printf("%d of %d camera observations got a pose (%d %s rejected) → %s\n", a.posed, a.cameras,
              rejected, visual ? "frames" : "tracker samples", out.getValue().c_str());
  for (size_t i = 0; i < std::min<size_t>(a.reasons.size(), 5); ++i)
    std::printf("  no pose: %s\n", a.reasons[i].c_str());
  if (a.reasons.size() > 5) std::printf("  … and %zu more\n", a.reasons.size() - 5);
  if (truth.isSet()) ReportPoseError(a, truth.getValue());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-poses", [&] { return Run(argc, argv); });
}
