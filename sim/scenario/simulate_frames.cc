#include "sim/scenario/simulate_frames.h"

#include "sim/output/ground_truth_writer.h"
#include "sim/render/renderer.h"
#include "sim/scenario/scenario_world.h"

namespace novelty::sim {

std::vector<SimulatedFrame> SimulateFrames(const Scenario& s, int frames) {
  const int n = frames > 0 ? std::min(frames, s.frames) : s.frames;
  ScenarioWorld world(s);
  std::vector<SimulatedFrame> out;
  out.reserve(std::size_t(n));
  for (int k = 0; k < n; ++k) {
    SimulatedFrame f;
    f.index = k + 1;
    f.time = k / s.fps;
    world.AdvanceTo(f.time);
    RayScene scene, reference;
    world.AddToScene(scene);
    scene.Commit();
    world.AddNoveltyReferenceToScene(reference);
    reference.Commit();
    RenderOptions ro = s.render;
    ro.frame = std::uint64_t(k);
    f.T_world_cam = world.HeadPose();
    const RenderedFrame r = Render(scene, world.CurrentLighting(), s.camera, f.T_world_cam, ro);
    f.rgb = r.rgb;
    f.depth = r.depth;
    f.novelty = GroundTruthWriter::NoveltyMask(r.ids, RenderIds(reference, s.camera, f.T_world_cam),
                                               world.AddedIds(), world.RemovedIds());
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace novelty::sim
