#include "mrpt_plugins/c_differencing_map.h"

#include <mrpt/opengl/CSetOfObjects.h>

#include <sstream>

#include "mrpt_plugins/register_maps.h"
#include "mrpt_plugins/view_display.h"

using novelty::mrpt_plugins::CDifferencingMap;

MAP_DEFINITION_REGISTER("CDifferencingMap,novelty::mrpt_plugins::CDifferencingMap",
                        novelty::mrpt_plugins::CDifferencingMap)

IMPLEMENTS_SERIALIZABLE(CDifferencingMap, CMetricMap, novelty::mrpt_plugins)

namespace novelty::mrpt_plugins {

CDifferencingMap::CDifferencingMap(const DifferencingMapConfig& config)
    : ViewMapAdapter(config, "CDifferencingMap", ".differencing_map") {}

std::string CDifferencingMap::asString() const {
  std::ostringstream s;
  s << "CDifferencingMap: " << StoreSummary(map_->store());
  return s.str();
}

void CDifferencingMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
  AddViewFrusta(map_->store(), {}, o);
}

uint8_t CDifferencingMap::serializeGetVersion() const {
  return FileVersion();
}

void CDifferencingMap::serializeTo(mrpt::serialization::CArchive& out) const {
  WriteMapFile(out);
}

void CDifferencingMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  ReadMapFile(in, version);
}

CDifferencingMap::TMapDefinition::TMapDefinition() = default;

void CDifferencingMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
  config = DifferencingMapConfig::FromConfig(source, prefix + "_options", ConfigSourceName(source));
}

void CDifferencingMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
  config.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CDifferencingMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
  return new CDifferencingMap(dynamic_cast<const CDifferencingMap::TMapDefinition&>(def).config);
}

}  // namespace novelty::mrpt_plugins
