#include "mrpt_plugins/c_illumination_invariant_map.h"

#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/false_color.h"
#include "mrpt_plugins/cimage_products.h"
#include "mrpt_plugins/map_file.h"
#include "mrpt_plugins/map_formats.h"
#include "mrpt_plugins/observation_frame.h"
#include "mrpt_plugins/register_maps.h"
#include "mrpt_plugins/view_archive.h"
#include "mrpt_plugins/view_display.h"

using novelty::mrpt_plugins::CIlluminationInvariantMap;

MAP_DEFINITION_REGISTER(
    "CIlluminationInvariantMap,novelty::mrpt_plugins::CIlluminationInvariantMap",
    novelty::mrpt_plugins::CIlluminationInvariantMap)

IMPLEMENTS_SERIALIZABLE(CIlluminationInvariantMap, CMetricMap, novelty::mrpt_plugins)

namespace novelty::mrpt_plugins {

namespace {

constexpr int32_t kMaxViewpoints = 100000;
constexpr int32_t kMaxTailEntries = 4096;  // a missing-texture tail table (64 by default)

void WriteFit(mrpt::serialization::CArchive& out, const stats::GammaFit& f) {
  out << f.alpha << f.beta;
}

stats::GammaFit ReadFit(mrpt::serialization::CArchive& in) {
  stats::GammaFit f;
  in >> f.alpha >> f.beta;
  return f;
}

}  // namespace

CIlluminationInvariantMap::CIlluminationInvariantMap(const IlluminationInvariantMapConfig& config)
    : config_(config), map_(std::make_unique<illumination::IlluminationMap>(config.map)) {}

bool CIlluminationInvariantMap::internal_insertObservation(
    const mrpt::obs::CObservation& obs,
    const std::optional<const mrpt::poses::CPose3D>& robot_pose) {
  core::Frame f;
  if (!DecodeObservation(obs, robot_pose, f)) return false;
  if (!map_->built()) {
    map_->AddTrainingFrame(f);
    return true;
  }
  last_ = map_->Detect(f);
  last_frame_ = std::move(f);
  return true;
}

void CIlluminationInvariantMap::internal_clear() {
  map_ = std::make_unique<illumination::IlluminationMap>(config_.map);
  last_frame_ = {};
  last_ = {};
}

std::string CIlluminationInvariantMap::asString() const {
  std::ostringstream s;
  const illumination::IlluminationMap& m = *map_;
  s << "CIlluminationInvariantMap: " << m.lightings() << " lightings, " << m.size()
    << " viewpoints";
  if (!m.built()) return s.str() + " (acquiring)";
  double coverage = 0.0, threshold = 0.0;
  for (int i = 0; i < m.size(); ++i) {
    coverage += m.model(i).coverage / m.size();
    threshold += m.model(i).model.threshold / m.size();
  }
  s << " (" << m.dropped_viewpoints() << " dropped), mean coverage " << 100.0 * coverage
    << " %, mean T_Y " << threshold << ", decision threshold ";
  if (std::isnan(m.decision_threshold()))
    s << "none";
  else
    s << m.decision_threshold() << " nats at " << 100.0 * m.options().threshold.false_alarm_rate
      << " % false alarms";
  s << ", " << m.BytesUsed() / 1e6 << " MB";
  return s.str();
}

void CIlluminationInvariantMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
  if (!map_->built()) return;
  std::vector<double> badness;
  for (int i = 0; i < map_->size(); ++i) badness.push_back(1.0 - map_->model(i).coverage);
  AddViewFrusta(map_->store(), badness, o);
}

mrpt::img::CImage CIlluminationInvariantMap::invariantImage() const {
  if (last_.coverage == 0.0) return {};
  return ToCImage(
      illumination::LinearImage8(last_.viewpoint.log_invariant, last_.viewpoint.covered));
}

mrpt::img::CImage CIlluminationInvariantMap::noveltyImage(double max_novelty) const {
  if (last_.novelty.novelty.empty()) return {};
  return ToCImage(core::FalseColor(last_.novelty.novelty, max_novelty));
}

mrpt::img::CImage CIlluminationInvariantMap::informationImage(double max_information) const {
  if (last_.novelty.information_y.empty()) return {};
  return ToCImage(core::FalseColor(last_.novelty.information_y, max_information));
}

void CIlluminationInvariantMap::SaveToFile(const std::string& path) const {
  if (!map_->built())
    throw std::logic_error(
        "CIlluminationInvariantMap: still acquiring; call finishAcquisition() "
        "before saving " +
        path);
  SaveAtomically(*this, path);
}

void CIlluminationInvariantMap::LoadFromFile(const std::string& path) {
  RegisterMaps();                    // the archive names the class
  CIlluminationInvariantMap loaded;  // a fresh map: on failure this one is untouched
  LoadInto(loaded, path, "CIlluminationInvariantMap");
  config_ = loaded.config_;
  map_ = std::move(loaded.map_);
  last_frame_ = {};
  last_ = {};
}

void CIlluminationInvariantMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
  SaveToFile(prefix + ".illumination_invariant");
}

