#include "sensors/rawlog/rawlog_input.h"

#include "sensors/rawlog/brief_message.h"

#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <stdexcept>

namespace novelty::sensors {

std::string ImagesDirOf(const std::string& rawlog) {
  const std::filesystem::path p(rawlog);
  return (p.parent_path() / (p.stem().string() + "_Images")).string();
}

class RawlogInput::Impl {
 public:
  explicit Impl(const std::string& path) : file(path) {}
  mrpt::io::CFileGZInputStream file;
};

RawlogInput::RawlogInput(const std::string& path) : path_(path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such rawlog");
  impl_ = std::make_unique<Impl>(path);
  if (!impl_->file.fileOpenCorrectly()) throw std::runtime_error(path + ": cannot open rawlog");
  mrpt::img::CImage::setImagesPathBase(ImagesDirOf(path));
}

RawlogInput::~RawlogInput() = default;

mrpt::serialization::CSerializable::Ptr RawlogInput::Next() {
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  mrpt::serialization::CSerializable::Ptr obj;
  try {
    arch >> obj;
  } catch (const mrpt::serialization::CExceptionEOF&) {
    return nullptr;
  } catch (const std::exception& e) {
    throw std::runtime_error(path_ + ": cannot read object " + std::to_string(objects_ + 1) + ": " +
                             BriefMessage(e));
  }
  ++objects_;
  return obj;
}

}  // namespace novelty::sensors
