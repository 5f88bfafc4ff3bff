// The illumination-invariant image of one viewpoint from a folder of images of it under different
// lights (thesis 6.1.2), its illumination images (eq. 6.14) and their statistics (6.2: gamma
// models, information maps, the shapes of highlights and strong shadows) — the library side of
// novelty-invariant.
//
// The folder holds the lightings (sensors/dataset/lighting_folder_reader.h) and optionally
// mask.png; in the MIT Intrinsic Images layout (reflectance.png, shading.png, diffuse.png) the
// decomposition is also scored with the benchmark's LMSE. The output folder gets invariant.png
// (linear, the inputs' bit depth and scale), illumination/ (L = I / R as 8 bits, 1 → 128),
// information/ (i_Y in false colour, 0 … 2 T_Y), shapes/ (255 where i_Y > T_Y), panels/,
// model.csv, findings.csv and report.html.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "eval/findings_table.h"
#include "eval/lmse.h"
#include "maps/illumination/illumination_map.h"
#include "sensors/dataset/lighting_folder_reader.h"

namespace novelty::experiments {

struct InvariantImageRunResult {
  eval::FindingsTable findings;  ///< as findings.csv holds them
  std::string summary;           ///< one line: lightings, seconds, the gamma models, T_Y
  int lightings = 0;
  double threshold = 0.0;                    ///< T_Y (eq. 6.18)
  std::optional<eval::IntrinsicScore> lmse;  ///< in the MIT layout
};

/// Learns the invariant image and the model from the lightings in `folder` with the options of
/// CIlluminationInvariantMap (`map.invariant`, `map.model`) and writes the results into `out_dir`
/// (an existing folder); `pick` says which of the folder's images are lightings. `status` is told
/// the input's size and what the patterns left out. Throws std::invalid_argument naming the
/// folder or option (fewer lightings than `min_lightings`, images of different sizes, ...).
InvariantImageRunResult RunInvariantImage(
    const std::string& folder, const illumination::IlluminationMapOptions& map,
    const std::string& out_dir, const std::function<void(const std::string&)>& status = {},
    const sensors::LightingFolderOptions& pick = {});

}  // namespace novelty::experiments
