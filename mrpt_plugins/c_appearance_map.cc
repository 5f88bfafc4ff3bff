#include "mrpt_plugins/c_appearance_map.h"

#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/map_files.h"
#include "mrpt_plugins/register_maps.h"
#include "sensors/rawlog/rgbd_observation.h"

using novelty::mrpt_plugins::CAppearanceMap;

MAP_DEFINITION_REGISTER("CAppearanceMap,novelty::mrpt_plugins::CAppearanceMap",
                        novelty::mrpt_plugins::CAppearanceMap)

IMPLEMENTS_SERIALIZABLE(CAppearanceMap, CMetricMap, novelty::mrpt_plugins)

namespace novelty::mrpt_plugins {

namespace {

// The options, in a fixed order (every field share/appearance.ini can set).
template <class Archive, class Double, class Bool>
void VisitOptions(Archive& a, appearance::AppearanceMapOptions& o, Double d, Bool b) {
  d(a, o.surprise.update.forgetting_factor);
  d(a, o.surprise.update.xi);
  d(a, o.surprise.update.sigma_min);
  d(a, o.surprise.update.sigma_max);
  d(a, o.initial_prior.alpha);
  d(a, o.initial_prior.beta);
  d(a, o.initial_prior.tau);
  d(a, o.initial_prior.sigma);
  b(a, o.surprise.kl.fast_approximations);
  b(a, o.half_precision);
  d(a, o.views.new_view_distance);
  d(a, o.views.new_view_angle);
  d(a, o.views.warp.max_relative_depth_jump);
  d(a, o.views.blend.depth_tolerance);
}

// Options added in version 1 (after the version-0 ones).
template <class Archive, class Double, class Bool>
void VisitOptionsV1(Archive& a, appearance::AppearanceMapOptions& o, Double d, Bool b) {
  d(a, o.surprise.update.min_variance);
  d(a, o.views.blend.angle_power);
  b(a, o.views.selection.weight_by_rays);
}

// A version-0 map was made without these: no variance floor, the plain average of distinct views.
void SetVersion0Behaviour(appearance::AppearanceMapOptions& o) {
  o.surprise.update.min_variance = 0.0;
  SetVersion0ViewOptions(o.views);
}

// Mean Σβ of a view (its "ab_sigma" plane, channels 1…3), for the frustum colour.
double MeanUncertainty(const views::ReferenceView& v) {
  cv::Mat p;
  v.planes.at("ab_sigma").convertTo(p, CV_32F);
  const cv::Scalar m = cv::mean(p.reshape(1, int(p.total())).colRange(1, 4));
  return m[0] + m[1] + m[2];
}

}  // namespace

CAppearanceMap::CAppearanceMap(const appearance::AppearanceMapOptions& options)
    : ViewMapAdapter(options, "CAppearanceMap", ".appearance_map") {}

std::string CAppearanceMap::asString() const {
  std::ostringstream s;
  s << "CAppearanceMap: " << map_->store().size() << " reference views, "
    << map_->store().BytesUsed() / (1024 * 1024) << " MiB";
  return s.str();
}

void CAppearanceMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
  const views::ReferenceViewStore& store = map_->store();
  std::vector<double> badness;
  for (int j = 0; j < store.size(); ++j) {
    badness.push_back(std::log1p(MeanUncertainty(store.view(j))) / std::log1p(1e4));
  }
  AddViewFrusta(store, badness, o);
}

uint8_t CAppearanceMap::serializeGetVersion() const {
  return 1;
}

void CAppearanceMap::serializeTo(mrpt::serialization::CArchive& out) const {
  appearance::AppearanceMapOptions o = map_->options();
  const auto write_double = [](auto& a, double& v) { a << v; };
  const auto write_bool = [](auto& a, bool& v) { a << v; };
  VisitOptions(out, o, write_double, write_bool);
  VisitOptionsV1(out, o, write_double, write_bool);
  WriteViewMap(out, map_->view_map());
}

void CAppearanceMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  if (version > 1) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  appearance::AppearanceMapOptions o;
  const auto read_double = [](auto& a, double& v) { a >> v; };
  const auto read_bool = [](auto& a, bool& v) { a >> v; };
  VisitOptions(in, o, read_double, read_bool);
  if (version >= 1) {
    VisitOptionsV1(in, o, read_double, read_bool);
  } else {
    SetVersion0Behaviour(o);
  }
  auto map = std::make_unique<appearance::AppearanceMap>(o);
  ReadViewMap(in, map->view_map());
  ReplaceMap(std::move(map));  // only now: a failure above leaves the map as it was
}

// --- CMultiMetricMap integration ---------------------------------------------------------------

CAppearanceMap::TMapDefinition::TMapDefinition() = default;

void CAppearanceMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
  const MapConfig config = LoadMapConfig(source, prefix + "_options", ConfigSourceName(source));
  options = config.map;
  depth_source = config.depth;
}

void CAppearanceMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
  out << "CAppearanceMap: forgetting_factor=" << options.surprise.update.forgetting_factor
      << " xi=" << options.surprise.update.xi
      << " new_view_distance=" << options.views.new_view_distance << "\n";
}

mrpt::maps::CMetricMap* CAppearanceMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
  const auto& d = dynamic_cast<const CAppearanceMap::TMapDefinition&>(def);
  auto* map = new CAppearanceMap(d.options);
  map->setDepthSource(d.depth_source);
  return map;
}

}  // namespace novelty::mrpt_plugins
