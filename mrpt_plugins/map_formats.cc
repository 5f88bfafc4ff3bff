#include "mrpt_plugins/map_formats.h"

#include <stdexcept>

#include "mrpt_plugins/option_table.h"

namespace novelty::mrpt_plugins {

namespace {

struct ClassFormats {
  const char* map_class;
  uint8_t current;
  // The options versions 0 and 1 stored one after another, in order (1 appended the second list).
  std::vector<std::string> version0_keys, version1_keys;
};

// Versions of the view maps: 0 and 1 stored options positionally and planes raw, 2 options by
// key, 3 planes encoded (shuffled), 4 encoded with prediction. The others: version 1 added
// the object database's keypoints and the illumination map's texture tails, the illumination
// map's version 2 its decision threshold, the object database's version 2 its objects' names and
// outlines.
const std::vector<ClassFormats>& Classes() {
  static const std::vector<ClassFormats> classes = {
      {"CAppearanceMap",
       4,
       {"forgetting_factor", "xi", "sigma_min", "sigma_max", "initial_alpha", "initial_beta",
        "initial_tau", "initial_sigma", "fast_approximations", "half_precision",
        "new_view_distance", "new_view_angle_deg", "max_relative_depth_jump", "depth_tolerance"},
       {"min_variance", "angle_power", "weight_by_rays"}},
      {"CDifferencingMap",
       4,
       {"new_view_distance", "new_view_angle_deg", "max_relative_depth_jump", "depth_tolerance"},
       {"angle_power", "weight_by_rays"}},
      {"CObjectDatabaseMap", 2, {}, {}},
      {"CIlluminationInvariantMap", 2, {}, {}},
  };
  return classes;
}

const ClassFormats& Find(const std::string& map_class) {
  for (const ClassFormats& c : Classes())
    if (map_class == c.map_class) return c;
  throw std::logic_error("MapFormatOf: " + map_class + " has no map file");
}

}  // namespace

uint8_t CurrentMapFormat(const std::string& map_class) {
  return Find(map_class).current;
}

MapFormat MapFormatOf(const std::string& map_class, uint8_t version) {
  const ClassFormats& c = Find(map_class);
  if (version > c.current) {
    ThrowMapFileError("format version " + std::to_string(version) +
                      ", newer than this program's (" + std::to_string(c.current) + ")");
  }
  MapFormat f;
  f.version = version;
  const bool views = !c.version0_keys.empty();
  if (views) {
    f.options_by_key = version >= 2;
    if (!f.options_by_key) {
      f.positional_keys = c.version0_keys;
      if (version == 1)
        f.positional_keys.insert(f.positional_keys.end(), c.version1_keys.begin(),
                                 c.version1_keys.end());
    }
    f.raw_planes = version <= 2;
    f.encoding = version == 3 ? views::PlaneEncoding::kShuffled : views::PlaneEncoding::kPredicted;
  } else {
    f.learnt_keypoints = f.texture_tails = version >= 1;
    f.decision_threshold = c.map_class != std::string("CIlluminationInvariantMap") || version >= 2;
    f.object_info = c.map_class != std::string("CObjectDatabaseMap") || version >= 2;
  }
  return f;
}

}  // namespace novelty::mrpt_plugins
