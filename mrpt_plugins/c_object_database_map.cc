#include "mrpt_plugins/c_object_database_map.h"

#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "maps/objects/feature_extractor.h"
#include "mrpt_plugins/map_file.h"
#include "mrpt_plugins/map_formats.h"
#include "mrpt_plugins/register_maps.h"

using novelty::mrpt_plugins::CObjectDatabaseMap;

MAP_DEFINITION_REGISTER("CObjectDatabaseMap,novelty::mrpt_plugins::CObjectDatabaseMap",
                        novelty::mrpt_plugins::CObjectDatabaseMap)

IMPLEMENTS_SERIALIZABLE(CObjectDatabaseMap, CMetricMap, novelty::mrpt_plugins)

namespace novelty::mrpt_plugins {

namespace {

// Bounds on what a map file may claim before anything is allocated: a corrupt count must not ask
// for gigabytes.
constexpr int32_t kMaxObjects = 1 << 16, kMaxFeatures = 1 << 22;

void WriteVector(mrpt::serialization::CArchive& out, const Eigen::Vector3d& p) {
  out << p.x() << p.y() << p.z();
}

Eigen::Vector3d ReadVector(mrpt::serialization::CArchive& in) {
  Eigen::Vector3d p;
  in >> p.x() >> p.y() >> p.z();
  return p;
}

// An object's name and outline (map format 2): the name as its length and bytes, so that a
// corrupt length is refused before anything is allocated.
void WriteInfo(mrpt::serialization::CArchive& out, const objects::ObjectInfo& info) {
  out << uint32_t(info.name.size());
  if (!info.name.empty()) out.WriteBuffer(info.name.data(), info.name.size());
  out << uint32_t(info.outline.size());
  for (const Eigen::Vector2d& p : info.outline) out << p.x() << p.y();
}

objects::ObjectInfo ReadInfo(mrpt::serialization::CArchive& in) {
  objects::ObjectInfo info;
  uint32_t length = 0, points = 0;
  in >> length;
  if (length > objects::FeatureDatabase::kMaxNameLength)
    ThrowMapFileError("an object name of " + std::to_string(length) + " characters");
  info.name.resize(length);
  if (length > 0 && in.ReadBuffer(info.name.data(), length) != length)
    ThrowMapFileError("the file ends inside an object name");
  in >> points;
  if (points > objects::FeatureDatabase::kMaxOutline)
    ThrowMapFileError("an object outline of " + std::to_string(points) + " points");
  info.outline.resize(points);
  for (Eigen::Vector2d& p : info.outline) in >> p.x() >> p.y();
  return info;
}

// A colour per object, well apart for neighbouring indices (golden-ratio hues).
mrpt::img::TColorf ObjectColour(int k) {
  const double h = std::fmod(0.61803398875 * k, 1.0) * 6.0;
  const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  const int sector = int(h);
  const double rgb[6][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}, {x, 0, 1}, {1, 0, x}};
  return mrpt::img::TColorf(float(rgb[sector][0]), float(rgb[sector][1]), float(rgb[sector][2]));
}

}  // namespace

CObjectDatabaseMap::CObjectDatabaseMap(const ObjectDatabaseMapConfig& config)
    : mrpt::system::COutputLogger("CObjectDatabaseMap"),
      config_(config),
      acquisition_(std::make_unique<objects::ObjectAcquisition>(config.map)) {}

CObjectDatabaseMap::~CObjectDatabaseMap() {
  if (const auto appearance = appearance_.lock()) appearance->removeFrameConsumer(this);
}

void CObjectDatabaseMap::linkAppearanceMap(const std::shared_ptr<CAppearanceMap>& appearance) {
  if (!appearance) throw std::invalid_argument("CObjectDatabaseMap: no CAppearanceMap to link");
  const auto linked = appearance_.lock();
  if (appearance == linked) return;
  if (linked) linked->removeFrameConsumer(this);
  room_.reset();  // taken from the new map at its next frame
  appearance->setPredictDepth(true);
  appearance->addFrameConsumer(this);
  appearance_ = appearance;
}

