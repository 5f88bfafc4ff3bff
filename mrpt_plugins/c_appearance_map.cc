#include "mrpt_plugins/c_appearance_map.h"

#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/register_maps.h"
#include "mrpt_plugins/view_display.h"
#include "sensors/rawlog/rgbd_observation.h"

using novelty::mrpt_plugins::CAppearanceMap;

MAP_DEFINITION_REGISTER("CAppearanceMap,novelty::mrpt_plugins::CAppearanceMap",
                        novelty::mrpt_plugins::CAppearanceMap)

IMPLEMENTS_SERIALIZABLE(CAppearanceMap, CMetricMap, novelty::mrpt_plugins)

namespace novelty::mrpt_plugins {

namespace {

// Mean Σβ of a view (its "ab_sigma" plane, channels 1…3), for the frustum colour.
double MeanUncertainty(const views::ReferenceView& v) {
  cv::Mat p;
  v.planes.at("ab_sigma").convertTo(p, CV_32F);
  const cv::Scalar m = cv::mean(p.reshape(1, int(p.total())).colRange(1, 4));
  return m[0] + m[1] + m[2];
}

}  // namespace

CAppearanceMap::CAppearanceMap(const AppearanceMapConfig& config)
    : ViewMapAdapter(config, "CAppearanceMap", ".appearance_map") {}

void CAppearanceMap::addFrameConsumer(AppearanceFrameConsumer* consumer) {
  if (std::find(consumers_.begin(), consumers_.end(), consumer) == consumers_.end())
    consumers_.push_back(consumer);
}

void CAppearanceMap::removeFrameConsumer(AppearanceFrameConsumer* consumer) {
  consumers_.erase(std::remove(consumers_.begin(), consumers_.end(), consumer), consumers_.end());
}

void CAppearanceMap::FrameInserted() {
  for (AppearanceFrameConsumer* c : consumers_) c->ConsumeAppearanceFrame(*this);
}

std::string CAppearanceMap::asString() const {
  std::ostringstream s;
  s << "CAppearanceMap: " << StoreSummary(map_->store());
  return s.str();
}

void CAppearanceMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
  const views::ReferenceViewStore& store = map_->store();
  std::vector<double> badness;
  for (int j = 0; j < store.size(); ++j) {
    badness.push_back(std::log1p(MeanUncertainty(store.Decoded(j))) / std::log1p(1e4));
  }
  AddViewFrusta(store, badness, o);
}

uint8_t CAppearanceMap::serializeGetVersion() const {
  return FileVersion();
}

void CAppearanceMap::serializeTo(mrpt::serialization::CArchive& out) const {
  WriteMapFile(out);
}

void CAppearanceMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  ReadMapFile(in, version);
}

// --- CMultiMetricMap integration ---------------------------------------------------------------

CAppearanceMap::TMapDefinition::TMapDefinition() = default;

void CAppearanceMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
  config = AppearanceMapConfig::FromConfig(source, prefix + "_options", ConfigSourceName(source));
}

void CAppearanceMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
  config.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CAppearanceMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
  return new CAppearanceMap(dynamic_cast<const CAppearanceMap::TMapDefinition&>(def).config);
}

}  // namespace novelty::mrpt_plugins
