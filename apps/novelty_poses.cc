// novelty-poses: camera poses for a rawlog's camera observations (thesis 3.1).
//
//   novelty-poses IN.rawlog --source tracker --out OUT.rawlog [--smoothing 0.4]
//                 [--groundtruth DIR/groundtruth]
//
// --source tracker: the LED plate is calibrated from the longest static interval of the LED
// tracker samples (LEDs averaged, plate frame with LED 4 as origin; sensors/tracker/led_plate.h),
// mounted on the camera head as LedPlate::Nominal() describes; every sample with three or four
// LEDs gives a camera pose (SVD fit); poses are interpolated (SLERP, local linear smoothing) to
// the timestamps of the camera observations. OUT is IN with a CObservationRobotPose
// "POSE_TRACKER" before every camera observation that got a pose
// (sensors/rawlog/camera_pose_observation.h); novelty-run --poses rawlog uses them.
// With --groundtruth the pose error against novelty-sim's poses.csv is printed.
// --source visual (KLT + stereo visual localization) is not implemented yet and says so.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>
#include <tclap/CmdLine.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/led_observation.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/rawlog_output.h"
#include "sensors/rawlog/rgbd_observation.h"
#include "sensors/tracker/led_pose_estimator.h"
#include "sensors/tracker/pose_trajectory.h"

namespace {

using namespace novelty;

// T_robot_cam of a camera observation, or nullopt for anything else.
std::optional<Eigen::Isometry3d> CameraMount(const mrpt::serialization::CSerializable& obj) {
  if (auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obj))
    return sensors::CameraOnRobot(*scan);
  if (auto* image = dynamic_cast<const mrpt::obs::CObservationImage*>(&obj))
    return sensors::ToEigen(image->cameraPose);
  if (auto* stereo = dynamic_cast<const mrpt::obs::CObservationStereoImages*>(&obj))
    return sensors::ToEigen(mrpt::poses::CPose3D(stereo->cameraPose));
  return std::nullopt;
}

sensors::PoseTrajectory TrackerTrajectory(const std::string& rawlog, int* rejected) {
  std::vector<std::string> skipped;
  const std::vector<sensors::LedSample> samples = sensors::ReadLedSamples(rawlog, &skipped);
  if (samples.empty()) throw std::runtime_error(rawlog + ": no LED_TRACKER observations");
  std::string why;
  const auto interval = sensors::FindStaticInterval(samples, {}, &why);
  if (!interval) throw std::runtime_error(rawlog + ": cannot calibrate the LED plate: " + why);
  const std::vector<sensors::LedSample> still(samples.begin() + interval->first,
                                              samples.begin() + interval->second);
  const sensors::LedPlate plate =
      sensors::CalibratePlateGeometry(still, sensors::LedPlate::Nominal().camera_from_plate);
  std::fprintf(stderr,
               "[novelty-poses] plate calibrated from %zu samples (%.1f s still): LED1 (%.4f, "
               "%.4f, %.4f) LED2 (%.4f, %.4f, %.4f) LED3 (%.4f, %.4f, %.4f) m\n",
               still.size(), still.back().time - still.front().time, plate.leds[0].x(),
               plate.leds[0].y(), plate.leds[0].z(), plate.leds[1].x(), plate.leds[1].y(),
               plate.leds[1].z(), plate.leds[2].x(), plate.leds[2].y(), plate.leds[2].z());
  std::vector<sensors::TimedPose> poses;
  *rejected = int(skipped.size());
  for (const sensors::LedSample& s : samples) {
    if (auto p = sensors::EstimateCameraPose(plate, s, {}, nullptr))
      poses.push_back({p->time, p->world_from_camera});
    else
      ++*rejected;
  }
  return sensors::PoseTrajectory(std::move(poses));
}

}  // namespace

