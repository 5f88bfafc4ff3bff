#include "sensors/rawlog/rig_frame_reader.h"

#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <array>
#include <optional>
#include <stdexcept>

#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::sensors {
namespace {

const char* const kTrinocular[3] = {"CAM_CENTER", "CAM_LEFT", "CAM_RIGHT"};

int TrinocularSlot(const std::string& label) {
  for (int i = 0; i < 3; ++i)
    if (label == kTrinocular[i]) return i;
  return -1;
}

void CheckSizes(const RigFrame& f) {
  for (size_t i = 0; i < f.images.size(); ++i)
    if (f.images[i].size() != f.images[0].size() || f.cameras[i].width != f.images[i].cols ||
        f.cameras[i].height != f.images[i].rows)
      throw std::runtime_error("camera " + std::to_string(i + 1) +
                               ": image size differs from the reference image or its intrinsics");
}

}  // namespace

class RigFrameReader::Impl {
 public:
  explicit Impl(const std::string& p) : path(p), input(p) {}
  std::string path;
  RawlogInput input;
  int frames = 0;
  // The trinocular triple being collected (by slot), all with the same timestamp.
  std::array<mrpt::obs::CObservationImage::Ptr, 3> triple;

  std::string Where(double time) const {
    return path + ": rig frame " + std::to_string(frames) + " (t=" + std::to_string(time) + ")";
  }
  bool TripleStarted() const { return triple[0] || triple[1] || triple[2]; }
  double TripleTime() const {
    for (const auto& o : triple)
      if (o) return mrpt::Clock::toDouble(o->timestamp);
    return 0.0;
  }
};

RigFrameReader::RigFrameReader(const std::string& path) : impl_(std::make_unique<Impl>(path)) {}

RigFrameReader::~RigFrameReader() = default;

RigFrame RigFrameFromStereo(mrpt::obs::CObservationStereoImages& obs) {
  obs.load();
  if (!obs.hasImageRight) throw std::runtime_error("stereo observation without a right image");
  RigFrame f;
  f.time = mrpt::Clock::toDouble(obs.timestamp);
  f.images = {RgbFromImage(obs.imageLeft), RgbFromImage(obs.imageRight)};
  f.cameras = {FromMrpt(obs.leftCamera), FromMrpt(obs.rightCamera)};
  f.ref_from_camera = {Eigen::Isometry3d::Identity(),
                       ToEigen(mrpt::poses::CPose3D(obs.rightCameraPose))};
  f.robot_from_reference = ToEigen(mrpt::poses::CPose3D(obs.cameraPose));
  obs.unload();
  return f;
}

static RigFrame FromTriple(std::array<mrpt::obs::CObservationImage::Ptr, 3>& triple) {
  RigFrame f;
  f.time = mrpt::Clock::toDouble(triple[0]->timestamp);
  const Eigen::Isometry3d robot_from_center = ToEigen(triple[0]->cameraPose);
  for (auto& obs : triple) {
    obs->load();
    f.images.push_back(RgbFromImage(obs->image));
    f.cameras.push_back(FromMrpt(obs->cameraParams));
    f.ref_from_camera.push_back(robot_from_center.inverse() * ToEigen(obs->cameraPose));
    obs->unload();
  }
  f.robot_from_reference = robot_from_center;
  return f;
}

bool RigFrameReader::Next(RigFrame& frame,
                          std::vector<mrpt::serialization::CSerializable::Ptr>* others) {
  Impl& s = *impl_;
  auto skip_triple = [&](const std::string& why) {
    ++s.frames;
    skip_reasons_.push_back(s.Where(s.TripleTime()) + ": " + why);
    s.triple = {};
  };
  while (true) {
    const auto obj = s.input.Next();  // throws, naming the object, for a damaged file
    if (!obj) {
      if (s.TripleStarted()) skip_triple("incomplete trinocular triple at the end");
      return false;
    }
    std::optional<RigFrame> ready;
    const auto* observation = dynamic_cast<const mrpt::obs::CObservation*>(obj.get());
    const double time = observation ? mrpt::Clock::toDouble(observation->timestamp) : 0.0;
    try {
      if (auto stereo = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(obj)) {
        ++s.frames;
        ready = RigFrameFromStereo(*stereo);
      } else if (auto image = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obj);
                 image && TrinocularSlot(image->sensorLabel) >= 0) {
        const int slot = TrinocularSlot(image->sensorLabel);
        if (s.TripleStarted() &&
            (s.triple[slot] || mrpt::Clock::toDouble(image->timestamp) != s.TripleTime()))
          skip_triple("incomplete trinocular triple");
        s.triple[slot] = image;
        if (!(s.triple[0] && s.triple[1] && s.triple[2])) continue;
        ++s.frames;
        auto triple = s.triple;
        s.triple = {};
        ready = FromTriple(triple);
      } else {
        if (others) others->push_back(obj);
        continue;
      }
      CheckSizes(*ready);
    } catch (const std::exception& e) {
      skip_reasons_.push_back(s.Where(time) + ": " + e.what());
      continue;
    }
    frame = std::move(*ready);
    frame.index = s.frames;
    return true;
  }
}

}  // namespace novelty::sensors
