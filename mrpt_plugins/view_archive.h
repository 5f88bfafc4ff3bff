// The reference views of a map file: camera, pose, anchor, depth and named planes per view, in
// the layout a MapFormat gives (map_formats.h), each value checked as it is read.
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <string>

#include "maps/appearance/view_based_map.h"
#include "mrpt_plugins/map_formats.h"

namespace novelty::mrpt_plugins {

/// Views (camera, pose, anchor, depth, named planes) of a view-based map, laid out as `format`
/// says: by default the current one (views::EncodedView, as a compact map holds them); older
/// layouts for tests that check older files still load.
void WriteViewMap(mrpt::serialization::CArchive& out, const appearance::ViewBasedMap& map,
                  const MapFormat& format = {});
/// Reads what WriteViewMap wrote in `format` into `map` (replacing its views only if all reads
/// succeed).
void ReadViewMap(mrpt::serialization::CArchive& in, appearance::ViewBasedMap& map,
                 const MapFormat& format = {});

/// One view alone (camera, pose, depth and planes encoded as a compact store holds them), for
/// maps whose views are not a ViewBasedMap's.
void WriteView(mrpt::serialization::CArchive& out, const views::ReferenceView& view);
/// The view WriteView wrote; throws std::runtime_error beginning with kMapFileError and naming
/// `what` when it is truncated, implausible or damaged.
views::ReferenceView ReadView(mrpt::serialization::CArchive& in, const std::string& what);

}  // namespace novelty::mrpt_plugins