int main(int argc, char** argv) {
  try {
    TCLAP::CmdLine cmd("Adds camera poses (LED tracker or vision) to a rawlog.", ' ', "0.1");
    TCLAP::UnlabeledValueArg<std::string> in("input", "Input rawlog", true, "", "IN.rawlog", cmd);
    TCLAP::ValueArg<std::string> out("o", "out", "Output rawlog", true, "", "OUT.rawlog", cmd);
    std::vector<std::string> sources = {"tracker", "visual"};
    TCLAP::ValuesConstraint<std::string> allowed(sources);
    TCLAP::ValueArg<std::string> source("", "source", "Where poses come from", true, "", &allowed,
                                        cmd);
    TCLAP::ValueArg<double> smoothing(
        "", "smoothing", "Half-width (s) of the local linear pose fit; 0 = plain SLERP", false,
        sensors::PoseInterpolationOptions().smoothing_half_window, "S", cmd);
    TCLAP::ValueArg<std::string> truth("", "groundtruth", "Report errors against this folder",
                                       false, "", "DIR", cmd);
    cmd.parse(argc, argv);
    if (source.getValue() == "visual")
      throw std::runtime_error(
          "--source visual: visual localization (KLT + stereo) is not implemented yet; use "
          "--source tracker");
    if (std::filesystem::absolute(in.getValue()) == std::filesystem::absolute(out.getValue()))
      throw std::invalid_argument("--out must differ from the input rawlog");

    int rejected = 0;
    const sensors::PoseTrajectory trajectory = TrackerTrajectory(in.getValue(), &rejected);
    sensors::PoseInterpolationOptions interpolation;
    interpolation.smoothing_half_window = smoothing.getValue();

    mrpt::io::CFileGZInputStream file(in.getValue());
    if (!file.fileOpenCorrectly()) throw std::runtime_error(in.getValue() + ": cannot open");
    sensors::RawlogOutput output(out.getValue());
    output.ShareImagesOf(in.getValue());
    auto arch = mrpt::serialization::archiveFrom(file);
    int cameras = 0, posed = 0;
    std::vector<std::string> reasons;
    for (int object = 1;; ++object) {
      mrpt::serialization::CSerializable::Ptr obj;
      try {
        arch >> obj;
      } catch (const mrpt::serialization::CExceptionEOF&) {
        break;
      } catch (const std::exception& e) {
        throw std::runtime_error(in.getValue() + ": cannot read object " + std::to_string(object) +
                                 ": " + e.what());
      }
      if (const auto mount = CameraMount(*obj)) {
        ++cameras;
        const auto& o = dynamic_cast<const mrpt::obs::CObservation&>(*obj);
        std::string why;
        const double t = mrpt::Clock::toDouble(o.timestamp);
        if (const auto pose = trajectory.At(t, interpolation, &why)) {
          output.Write(
              sensors::MakeCameraPoseObservation(t, *pose, *mount, "POSE_TRACKER", 0.001, 0.003));
          ++posed;
        } else {
          reasons.push_back(why);
        }
      }
      output.Write(*obj);
    }
    output.Close();
    std::printf("%d of %d camera observations got a pose (%d tracker samples rejected) → %s\n",
                posed, cameras, rejected, output.path().c_str());
    for (size_t i = 0; i < std::min<size_t>(reasons.size(), 5); ++i)
      std::printf("  no pose: %s\n", reasons[i].c_str());
    if (reasons.size() > 5) std::printf("  … and %zu more\n", reasons.size() - 5);

    if (truth.isSet()) {  // pose error per RGB-D frame against novelty-sim's ground truth
      const auto gt = sensors::LoadGroundTruthPoses(truth.getValue() + "/poses.csv");
      sensors::RawlogFrameReader reader(output.path());
      std::vector<double> angle, shift;
      for (sensors::Frame f; reader.Next(f);) {
        const auto g = gt.find(f.index);
        if (!f.pose || g == gt.end()) continue;
        angle.push_back(
            Eigen::AngleAxisd(f.pose->linear().transpose() * g->second.linear()).angle() * 180 /
            M_PI);
        shift.push_back((f.pose->translation() - g->second.translation()).norm() * 1000);
      }
      if (!angle.empty()) {
        std::sort(angle.begin(), angle.end());
        std::sort(shift.begin(), shift.end());
        std::printf(
            "error against ground truth over %zu RGB-D frames: rotation median %.3f° "
            "(95 %%: %.3f°), translation median %.2f mm (95 %%: %.2f mm)\n",
            angle.size(), angle[angle.size() / 2], angle[angle.size() * 95 / 100],
            shift[shift.size() / 2], shift[shift.size() * 95 / 100]);
      }
    }
    return 0;
  } catch (const TCLAP::ArgException& e) {
    std::fprintf(stderr, "novelty-poses: %s (%s)\n", e.error().c_str(), e.argId().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "novelty-poses: %s\n", e.what());
  }
  return 1;
}