bool CObjectDatabaseMap::internal_insertObservation(
    const mrpt::obs::CObservation&, const std::optional<const mrpt::poses::CPose3D>&) {
  if (appearance_.expired())
    throw std::logic_error(
        "CObjectDatabaseMap: not linked to a CAppearanceMap (call LinkObjectDatabaseMaps(multimap) "
        "after its maps are made)");
  return false;  // the frame came, or comes, with the appearance map's insertion
}

void CObjectDatabaseMap::ConsumeAppearanceFrame(const CAppearanceMap& appearance) {
  if (paused_) return;
  const core::Frame& f = appearance.lastFrame();
  const appearance::AppearanceProducts& p = appearance.lastProducts();
  const cv::Mat expected_depth =
      config_.depth_of_room_at_start ? ExpectedDepthWithRoom(appearance) : p.expected_depth_span;
  last_ =
      acquisition_->Process(f.rgb, f.depth, p.surprise, expected_depth, f.camera, *f.T_world_cam);
  if (last_.learner.recognised == objects::LearnerStep::Recognised::kNewObject) {
    // At the object's index: objects may have been added to the database by hand before.
    learnt_at_.resize(std::size_t(last_.learner.object),
                      Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
    learnt_at_.push_back(f.T_world_cam->translation());
  }
  ++frames_used_;
}

// The room's farthest surface tells an object added since this map's first frame, which the
// appearance map's views take in as the robot passes it; the views now tell one removed since,
// which the room may never have held. So the span of both: added if nearer than the farthest of
// either, removed if farther than the nearest of either. The room is taken at the first frame
// (that frame's own depth among it: the map's prediction before the frame covers it) and again
// when the appearance map is loaded or cleared.
cv::Mat CObjectDatabaseMap::ExpectedDepthWithRoom(const CAppearanceMap& appearance) {
  if (!room_ || room_maps_replaced_ != appearance.mapsReplaced()) {
    room_ = std::make_unique<appearance::RoomDepth>(appearance.map().view_map());
    room_maps_replaced_ = appearance.mapsReplaced();
  }
  const appearance::AppearanceProducts& p = appearance.lastProducts();
  // At the pose the prior was predicted at (align_to_prior may have turned it).
  const cv::Mat room = room_->DepthSpan(appearance.lastFrame().camera, p.T_world_cam);
  return p.expected_depth_span.empty() ? room
                                       : appearance::UnionOfDepthSpans(p.expected_depth_span, room);
}

void CObjectDatabaseMap::internal_clear() {
  acquisition_ = std::make_unique<objects::ObjectAcquisition>(config_.map);
  learnt_at_.clear();
  room_.reset();
  last_ = {};
  frames_used_ = 0;
}

std::vector<Eigen::Vector3d> CObjectDatabaseMap::learntAt() const {
  std::vector<Eigen::Vector3d> at = learnt_at_;
  at.resize(std::size_t(database().objects()),
            Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
  return at;
}

std::string CObjectDatabaseMap::asString() const {
  const objects::FeatureDatabase& db = database();
  std::vector<int> features(std::size_t(db.objects()), 0);
  for (int h = 0; h < db.features(); ++h) ++features[std::size_t(db.MostProbableObject(h))];
  std::ostringstream s;
  s << "CObjectDatabaseMap: " << db.objects() << " objects, " << db.features() << " "
    << objects::FeatureExtractorName(config_.map.extractor) << " features";
  const std::vector<Eigen::Vector3d> learnt_at = learntAt();
  for (int k = 0; k < db.objects(); ++k) {
    const Eigen::Vector3d& at = learnt_at[std::size_t(k)];
    s << "\n  object " << k << ": " << features[std::size_t(k)] << " features, learnt from ("
      << at.x() << ", " << at.y() << ", " << at.z() << ")";
  }
  return s.str();
}

void CObjectDatabaseMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
  const objects::FeatureDatabase& db = database();
  std::vector<Eigen::Vector3d> sum(std::size_t(db.objects()), Eigen::Vector3d::Zero());
  std::vector<int> placed(std::size_t(db.objects()), 0);
  auto cloud = mrpt::opengl::CPointCloudColoured::Create();
  cloud->setPointSize(4.0f);
  for (int h = 0; h < db.features(); ++h) {
    const Eigen::Vector3d& p = db.Position(h);
    if (!p.allFinite()) continue;
    const int k = db.MostProbableObject(h);
    const mrpt::img::TColorf c = ObjectColour(k);
    cloud->push_back(float(p.x()), float(p.y()), float(p.z()), c.R, c.G, c.B);
    sum[std::size_t(k)] += p;
    ++placed[std::size_t(k)];
  }
  o.insert(cloud);
  for (int k = 0; k < db.objects(); ++k) {
    if (placed[std::size_t(k)] == 0) continue;
    const Eigen::Vector3d c = sum[std::size_t(k)] / placed[std::size_t(k)];
    auto label = mrpt::opengl::CText::Create(db.DisplayName(k));
    label->setLocation(c.x(), c.y(), c.z() + 0.05);
    label->setColor(ObjectColour(k));
    o.insert(label);
  }
}

void CObjectDatabaseMap::SaveToFile(const std::string& path) const {
  SaveAtomically(*this, path);
}

void CObjectDatabaseMap::LoadFromFile(const std::string& path) {
  RegisterMaps();             // the archive names the class
  CObjectDatabaseMap loaded;  // a fresh map: on failure this one is untouched
  LoadInto(loaded, path, "CObjectDatabaseMap");
  config_ = loaded.config_;
  acquisition_ = std::move(loaded.acquisition_);
  learnt_at_ = std::move(loaded.learnt_at_);
  room_.reset();
  last_ = {};
  frames_used_ = 0;
}

void CObjectDatabaseMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
  SaveToFile(prefix + ".object_database");
}

