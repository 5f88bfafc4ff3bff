// Test helper: the scene of the appearance-map tests, after thesis 4.3 — a robot drives an arc
// around a table with a striped cloth twice (the first pass builds the map, the second sees the
// same scene), then a cup is added and it drives the arc a third time.
#pragma once

#include <string>

namespace novelty::appearance {

inline constexpr const char* kClip = R"(
name clip
frames 102
fps 7
seed 5
camera 160 120 60
rig rgbd
sensor noise 1.0 gamma 2.2
mount 0.0 0.0 1.10 90 16
room 6 6 2.8
ambient 0.10 0.10 0.11
material wood phong 0.45 0.28 0.14 0.1 20
material cloth phong 0.92 0.90 0.84
texture cloth stripes 0.25 0.35 0.70 20
material red phong 0.75 0.10 0.08 0.2 30
material black phong 0.04 0.04 0.05 0.5 60
object table box 1.2 0.8 0.72 wood at 0 0 fixed
object cloth plane 1.3 0.9 cloth at 0 0 on table
object box box 0.14 0.06 0.20 red at 0.25 0.20 on cloth mass 0.4
object cup cup 0.05 0.11 black at -0.05 -0.05 on cloth absent mass 0.25
lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9
arc 0 0 1.6 -100 -80 0.15
stop 0.5
arc 0 0 1.6 -80 -100 0.15
stop 0.5
arc 0 0 1.6 -100 -80 0.15
stop 1.0
event 9.0 add cup
)";

// The same clip with a glass instead of the black cup (4.3: the transparent glass), at the
// thesis's 320×240, with a tin plate whose highlights move with the viewpoint and a second lamp:
// the view-dependent changes that differencing takes for novelty.
inline std::string GlassClipText() {
  std::string text = kClip;
  const auto replace = [&text](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("material black phong 0.04 0.04 0.05 0.5 60", "material black glass 0.96 0.98 0.96 0.6 300 1.5");
  replace("camera 160 120 60", "camera 320 240 60");
  const std::string lamp = "lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9";
  replace(lamp, lamp + "\nlamp l2 1.2 -0.6 2.6 1.6 1.6 1.7" +
                    "\nmaterial tin metal 0.75 0.75 0.78 0.9 80 0.6" +
                    "\nobject plate plate 0.11 tin at -0.05 -0.25 on cloth mass 0.3");
  return text;
}

}  // namespace novelty::appearance
