// Reads an MRPT rawlog in the "observations" format object by object — the one place that opens
// rawlogs, points MRPT's external-image lookup at `<name>_Images/`, and turns a truncated or
// foreign file into an error naming the file and the object.
#pragma once

#include <mrpt/serialization/CSerializable.h>

#include <memory>
#include <string>

namespace novelty::sensors {

/// `<dir>/<name>_Images` for `<dir>/<name>.rawlog`: where MRPT keeps a rawlog's external images.
std::string ImagesDirOf(const std::string& rawlog);

class RawlogInput {
 public:
  /// Opens `path` and makes MRPT resolve external images against its `_Images/` folder (one
  /// process-wide setting in MRPT). Throws std::runtime_error naming the file if it is missing
  /// or cannot be opened.
  explicit RawlogInput(const std::string& path);
  ~RawlogInput();

  /// The next object, or nullptr at the end. Throws std::runtime_error "PATH: cannot read object
  /// N: …" for a truncated or foreign file.
  mrpt::serialization::CSerializable::Ptr Next();
  /// 1-based number of the object Next() returned last.
  int object() const { return objects_; }
  const std::string& path() const { return path_; }

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  int objects_ = 0;
};

}  // namespace novelty::sensors