// Map file: every option by key (option_table.h); the object count; the descriptors (rows, width,
// floats); per feature its counts (object, n) and its 3-D place; per object where it was learnt;
// per feature its learnt keypoint's orientation and metric size (NaN unknown); per object its name
// and outline (objects::ObjectInfo). Older versions:
// map_formats.h.
uint8_t CObjectDatabaseMap::serializeGetVersion() const {
  return CurrentMapFormat("CObjectDatabaseMap");
}

void CObjectDatabaseMap::serializeTo(mrpt::serialization::CArchive& out) const {
  ObjectDatabaseMapConfig::Table().Write(out, config_);
  const objects::FeatureDatabase& db = database();
  const cv::Mat& d = db.descriptors();
  out << int32_t(db.objects()) << int32_t(d.rows) << int32_t(d.rows ? d.cols : 0);
  for (int h = 0; h < d.rows; ++h)
    out.WriteBufferFixEndianness(d.ptr<float>(h), std::size_t(d.cols));
  for (const auto& counts : db.counts()) {
    out << uint32_t(counts.size());
    for (const auto& [object, n] : counts) out << int32_t(object) << int32_t(n);
  }
  for (int h = 0; h < d.rows; ++h) WriteVector(out, db.Position(h));
  for (const Eigen::Vector3d& at : learntAt()) WriteVector(out, at);
  for (int h = 0; h < d.rows; ++h) out << db.Keypoint(h).angle_deg << db.Keypoint(h).size_m;
  for (int k = 0; k < db.objects(); ++k) WriteInfo(out, db.Info(k));
}

void CObjectDatabaseMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  const MapFormat format = MapFormatOf("CObjectDatabaseMap", version);
  ObjectDatabaseMapConfig config;
  ObjectDatabaseMapConfig::Table().Read(in, config);
  int32_t objects = 0, rows = 0, cols = 0;
  in >> objects >> rows >> cols;
  if (objects < 0 || objects > kMaxObjects || rows < 0 || rows > kMaxFeatures)
    ThrowMapFileError(std::to_string(objects) + " objects and " + std::to_string(rows) +
                      " features");
  const int width = objects::DescriptorWidth(config.map.extractor);
  if (rows > 0 && cols != width)
    ThrowMapFileError("descriptors of width " + std::to_string(cols) + ", but " +
                      objects::FeatureExtractorName(config.map.extractor) + " gives " +
                      std::to_string(width));
  // Everything grows as it is read, never by what the file claims: a truncated or corrupt file
  // fails at its end, having allocated no more than it held.
  cv::Mat d(0, width, CV_32F), row(1, width, CV_32F);
  for (int h = 0; h < rows; ++h) {
    in.ReadBufferFixEndianness(row.ptr<float>(), std::size_t(width));
    d.push_back(row);
  }
  objects::FeatureDatabase::Counts counts;
  for (int h = 0; h < rows; ++h) {
    uint32_t n = 0;
    in >> n;
    if (n > uint32_t(objects)) ThrowMapFileError(std::to_string(n) + " counts for a feature");
    counts.emplace_back();
    for (uint32_t i = 0; i < n; ++i) {
      int32_t k = 0, m = 0;
      in >> k >> m;
      counts.back().emplace_back(k, m);
    }
  }
  std::vector<Eigen::Vector3d> positions, learnt_at;
  for (int h = 0; h < rows; ++h) positions.push_back(ReadVector(in));
  for (int k = 0; k < objects; ++k) learnt_at.push_back(ReadVector(in));
  std::vector<objects::LearntKeypoint> keypoints;
  for (int h = 0; format.learnt_keypoints && h < rows; ++h) {
    keypoints.emplace_back();
    in >> keypoints.back().angle_deg >> keypoints.back().size_m;
  }
  std::vector<objects::ObjectInfo> info;
  for (int k = 0; format.object_info && k < objects; ++k) info.push_back(ReadInfo(in));
  auto acquisition = std::make_unique<objects::ObjectAcquisition>(config.map);
  try {
    acquisition->learner().database() =
        objects::FeatureDatabase::FromParts(objects, d, counts, positions, keypoints, info);
  } catch (const std::invalid_argument& e) {  // the content, not the archive, is wrong
    ThrowMapFileError(e.what());
  }
  config_ = config;  // only now: a failure above leaves the map as it was
  acquisition_ = std::move(acquisition);
  learnt_at_ = std::move(learnt_at);
  room_.reset();
  last_ = {};
}

// --- CMultiMetricMap integration ---------------------------------------------------------------

CObjectDatabaseMap::TMapDefinition::TMapDefinition() = default;

void CObjectDatabaseMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
  config =
      ObjectDatabaseMapConfig::FromConfig(source, prefix + "_options", ConfigSourceName(source));
}

void CObjectDatabaseMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
  config.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CObjectDatabaseMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
  return new CObjectDatabaseMap(
      dynamic_cast<const CObjectDatabaseMap::TMapDefinition&>(def).config);
}

void LinkObjectDatabaseMaps(mrpt::maps::CMultiMetricMap& maps) {
  std::shared_ptr<CAppearanceMap> appearance;
  for (const auto& m : maps.maps) {
    if (auto a = std::dynamic_pointer_cast<CAppearanceMap>(m)) {
      appearance = a;
      break;
    }
  }
  for (const auto& m : maps.maps) {
    if (auto o = std::dynamic_pointer_cast<CObjectDatabaseMap>(m)) {
      if (!appearance)
        throw std::invalid_argument(
            "CObjectDatabaseMap needs a CAppearanceMap in the multimap (it takes the appearance "
            "map's surprise of each frame)");
      o->linkAppearanceMap(appearance);
    }
  }
}

}  // namespace novelty::mrpt_plugins
