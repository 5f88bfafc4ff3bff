#include "mrpt_plugins/c_appearance_map.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/opengl/CFrustum.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "mrpt_plugins/appearance_map_options.h"
#include "sensors/rawlog/rgbd_observation.h"

using novelty::mrpt_plugins::CAppearanceMap;

MAP_DEFINITION_REGISTER("CAppearanceMap,novelty::mrpt_plugins::CAppearanceMap",
                        novelty::mrpt_plugins::CAppearanceMap)

IMPLEMENTS_SERIALIZABLE(CAppearanceMap, CMetricMap, novelty::mrpt_plugins)

namespace novelty::mrpt_plugins {

namespace {

// MRPT finds classes by name when reading archives: register ours once per process.
const bool kRegistered = [] {
  mrpt::rtti::registerClass(CLASS_ID(CAppearanceMap));
  return true;
}();

void WriteMat(mrpt::serialization::CArchive& out, const cv::Mat& m) {
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  out << int32_t(c.type()) << int32_t(c.rows) << int32_t(c.cols);
  out.WriteBuffer(c.data, c.total() * c.elemSize());
}

cv::Mat ReadMat(mrpt::serialization::CArchive& in) {
  int32_t type, rows, cols;
  in >> type >> rows >> cols;
  if (rows < 0 || cols < 0 || rows > 100000 || cols > 100000) {
    throw std::runtime_error("corrupt image size " + std::to_string(rows) + "x" +
                             std::to_string(cols));
  }
  cv::Mat m(rows, cols, type);
  in.ReadBuffer(m.data, m.total() * m.elemSize());
  return m;
}

void WritePose(mrpt::serialization::CArchive& out, const Eigen::Isometry3d& p) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) out << p.matrix()(r, c);
}

Eigen::Isometry3d ReadPose(mrpt::serialization::CArchive& in) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) in >> p.matrix()(r, c);
  return p;
}

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
  const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs);
  if (!scan) return false;
  scan->load();
  cv::Mat rgb, depth;
  views::PinholeCamera camera;
  try {
    sensors::DecodeRgbd(*scan, rgb, depth, camera);
  } catch (const std::exception& e) {
    throw std::invalid_argument("CAppearanceMap: observation '" + scan->sensorLabel +
                                "': " + e.what());
  }
  const Eigen::Isometry3d world_from_robot =
      robot ? sensors::ToEigen(*robot) : Eigen::Isometry3d::Identity();
  InsertFrame(rgb, depth, camera, world_from_robot * sensors::CameraOnRobot(*scan));
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
  // Frusta point along their +X: turn the camera's +Z onto it.
  Eigen::Isometry3d cam_from_frustum = Eigen::Isometry3d::Identity();
  cam_from_frustum.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  for (int j = 0; j < store.size(); ++j) {
    const views::ReferenceView& v = store.view(j);
    const double u = std::clamp(std::log1p(MeanUncertainty(v)) / std::log1p(1e4), 0.0, 1.0);
    const double hfov = 2.0 * std::atan(0.5 * v.camera.width / std::abs(v.camera.fx));
    const double vfov = 2.0 * std::atan(0.5 * v.camera.height / std::abs(v.camera.fy));
    auto f = mrpt::opengl::CFrustum::Create(0.01f, 0.08f, float(hfov * 180 / M_PI),
                                            float(vfov * 180 / M_PI), 1.0f, true, false);
    f->setColor_u8(uint8_t(255 * u), uint8_t(255 * (1 - u)), 40);
    f->setPose(sensors::ToMrpt(v.T_world_cam * cam_from_frustum));
    o.insert(f);
  }
}

uint8_t CAppearanceMap::serializeGetVersion() const {
  return 0;
}

void CAppearanceMap::serializeTo(mrpt::serialization::CArchive& out) const {
  appearance::AppearanceMapOptions o = map_->options();
  VisitOptions(
      out, o, [](auto& a, double& v) { a << v; }, [](auto& a, bool& v) { a << v; });
  const appearance::ViewBasedMap& views_map = map_->view_map();
  const views::ReferenceViewStore& store = views_map.store();
  out << int32_t(store.size());
  for (int j = 0; j < store.size(); ++j) {
    const views::ReferenceView& v = store.view(j);
    out << int32_t(v.camera.width) << int32_t(v.camera.height) << v.camera.fx << v.camera.fy
        << v.camera.cx << v.camera.cy;
    WritePose(out, v.T_world_cam);
    WritePose(out, views_map.anchors()[std::size_t(j)]);
    WriteMat(out, v.depth);
    out << int32_t(v.planes.size());
    for (const auto& [name, plane] : v.planes) {
      out << name;
      WriteMat(out, plane);
    }
  }
}

void CAppearanceMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  if (version != 0) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  appearance::AppearanceMapOptions o;
  VisitOptions(
      in, o, [](auto& a, double& v) { a >> v; }, [](auto& a, bool& v) { a >> v; });
  int32_t n;
  in >> n;
  if (n < 0 || n > 1000000) throw std::runtime_error("corrupt view count");
  std::vector<views::ReferenceView> views;
  std::vector<Eigen::Isometry3d> anchors;
  for (int32_t j = 0; j < n; ++j) {
    views::ReferenceView v;
    int32_t w, h;
    in >> w >> h >> v.camera.fx >> v.camera.fy >> v.camera.cx >> v.camera.cy;
    v.camera.width = w;
    v.camera.height = h;
    v.T_world_cam = ReadPose(in);
    anchors.push_back(ReadPose(in));
    v.depth = ReadMat(in);
    int32_t planes;
    in >> planes;
    for (int32_t k = 0; k < planes; ++k) {
      std::string name;
      in >> name;
      v.planes[name] = ReadMat(in);
    }
    views.push_back(std::move(v));
  }
  auto map = std::make_unique<appearance::AppearanceMap>(o);
  map->view_map().Restore(std::move(views), std::move(anchors));
  map_ = std::move(map);  // only now: a failure above leaves the map as it was
  last_ = {};
}

void CAppearanceMap::SaveToFile(const std::string& path) const {
  const std::string tmp = path + ".tmp";
  {
    mrpt::io::CFileGZOutputStream file(tmp);
    if (!file.fileOpenCorrectly()) throw std::runtime_error(tmp + ": cannot open for writing");
    auto arch = mrpt::serialization::archiveFrom(file);
    arch << *this;
  }
  std::filesystem::rename(tmp, path);
}

void CAppearanceMap::LoadFromFile(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such map file");
  CAppearanceMap loaded;
  try {
    mrpt::io::CFileGZInputStream file(path);
    auto arch = mrpt::serialization::archiveFrom(file);
    arch >> loaded;
  } catch (const std::exception&) {
    // MRPT's own message spans several lines of parser detail; say what matters.
    throw std::runtime_error(path +
                             ": not a readable CAppearanceMap (truncated, or another kind "
                             "of file)");
  }
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
