#include "experiments/inserted_object_run.h"

#include <mrpt/obs/CObservation3DRangeScan.h>

#include <filesystem>
#include <stdexcept>

#include "core/frame_stem.h"
#include "core/range_check.h"
#include "experiments/maps_config.h"
#include "mrpt_plugins/multi_map_config.h"
#include "sensors/dataset/rgbd_importer.h"
#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rawlog_output.h"
#include "sim/output/ground_truth_writer.h"
#include "sim/render/object_insertion.h"
#include "sim/scenario/scenario.h"

namespace novelty::experiments {
namespace {

constexpr int kBoxId = 1;
constexpr int kMinBoxPixels = 30;  // as the surprise experiment's changed regions (30 px)

// The RGB-D observations of `rawlog`, counted without decoding an image.
int CountFrames(const std::string& rawlog) {
  sensors::RawlogInput in(rawlog);
  int n = 0;
  while (const auto o = in.Next())
    n += bool(std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(o));
  return n;
}

// What GroundTruthWriter needs of a scenario: the camera, the phases and the box.
sim::Scenario BoxScenario(const std::string& rawlog, const core::PinholeCamera& camera,
                          int insert_from, int frames, const Eigen::Vector3d& size) {
  sim::Scenario s;
  s.name = "inserted box";
  s.file = rawlog;
  s.frames = frames;
  s.camera = camera;
  s.phases = {{"A", 1, insert_from - 1, "the room as recorded"},
              {"X", insert_from, frames, "a synthetic box inserted"}};
  sim::ObjectSpec box;
  box.name = "box";
  box.id = kBoxId;
  box.dims = size;
  s.objects.push_back(box);
  return s;
}

// Writes the frames, the box drawn in from `insert_from` on, as a rawlog and ground truth;
// counts in `r` the frames that see the box as the scored regions do (kMinBoxPixels) and its area.
void WriteInserted(const InsertedObjectRunOptions& o, int insert_from, int frames,
                   const std::string& out, InsertedObjectRunResult& r) {
  sensors::RawlogFrameReader reader(o.rawlog);
  sensors::RawlogOutput rawlog(out + "/inserted.rawlog");
  const Eigen::Isometry3d mount = sensors::HandHeldMount();
  std::optional<sim::Scenario> scenario;
  std::optional<sim::GroundTruthWriter> truth;
  std::optional<sim::ObjectInserter> inserter;
  core::Frame f;
  for (int k = 1; k <= frames && reader.Next(f); ++k) {
    if (!f.T_world_cam)
      throw std::runtime_error(o.rawlog + ": frame " + std::to_string(k) +
                               " has no pose observation (novelty-import and novelty-poses write "
                               "them)");
    if (!truth) {
      scenario = BoxScenario(o.rawlog, f.camera, insert_from, frames, o.size);
      truth.emplace(out, *scenario, std::vector<Eigen::Isometry3d>{Eigen::Isometry3d::Identity()});
    }
    cv::Mat depth = f.depth.clone(), mask(f.rgb.size(), CV_8UC1, cv::Scalar(0));
    cv::Mat rgb = f.rgb.clone();
    if (k == insert_from) {
      sim::InsertedBoxOptions box;
      box.size = o.size;
      box.pose =
          sim::ObjectInserter::StandInFrontOf(depth, f.camera, *f.T_world_cam, o.standoff, o.size);
      inserter.emplace(box);
    }
    if (inserter) mask = inserter->Insert(rgb, depth, f.camera, *f.T_world_cam, k);
    rawlog.Write(sensors::MakeCameraPoseObservation(f.time, *f.T_world_cam, mount, "POSE_DATASET",
                                                    0.001, 0.002));
    rawlog.WriteRgbd(f.time, rgb, depth, f.camera, mount, core::FrameStem(k));
    cv::Mat ids(mask.size(), CV_32SC1, cv::Scalar(0));
    ids.setTo(kBoxId, mask);
    truth->WriteFrame(k, f.time, *f.T_world_cam, nullptr, depth, ids, mask);
    if (const int seen = cv::countNonZero(mask); seen >= kMinBoxPixels) {
      ++r.box_frames;
      r.box_pixels += seen;
    }
    if (o.progress) o.progress("drawing the box in", k, frames);
  }
  if (!truth) throw std::runtime_error(o.rawlog + ": no RGB-D frame could be read");
  // A skipped frame would shift the box and the ground truth against the frames asked for.
  if (reader.skipped() > 0)
    throw std::runtime_error(o.rawlog + ": " + std::to_string(reader.skipped()) +
                             " RGB-D frames could not be read (" + reader.skip_reasons().front() +
                             "); the box needs every frame");
  truth->WriteEvents({});
  truth->WriteObjects();
  rawlog.Close();
}

}  // namespace

InsertedObjectRunResult RunInsertedObject(const InsertedObjectRunOptions& o,
                                          const std::string& out) {
  core::CheckInRange(o.standoff, 0.0, 10.0, "standoff");
  if (!(o.size.minCoeff() > 0.0 && o.size.maxCoeff() <= 10.0))
    throw std::invalid_argument("box size: edge lengths in (0, 10] m");
  if (o.max_frames && *o.max_frames < 2) throw std::invalid_argument("max_frames must be >= 2");
  // The baseline the box is scored against, checked before any frame is drawn.
  const MapsConfig maps = OpenMapsConfig(o.config);
  if (mrpt_plugins::CheckMultiMapConfig(*maps.ini, "map", maps.source)["CDifferencingMap"] != 1)
    throw std::invalid_argument(maps.source +
                                ": the box is scored against image differencing; declare "
                                "CDifferencingMap_count = 1");
  int frames = CountFrames(o.rawlog);
  if (o.max_frames) frames = std::min(frames, *o.max_frames);
  if (frames < 2) throw std::runtime_error(o.rawlog + ": fewer than 2 RGB-D frames");
  InsertedObjectRunResult r;
  r.insert_from = o.insert_from ? o.insert_from : frames / 2 + 1;
  if (r.insert_from < 2 || r.insert_from > frames)
    throw std::invalid_argument("insert_from " + std::to_string(r.insert_from) +
                                ": the box needs frames before it and from it on (2…" +
                                std::to_string(frames) + ")");
  WriteInserted(o, r.insert_from, frames, out, r);
  if (r.box_frames > 0) r.box_pixels /= r.box_frames;
  SurpriseExperimentOptions s;
  s.rawlog = out + "/inserted.rawlog";
  s.groundtruth = out + "/groundtruth";
  s.config = o.config;
  s.pose_source = "rawlog";
  if (o.judge_only) s.learn_until = r.insert_from - 1;
  s.panels_every = o.panels_every;
  s.status = o.status;
  if (o.progress) s.progress = [&](int frame, int total) { o.progress("playing", frame, total); };
  std::filesystem::create_directories(out + "/run");
  r.run = RunSurpriseExperiment(s, out + "/run");
  r.frames = r.run.frames;
  // Means over the frames that see the box, as MeanOver takes them.
  r.box = eval::MeanOver(r.run.rows, "box", r.insert_from, frames);
  for (const eval::SelectivityRow& row : r.run.rows) {
    if (row.region != "box") continue;
    r.first_sight = eval::MeanOver(r.run.rows, "box", row.frame, row.frame);
    break;
  }
  const auto db = [](double v) { return eval::NumberText(v) + " dB"; };
  const auto add = [&](const std::string& when, const eval::MeanSelectivity& m) {
    r.findings.Add("box " + when + ": AS surprise, differencing",
                   db(m.as_surprise) + ", " + db(m.as_difference));
    r.findings.Add("box " + when + ": PAS surprise, differencing",
                   db(m.pas_surprise) + ", " + db(m.pas_difference));
    r.findings.Add("box " + when + ": AS surprise - AS differencing",
                   db(m.as_surprise - m.as_difference), ">= 1 dB (issue 51)",
                   m.frames > 0 && m.as_surprise >= m.as_difference + 1.0);
    r.findings.Add("box " + when + ": coverage", eval::NumberText(m.coverage), ">= 0.8 (issue 51)",
                   m.frames > 0 && m.coverage >= 0.8);
  };
  r.findings.Add("frames seeing the box (of " + std::to_string(frames - r.insert_from + 1) + ")",
                 std::to_string(r.box_frames));
  add("at first sight", r.first_sight);
  add("over the frames seeing it", r.box);
  r.findings.WriteCsv(out + "/findings.csv");
  return r;
}

}  // namespace novelty::experiments
