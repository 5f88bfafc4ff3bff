// Test helper: frames of the simulator's stereo scenario (6.4.1, the Pioneer's stereo camera on
// a quarter circle around a table), rendered straight into memory; hard shadows keep tests short.
// Shared by the visual-odometry tests.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <utility>

#include "sensors/localization/stereo_pair.h"
#include "sim/render/renderer.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_world.h"

namespace novelty::sensors {

class QuarterCircle {
 public:
  QuarterCircle()
      : s_(sim::LoadScenario(std::string(NOVELTY_SOURCE_DIR) +
                             "/share/scenarios/lambertian_table.scn")),
        world_(s_) {
    s_.render.soft_shadow_samples = 1;
  }
  struct RgbdFrame {
    cv::Mat rgb, depth;  ///< R G B; metres (0: no surface)
    core::PinholeCamera camera;
    Eigen::Isometry3d T_world_cam;
  };
  // The reference camera's colour and depth and its true T_world_cam at frame k (0-based).
  RgbdFrame Rgbd(int k) {
    world_.AdvanceTo(k / s_.fps);
    sim::RayScene scene;
    world_.AddToScene(scene);
    scene.Commit();
    sim::RenderOptions o = s_.render;
    o.frame = 2 * k;
    const Eigen::Isometry3d head = world_.HeadPose();
    sim::RenderedFrame f = sim::Render(scene, world_.CurrentLighting(), s_.camera, head, o);
    return {f.rgb, f.depth, s_.camera, head};
  }

  // The stereo pair and the true T_world_cam of the left (reference) camera at frame k (0-based).
  std::pair<StereoPair, Eigen::Isometry3d> Frame(int k) {
    const double t = k / s_.fps;
    world_.AdvanceTo(t);
    sim::RayScene scene;
    world_.AddToScene(scene);
    scene.Commit();
    const auto offsets = world_.RigOffsets();
    const Eigen::Isometry3d head = world_.HeadPose();
    sim::RenderOptions o = s_.render;
    o.frame = 2 * k;
    StereoPair pair;
    pair.time = t;
    pair.reference = sim::Render(scene, world_.CurrentLighting(), s_.camera, head, o).rgb;
    o.frame = 2 * k + 1;
    pair.other = sim::Render(scene, world_.CurrentLighting(), s_.camera, head * offsets[1], o).rgb;
    pair.reference_camera = pair.other_camera = s_.camera;
    pair.reference_from_other = offsets[1];
    return {pair, head};
  }

 private:
  sim::Scenario s_;
  sim::ScenarioWorld world_;
};

inline double AngleBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace novelty::sensors
