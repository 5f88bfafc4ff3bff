// What each format version of each map class's file holds, in this one place: a class writes
// only its current version, and its reader asks MapFormatOf what the version it meets lacks or
// stores differently instead of comparing version numbers itself (docs/map_storage.md lists the
// versions). A version newer than the current one is an error naming both.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "maps/views/plane_codec.h"

namespace novelty::mrpt_plugins {

/// The layout of one format version of one class's map file.
struct MapFormat {
  uint8_t version = 0;
  /// Options by key (option_table.h) — else the positional keys below, as files before option
  /// tables stored them; options they lack get OptionEntry::legacy.
  bool options_by_key = true;
  std::vector<std::string> positional_keys;
  /// Views (CAppearanceMap, CDifferencingMap): planes stored raw, or encoded as `encoding`.
  bool raw_planes = false;
  views::PlaneEncoding encoding = views::PlaneEncoding::kPredicted;
  /// CObjectDatabaseMap: each feature's learnt keypoint (orientation, metric size).
  bool learnt_keypoints = true;
  /// CObjectDatabaseMap: each object's name and photo outline (objects::ObjectInfo).
  bool object_info = true;
  /// CIlluminationInvariantMap: each viewpoint's missing-texture tail table.
  bool texture_tails = true;
  /// CIlluminationInvariantMap: the decision threshold on Δ learnt from the training lightings.
  bool decision_threshold = true;
};

/// The current version of `map_class`'s file ("CAppearanceMap", …); throws std::logic_error for
/// a class that has no map file.
uint8_t CurrentMapFormat(const std::string& map_class);

/// The layout of `map_class`'s files of `version`; throws std::runtime_error beginning with
/// kMapFileError for a version newer than the current one.
MapFormat MapFormatOf(const std::string& map_class, uint8_t version);

}  // namespace novelty::mrpt_plugins