// Map file: every option by key (option_table.h); the lightings and viewpoint counts; per
// viewpoint its view (view_archive.h WriteView: camera, pose, depth, planes "invariant" and
// "shapes"), its coverage, its model (gamma fits of luminance and saturation, quantisation
// widths, mean information, T_Y) and the missing texture's tail table (entries, values,
// ln(N + 1); no entries: not learnt), energy floor and block; the texture's scale is the view's
// plane "texture"; then the decision threshold on Δ (NaN: none learnt). Older versions:
// map_formats.h.
uint8_t CIlluminationInvariantMap::serializeGetVersion() const {
  return CurrentMapFormat("CIlluminationInvariantMap");
}

void CIlluminationInvariantMap::serializeTo(mrpt::serialization::CArchive& out) const {
  if (!map_->built())
    throw std::logic_error(
        "CIlluminationInvariantMap: still acquiring (call finishAcquisition() before saving)");
  IlluminationInvariantMapConfig::Table().Write(out, config_);
  out << int32_t(map_->lightings()) << int32_t(map_->size());
  for (int i = 0; i < map_->size(); ++i) {
    WriteView(out, map_->view(i));
    const illumination::IlluminationViewpointModel& m = map_->model(i);
    out << m.coverage;
    WriteFit(out, m.model.luminance);
    WriteFit(out, m.model.saturation);
    out << m.model.luminance_step << m.model.saturation_step << m.model.mean_information
        << m.model.threshold;
    out << int32_t(m.model.texture.values.size());
    for (float v : m.model.texture.values) out << v;
    out << m.model.texture.max_information << m.model.texture_floor
        << int32_t(m.model.texture_block);
  }
  out << map_->decision_threshold();
}

void CIlluminationInvariantMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  const MapFormat format = MapFormatOf("CIlluminationInvariantMap", version);
  IlluminationInvariantMapConfig config;
  IlluminationInvariantMapConfig::Table().Read(in, config);
  int32_t lightings = 0, viewpoints = 0;
  in >> lightings >> viewpoints;
  if (lightings < 2 || lightings > illumination::kMaxLightings || viewpoints < 1 ||
      viewpoints > kMaxViewpoints)
    ThrowMapFileError(std::to_string(lightings) + " lightings and " + std::to_string(viewpoints) +
                      " viewpoints");
  auto map = std::make_unique<illumination::IlluminationMap>(config.map);
  for (int32_t i = 0; i < viewpoints; ++i) {
    const std::string what = "viewpoint " + std::to_string(i);
    views::ReferenceView view = ReadView(in, what);
    illumination::IlluminationViewpointModel m;
    in >> m.coverage;
    m.model.luminance = ReadFit(in);
    m.model.saturation = ReadFit(in);
    in >> m.model.luminance_step >> m.model.saturation_step >> m.model.mean_information >>
        m.model.threshold;
    if (format.texture_tails) {
      int32_t entries = 0, block = 0;
      in >> entries;
      if (entries < 0 || entries > kMaxTailEntries)
        ThrowMapFileError(what + ": " + std::to_string(entries) + " tail entries");
      m.model.texture.values.resize(std::size_t(entries));
      for (float& v : m.model.texture.values) in >> v;
      in >> m.model.texture.max_information >> m.model.texture_floor >> block;
      m.model.texture_block = block;  // AddViewpoint checks the table, floor and block
    }
    for (double v :
         {m.coverage, m.model.luminance_step, m.model.saturation_step, m.model.mean_information,
          m.model.threshold, m.model.saturation.alpha, m.model.saturation.beta,
          m.model.texture.max_information, m.model.texture_floor})
      if (!std::isfinite(v) || v < 0)
        ThrowMapFileError(what + ": a model value is negative or not finite");
    try {
      map->AddViewpoint(std::move(view), std::move(m), lightings);
    } catch (const std::invalid_argument& e) {  // the content, not the archive, is wrong
      ThrowMapFileError(e.what());
    }
  }
  double threshold = std::numeric_limits<double>::quiet_NaN();  // older files: none learnt
  if (format.decision_threshold) in >> threshold;
  try {
    map->SetDecisionThreshold(threshold);
  } catch (const std::invalid_argument& e) {
    ThrowMapFileError(e.what());
  }
  config_ = config;  // only now: a failure above leaves the map as it was
  map_ = std::move(map);
  last_frame_ = {};
  last_ = {};
}

// --- CMultiMetricMap integration ---------------------------------------------------------------

CIlluminationInvariantMap::TMapDefinition::TMapDefinition() = default;

void CIlluminationInvariantMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
  config = IlluminationInvariantMapConfig::FromConfig(source, prefix + "_options",
                                                      ConfigSourceName(source));
}

void CIlluminationInvariantMap::TMapDefinition::dumpToTextStream_map_specific(
    std::ostream& out) const {
  config.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CIlluminationInvariantMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
  return new CIlluminationInvariantMap(
      dynamic_cast<const CIlluminationInvariantMap::TMapDefinition&>(def).config);
}

}  // namespace novelty::mrpt_plugins
