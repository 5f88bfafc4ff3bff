// What the map classes share: reading an RGB-D frame out of an observation, archiving a
// view-based map, and saving/loading MRPT-serialized maps atomically.
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/CSerializable.h>

#include <optional>
#include <string>
#include <vector>

#include "core/frame.h"
#include "maps/appearance/view_based_map.h"

namespace novelty::mrpt_plugins {

/// The frame of a CObservation3DRangeScan with an intensity image (loading external images),
/// its camera at robot_pose ⊕ sensor pose (robot at the origin if no pose). Returns false for
/// other observations; throws std::invalid_argument naming the sensor if the scan is unusable.
bool DecodeObservation(const mrpt::obs::CObservation& obs,
                       const std::optional<const mrpt::poses::CPose3D>& robot_pose,
                       core::Frame& frame);

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

/// "N reference views, X MiB", and for a compact store how many are decoded and how often
/// views were encoded and decoded: what asString says of a view-based map.
std::string StoreSummary(const views::ReferenceViewStore& store);

/// One frustum per reference view at its pose; `badness[j]` in [0, 1] colours view j from green
/// to red (empty: all grey).
void AddViewFrusta(const views::ReferenceViewStore& store, const std::vector<double>& badness,
                   mrpt::opengl::CSetOfObjects& o);

/// Serializes `object` to `path` through a temporary file (`path`.tmp, synced to disk) and a
/// rename: a process killed at any moment, or a full disk, leaves `path` the old map or the new.
void SaveAtomically(const mrpt::serialization::CSerializable& object, const std::string& path);
/// Deserializes `path` into `object` (a fresh one: on failure the caller's map is untouched);
/// throws std::runtime_error naming the file and `kind`.
void LoadInto(mrpt::serialization::CSerializable& object, const std::string& path,
              const std::string& kind);

}  // namespace novelty::mrpt_plugins
