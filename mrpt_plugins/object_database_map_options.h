// The options of CObjectDatabaseMap: the surprise-driven acquisition's (maps/objects/
// object_acquisition.h) in one table (option_table.h), with the best measured setting as defaults —
// share/object_database.ini is the dump of them (tested), share/thesis/ the thesis's.
#pragma once

#include "maps/objects/object_acquisition.h"
#include "mrpt_plugins/option_table.h"

namespace novelty::mrpt_plugins {

struct ObjectDatabaseMapConfig : public TabledOptions<ObjectDatabaseMapConfig> {
  /// The best measured setting, "the 90 % setting" of docs/objects.md (TPR 90.0–91.3 % at FPR
  /// 0.3 % in I3, 63.9 % in the held-out room): SIFT, a 12 px closing, the depth tests
  /// (learn_unchanged_change, learn_only_nearer_features, nearer_is_surprising,
  /// depth_of_room_at_start), static_features_recognise and verify_pose on; every other option
  /// objects::ObjectAcquisitionOptions' default (the thesis's algorithm). The thesis's settings,
  /// 22.3 % there: share/thesis/object_database.ini.
  ObjectDatabaseMapConfig();

  objects::ObjectAcquisitionOptions map;
  /// Beyond the thesis: the added/removed decision and the nearer-than-the-map tests
  /// (learn_only_nearer_features, nearer_is_surprising, grow_focus_over_nearer) compare with the
  /// depth the appearance map's views hold now together with what they held at the first frame
  /// this map used — the room as the robot knew it when it began to look for objects
  /// (c_object_database_map.h) — so that an object stays added after the views have taken in its
  /// depth. false: the views now.
  bool depth_of_room_at_start = true;

  static const OptionTable<ObjectDatabaseMapConfig>& Table();
  static constexpr const char* kClass = "CObjectDatabaseMap";
  /// The options section of the first CObjectDatabaseMap of a CMultiMetricMap .ini whose maps are
  /// declared in [map] (MRPT's naming: <section>_<Class>_<NN>_options), as in share/*.ini.
  static constexpr const char* kSection = "map_CObjectDatabaseMap_00_options";
};

}  // namespace novelty::mrpt_plugins
