// Test helper: the object database's clip (c_object_database_map_test, the 5.2 experiment's
// test): an arc past a table, a photo-printed box put down (or taken away) at kEvent, the arc
// driven back; and the shared textures it prints on the box.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace novelty::mrpt_plugins {

// The shared textures folder, or "" (the photo-textured tests then skip).
inline std::string Textures() {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const std::string dir = std::string(shared ? shared : "") + "/textures";
  return shared && std::filesystem::exists(dir + "/fruits.jpg") ? dir : "";
}

// Pass 1 (frames before kEvent) sees the table; the robot stands for `stop` s from 3.5 s, the box
// is added (or removed) at kEvent, and the robot drives the arc back.
inline constexpr double kEvent = 4.0;  // s
inline std::string ClipText(bool box_added, double stop) {
  return std::string(R"(
name objects
frames 54
fps 7
seed 5
camera 320 240 60
rig rgbd
sensor noise 1.0 gamma 2.2
mount 0.0 0.0 1.10 90 16
room 6 6 2.8
ambient 0.10 0.10 0.11
material wood phong 0.45 0.28 0.14 0.1 20
material cloth phong 0.92 0.90 0.84
texture cloth stripes 0.25 0.35 0.70 20
material print phong 0.9 0.9 0.9 0.1 20
texture print image fruits.jpg
object table box 1.2 0.8 0.72 wood at 0 0 fixed
object cloth plane 1.3 0.9 cloth at 0 0 on table
)") + "object box box 0.40 0.12 0.30 print at 0.05 0.10 on cloth mass 0.4" +
         (box_added ? " absent\n" : "\n") + R"(lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9
arc 0 0 1.0 -105 -75 0.15
stop )" + std::to_string(stop) +
         R"(
arc 0 0 1.0 -75 -105 0.15
)" + "event 4.0 " +
         (box_added ? "add" : "remove") + " box\n";
}

}  // namespace novelty::mrpt_plugins
