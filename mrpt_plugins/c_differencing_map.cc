#include "mrpt_plugins/c_differencing_map.h"

#include <mrpt/opengl/CSetOfObjects.h>

#include <sstream>

#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/map_files.h"
#include "mrpt_plugins/register_maps.h"

using novelty::mrpt_plugins::CDifferencingMap;

MAP_DEFINITION_REGISTER("CDifferencingMap,novelty::mrpt_plugins::CDifferencingMap",
                        novelty::mrpt_plugins::CDifferencingMap)

IMPLEMENTS_SERIALIZABLE(CDifferencingMap, CMetricMap, novelty::mrpt_plugins)

namespace novelty::mrpt_plugins {

CDifferencingMap::CDifferencingMap(const appearance::ViewBasedMapOptions& options)
    : ViewMapAdapter(options, "CDifferencingMap", ".differencing_map") {}

std::string CDifferencingMap::asString() const {
  std::ostringstream s;
  s << "CDifferencingMap: " << map_->store().size() << " reference views";
  return s.str();
}

void CDifferencingMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
  AddViewFrusta(map_->store(), {}, o);
}

uint8_t CDifferencingMap::serializeGetVersion() const {
  return 1;  // 1: the blend's angle_power and the view selection's weight_by_rays
}

void CDifferencingMap::serializeTo(mrpt::serialization::CArchive& out) const {
  const appearance::ViewBasedMapOptions& o = map_->options();
  out << o.new_view_distance << o.new_view_angle << o.warp.max_relative_depth_jump
      << o.blend.depth_tolerance << o.blend.angle_power << o.selection.weight_by_rays;
  WriteViewMap(out, map_->view_map());
}

void CDifferencingMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  if (version > 1) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  appearance::ViewBasedMapOptions o;
  in >> o.new_view_distance >> o.new_view_angle >> o.warp.max_relative_depth_jump >>
      o.blend.depth_tolerance;
  if (version >= 1) {
    in >> o.blend.angle_power >> o.selection.weight_by_rays;
  } else {
    SetVersion0ViewOptions(o);
  }
  auto map = std::make_unique<appearance::DifferencingMap>(o);
  ReadViewMap(in, map->view_map());
  ReplaceMap(std::move(map));  // only now: a failure above leaves the map as it was
}

CDifferencingMap::TMapDefinition::TMapDefinition() = default;

void CDifferencingMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
  const MapConfig config = LoadMapConfig(source, prefix + "_options", ConfigSourceName(source));
  options = config.map.views;
  depth_source = config.depth;
}

void CDifferencingMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
  out << "CDifferencingMap: new_view_distance=" << options.new_view_distance << "\n";
}

mrpt::maps::CMetricMap* CDifferencingMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
  const auto& d = dynamic_cast<const CDifferencingMap::TMapDefinition&>(def);
  auto* map = new CDifferencingMap(d.options);
  map->setDepthSource(d.depth_source);
  return map;
}

}  // namespace novelty::mrpt_plugins
