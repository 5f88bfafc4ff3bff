// The reference views of a map file: camera, pose, anchor, depth and named planes per view, in
// the current format (4: encoded as a compact store holds them) and the older ones (3: shuffled
// planes; 0-2: raw images), each value checked as it is read.
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <string>

#include "maps/appearance/view_based_map.h"

namespace novelty::mrpt_plugins {

/// Views (camera, pose, anchor, depth, named planes) of a view-based map in map file format
/// `version`: 4 (views::EncodedView, as a compact map holds them), 3 (views::PlaneEncoding::
/// kShuffled) or ≤ 2 (raw images; versions 0-2, for tests).
void WriteViewMap(mrpt::serialization::CArchive& out, const appearance::ViewBasedMap& map,
                  uint8_t version = 4);
/// Reads what WriteViewMap wrote in `version` into `map` (replacing its views only if all reads
/// succeed).
void ReadViewMap(mrpt::serialization::CArchive& in, appearance::ViewBasedMap& map,
                 uint8_t version = 4);

/// One view alone (camera, pose, depth and planes encoded as a compact store holds them: map
/// file version 4's encoding), for maps whose views are not a ViewBasedMap's.
void WriteView(mrpt::serialization::CArchive& out, const views::ReferenceView& view);
/// The view WriteView wrote; throws std::runtime_error beginning with kMapFileError and naming
/// `what` when it is truncated, implausible or damaged.
views::ReferenceView ReadView(mrpt::serialization::CArchive& in, const std::string& what);

}  // namespace novelty::mrpt_plugins
