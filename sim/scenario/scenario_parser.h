// Reads scenario files. One statement per line, `#` starts a comment, lengths in metres, angles
// in degrees, times in seconds, colours as r g b in 0…1 (lamp intensities may exceed 1).
//
//   name NAME                         frames N            fps F          seed S
//   camera WIDTH HEIGHT HFOV_DEG      rig mono|rgbd|stereo B|trinocular B
//   sensor noise SIGMA gamma G exposure E shadow_samples K pixel_samples N   (any subset, any
//                                     order; N × N rays per pixel, renderer.h)
//   mount X Y Z YAW_DEG PITCH_DEG     camera head on the robot (pitch: down positive)
//   static_camera X Y Z TX TY TZ      tripod at X Y Z looking at TX TY TZ (no robot)
//   room SX SY HEIGHT                 walls around the origin
//   window X Z W H                    opening in the +y wall, centre X Z, size W H
//   ambient R G B                     daylight DX DY DZ R G B      sky R G B (radiance outside)
//   material NAME phong R G B [KS N]  | metal R G B KS N REFLECTIVITY | glass R G B KS N IOR
//   texture MATERIAL checker|stripes R G B CELLS | image FILE  (FILE relative to the scenario)
//   object NAME box SX SY SZ | cylinder R H | sphere R | cup R H | plate R | plane SX SY
//          MATERIAL at X Y [yaw DEG] [on SUPPORT] [fixed] [absent] [mass KG]
//   lamp NAME X Y Z R G B [radius M] [off]
//   arc CX CY RADIUS FROM_DEG TO_DEG SPEED      stop SECONDS      repeat N
//   start_offset DX DY                robot placed off its trajectory's start (m)
//   event T add|remove OBJECT [arm SECONDS] | move OBJECT X Y [arm SECONDS]
//         | walk OBJECT X Y SECONDS       (slides there on its support at constant speed: a
//                                          person walking; no physics while it walks)
//         | lamp LAMP X Y Z | lamp_on LAMP | lamp_off LAMP
//         | sun DX DY DZ [over SECONDS]   (the daylight turns to this direction, linearly)
//         | exposure E [over SECONDS]     (the camera's exposure steps, or ramps, to E)
//   phase NAME FIRST LAST [DESCRIPTION…]        frames, 1-based, inclusive
//
// Every number is range-checked (beyond the ranges ODE and Embree assert, buffers take gigabytes
// or a run never ends): positions and centres |·| ≤ 1000 m (objects, arcs, moves ≤ 100 m; mount
// ≤ 10 m); sizes 1 mm…100 m; angles |·| ≤ 3600°, mount pitch ≤ 90°, field of view 1…170°;
// colours and intensities 0…10⁴; ks and reflectivity 0…1; shininess ≤ 10⁴; IOR 1…5; camera
// 8…4096 pixels a side with width·height·pixel_samples² ≤ 2²⁶ rays a frame; pixel_samples 1…8;
// shadow_samples 1…256; noise 0…100; gamma 0.1…10; exposure 10⁻⁴…10⁴; fps 0.1…1000; frames
// 1…10⁶; times 0…86400 s; arc speed ≤ 10 m/s; mass 1 g…10 t; repeat up to 10⁵ segments in all.
// NAME is a plain file name (letters, digits, _ - .), since outputs are named after it.
#pragma once

#include <istream>
#include <string>

#include "sim/scenario/scenario.h"

namespace novelty::sim {

/// Parses a scenario file. Throws std::runtime_error "FILE:LINE: problem" on any error,
/// including unknown keywords, bad numbers, references to undeclared names and events after the
/// end of the run.
Scenario LoadScenario(const std::string& path);

/// The same from a stream; `name_for_errors` is used in messages, `base_dir` for texture files.
Scenario ParseScenario(std::istream& in, const std::string& name_for_errors,
                       const std::string& base_dir = ".");

}  // namespace novelty::sim
