#include "sim/scenario/scenario_runner.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "core/frame_stem.h"
#include "core/write_rgb_image.h"
#include "sim/output/cdnet_writer.h"
#include "sim/output/contact_sheet.h"
#include "sim/output/ground_truth_writer.h"
#include "sim/output/rawlog_writer.h"
#include "sim/render/renderer.h"
#include "sim/scenario/scenario_world.h"
#include "sim/world/led_tracker.h"

namespace novelty::sim {

namespace {

// Writes the rig's images of one frame as the rig's observation type(s).
void WriteCameras(RawlogWriter& out, const Scenario& s, double t, int frame,
                  const std::vector<RenderedFrame>& renders,
                  const Eigen::Isometry3d& robot_from_head,
                  const std::vector<Eigen::Isometry3d>& offsets) {
  const std::string stem = core::FrameStem(frame);
  switch (s.rig.kind) {
    case RigKind::kMono:
      out.WriteImage(t, "CAMERA", renders[0].rgb, s.camera, robot_from_head, stem);
      break;
    case RigKind::kRgbd:
      out.WriteRgbd(t, renders[0].rgb, renders[0].depth, s.camera, robot_from_head, stem);
      break;
    case RigKind::kStereo:
      out.WriteStereo(t, renders[0].rgb, renders[1].rgb, s.camera, robot_from_head, s.rig.baseline,
                      stem);
      break;
    case RigKind::kTrinocular: {
      const char* labels[] = {"CAM_CENTER", "CAM_LEFT", "CAM_RIGHT"};
      const char* suffix[] = {"_center", "_left", "_right"};
      for (int i = 0; i < 3; ++i) {
        out.WriteImage(t, labels[i], renders[i].rgb, s.camera, robot_from_head * offsets[i],
                       stem + suffix[i]);
      }
      break;
    }
  }
}

// Camera `camera` of frame k: independent noise per camera and frame, the exposure of now.
RenderOptions FrameRenderOptions(const Scenario& s, const ScenarioWorld& world, std::uint64_t seed,
                                 int k, int camera) {
  RenderOptions ro = s.render;
  ro.exposure = world.CurrentExposure();
  ro.seed = seed;
  ro.frame = std::uint64_t(k) * 4 + std::uint64_t(camera);
  return ro;
}

// CDnet's temporal ROI: the phases after the first, clipped to the frames written.
std::pair<int, int> TemporalRoi(const Scenario& s, int frames) {
  if (s.phases.size() < 2) return {1, frames};
  return {std::min(s.phases[1].first_frame, frames), std::min(s.phases.back().last_frame, frames)};
}

// The frame's CDnet labels: the foreground's pixels against a render of its background.
cv::Mat CdnetFrameTruth(const ScenarioWorld& world, const Scenario& s, const RenderedFrame& frame,
                        const Lighting& lighting, const RenderOptions& ro) {
  RayScene background;
  world.AddBackgroundToScene(background);
  background.Commit();
  const RenderedFrame b = Render(background, lighting, s.camera, world.HeadPose(), ro);
  return CdnetTruth(frame.ids, world.AddedIds(), frame.rgb, b.rgb);
}

}  // namespace

RunSummary RunScenario(const Scenario& s, const RunOptions& o) {
  const auto wall_start = std::chrono::steady_clock::now();
  const int frames = o.frames ? *o.frames : s.frames;
  if (frames <= 0 || frames > s.frames) {
    throw std::invalid_argument(s.file + ": --frames must be in 1…" + std::to_string(s.frames) +
                                ", got " + std::to_string(frames));
  }
  if (o.cdnet && !s.static_camera)
    throw std::invalid_argument(s.file +
                                ": the CDnet layout is for a fixed camera (static_camera)");
  const std::uint64_t seed = o.seed ? *o.seed : s.seed;
  std::filesystem::create_directories(o.out_dir);
  std::optional<CdnetWriter> cdnet;
  const std::string cdnet_dir = o.out_dir + "/" + s.name + "_cdnet";
  if (o.cdnet) {
    const auto [first, last] = TemporalRoi(s, frames);
    cdnet.emplace(cdnet_dir, first, last);
  }

  ScenarioWorld world(s);
  LedTracker tracker(LedTrackerSpec{}, seed ^ 0x7EA4u);
  RawlogWriter rawlog(o.out_dir, s.name);
  const std::vector<Eigen::Isometry3d> offsets = world.RigOffsets();
  GroundTruthWriter truth(o.out_dir, s, offsets);

  const int tile_every = std::max(1, frames / std::max(1, o.contact_sheet_tiles));
  std::vector<std::pair<std::string, cv::Mat>> tiles;
  double next_tracker = 0.0;
  const double tracker_period = 1.0 / tracker.spec().rate_hz;
  for (int k = 0; k < frames; ++k) {
    const double t = k / s.fps;
    for (; next_tracker <= t + 1e-9; next_tracker += tracker_period) {
      world.AdvanceTo(next_tracker);
      rawlog.WriteTracker(next_tracker, tracker.Measure(world.HeadPose()),
                          tracker.spec().noise_std);
    }
    world.AdvanceTo(t);
    if (world.robot()) rawlog.WriteOdometry(t, world.robot()->odometry());

    RayScene scene;
    world.AddToScene(scene);
    scene.Commit();
    const Lighting lighting = world.CurrentLighting();
    const Eigen::Isometry3d head = world.HeadPose();
    std::vector<RenderedFrame> renders;
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      renders.push_back(Render(scene, lighting, s.camera, head * offsets[i],
                               FrameRenderOptions(s, world, seed, k, int(i))));
    }
    WriteCameras(rawlog, s, t, k + 1, renders, world.RobotFromHead(), offsets);
    if (cdnet) {
      // The background is rendered with the frame's noise, so that it cancels.
      cdnet->WriteFrame(k + 1, renders[0].rgb,
                        CdnetFrameTruth(world, s, renders[0], lighting,
                                        FrameRenderOptions(s, world, seed, k, 0)));
    }

    RayScene reference;  // the scene with removed objects back in place (novelty masks)
    world.AddNoveltyReferenceToScene(reference);
    reference.Commit();
    const cv::Mat reference_ids = RenderIds(reference, s.camera, head);
    const cv::Mat novelty = GroundTruthWriter::NoveltyMask(renders[0].ids, reference_ids,
                                                           world.AddedIds(), world.RemovedIds());
    truth.WriteFrame(k + 1, t, head, world.robot(), renders[0].depth, renders[0].ids, novelty);
    if (k % tile_every == 0 && int(tiles.size()) < o.contact_sheet_tiles) {
      tiles.push_back({"frame " + std::to_string(k + 1), renders[0].rgb.clone()});
    }
    if (o.progress && ((k + 1) % 10 == 0 || k + 1 == frames)) {
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      std::fprintf(stderr, "\r[novelty-sim] %s: frame %d/%d (%.0f%%), %.1f frames/s   ",
                   s.name.c_str(), k + 1, frames, 100.0 * (k + 1) / frames, (k + 1) / elapsed);
    }
  }
  if (o.progress) std::fprintf(stderr, "\n");
  truth.WriteEvents(world.applied_events());
  truth.WriteObjects();
  rawlog.Close();

  RunSummary summary;
  summary.frames = frames;
  summary.observations = rawlog.observations();
  summary.rawlog = rawlog.rawlog_path();
  summary.contact_sheet = o.out_dir + "/" + s.name + "_contact_sheet.png";
  if (o.cdnet) summary.cdnet_dir = cdnet_dir;
  core::WriteRgbImage(summary.contact_sheet, ContactSheet(tiles, 6));
  summary.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return summary;
}

}  // namespace novelty::sim
