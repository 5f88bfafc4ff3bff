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

// Mean Σβ of a view (its "ab_sigma" plane, channels 1…3), for the frustum colour.
double MeanUncertainty(const views::ReferenceView& v) {
  cv::Mat p;
  v.planes.at("ab_sigma").convertTo(p, CV_32F);
  const cv::Scalar m = cv::mean(p.reshape(1, int(p.total())).colRange(1, 4));
  return m[0] + m[1] + m[2];
}

}  // namespace

CAppearanceMap::CAppearanceMap(const appearance::AppearanceMapOptions& options)
    : map_(std::make_unique<appearance::AppearanceMap>(options)) {}

bool CAppearanceMap::isEmpty() const {
  return map_->store().size() == 0;
}

std::string CAppearanceMap::asString() const {
  std::ostringstream s;
  s << "CAppearanceMap: " << map_->store().size() << " reference views, "
    << map_->store().BytesUsed() / (1024 * 1024) << " MiB";
  return s.str();
}

void CAppearanceMap::internal_clear() {
  map_ = std::make_unique<appearance::AppearanceMap>(map_->options());
  last_ = {};
}

bool CAppearanceMap::internal_insertObservation(
    const mrpt::obs::CObservation& obs, const std::optional<const mrpt::poses::CPose3D>& robot) {
  ObservedFrame f;
  try {
    if (!DecodeObservation(obs, robot, f)) return false;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("CAppearanceMap: ") + e.what());
  }
  InsertFrame(f.rgb, f.depth, f.camera, f.T_world_cam);
  return true;
}

const appearance::AppearanceProducts& CAppearanceMap::InsertFrame(
    const cv::Mat& rgb, const cv::Mat& depth, const views::PinholeCamera& camera,
    const Eigen::Isometry3d& T_world_cam) {
  last_ = map_->Insert(rgb, depth, camera, T_world_cam);
  return last_;
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
  return 0;
}

void CAppearanceMap::serializeTo(mrpt::serialization::CArchive& out) const {
  appearance::AppearanceMapOptions o = map_->options();
  VisitOptions(
      out, o, [](auto& a, double& v) { a << v; }, [](auto& a, bool& v) { a << v; });
  WriteViewMap(out, map_->view_map());
}

void CAppearanceMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  if (version != 0) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  appearance::AppearanceMapOptions o;
  VisitOptions(
      in, o, [](auto& a, double& v) { a >> v; }, [](auto& a, bool& v) { a >> v; });
  auto map = std::make_unique<appearance::AppearanceMap>(o);
  ReadViewMap(in, map->view_map());
  map_ = std::move(map);  // only now: a failure above leaves the map as it was
  last_ = {};
}

void CAppearanceMap::SaveToFile(const std::string& path) const {
  SaveAtomically(*this, path);
}

void CAppearanceMap::LoadFromFile(const std::string& path) {
  RegisterMaps();         // the archive names the class
  CAppearanceMap loaded;  // a fresh map: on failure this one is untouched
  LoadInto(loaded, path, "CAppearanceMap");
  map_ = std::move(loaded.map_);
  last_ = {};
}

void CAppearanceMap::SaveSceneFile(const std::string& path) const {
  mrpt::opengl::COpenGLScene scene;
  auto objects = mrpt::opengl::CSetOfObjects::Create();
  getVisualizationInto(*objects);
  scene.insert(objects);
  const std::string tmp = path + ".tmp";
  if (!scene.saveToFile(tmp)) throw std::runtime_error(path + ": cannot write the scene");
  std::filesystem::rename(tmp, path);
}

void CAppearanceMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
  SaveToFile(prefix + ".appearance_map");
}

// --- CMultiMetricMap integration ---------------------------------------------------------------

CAppearanceMap::TMapDefinition::TMapDefinition() = default;

void CAppearanceMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
  options = LoadAppearanceMapOptions(source, prefix + "_options", "map definition");
}

void CAppearanceMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
  out << "CAppearanceMap: forgetting_factor=" << options.surprise.update.forgetting_factor
      << " xi=" << options.surprise.update.xi
      << " new_view_distance=" << options.views.new_view_distance << "\n";
}

mrpt::maps::CMetricMap* CAppearanceMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
  const auto& d = dynamic_cast<const CAppearanceMap::TMapDefinition&>(def);
  return new CAppearanceMap(d.options);
}

}  // namespace novelty::mrpt_plugins
