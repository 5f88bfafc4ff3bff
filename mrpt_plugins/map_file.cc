#include "mrpt_plugins/map_file.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/temporary_file.h"
#include "mrpt_plugins/option_table.h"
#include "sensors/rawlog/brief_message.h"

namespace novelty::mrpt_plugins {
namespace {

constexpr std::array<char, 8> kMagic = {'N', 'V', 'M', 'A', 'P', 'C', 'R', 'C'};
constexpr std::size_t kTrailer = kMagic.size() + 4;

uint32_t Crc(uint32_t crc, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const Bytef*>(data);
  while (bytes > 0) {  // zlib takes at most 4 GiB a call
    const uInt n = uInt(std::min<std::size_t>(bytes, 1u << 30));
    crc = uint32_t(crc32(crc, p, n));
    p += n;
    bytes -= n;
  }
  return crc;
}

// A file stream that keeps the CRC-32 of what is written through it.
class ChecksummedOutput : public mrpt::io::CStream {
 public:
  explicit ChecksummedOutput(mrpt::io::CFileOutputStream& file) : file_(file) {}
  size_t Read(void*, size_t) override { throw std::logic_error("ChecksummedOutput: no reading"); }
  size_t Write(const void* buffer, size_t count) override {
    crc_ = Crc(crc_, buffer, count);
    return file_.Write(buffer, count);
  }
  uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override {
    throw std::logic_error("ChecksummedOutput: no seeking");
  }
  uint64_t getTotalBytesCount() const override { return file_.getTotalBytesCount(); }
  uint64_t getPosition() const override { return file_.getPosition(); }
  uint32_t crc() const { return crc_; }

 private:
  mrpt::io::CFileOutputStream& file_;
  uint32_t crc_ = uint32_t(crc32(0L, Z_NULL, 0));
};

void PutLittleEndian(uint32_t v, unsigned char* out) {
  for (int k = 0; k < 4; ++k) out[k] = static_cast<unsigned char>(v >> (8 * k));
}

uint32_t GetLittleEndian(const unsigned char* in) {
  uint32_t v = 0;
  for (int k = 0; k < 4; ++k) v |= uint32_t(in[k]) << (8 * k);
  return v;
}

}  // namespace

void SaveAtomically(const mrpt::serialization::CSerializable& object, const std::string& path) {
  try {
    // A new name created exclusively: a file or link already at "<path>.tmp" is left alone.
    core::TemporaryFile tmp(path);
    {
      // Plain: the planes are compressed already (views::EncodePlane); MRPT's reader takes plain
      // and gzip'd files alike, so maps saved gzip'd before load as they did.
      mrpt::io::CFileOutputStream file(tmp.path());
      if (!file.fileOpenCorrectly()) throw std::runtime_error("cannot open " + tmp.path());
      ChecksummedOutput checked(file);
      auto arch = mrpt::serialization::archiveFrom(checked);
      arch << object;
      unsigned char trailer[kTrailer];
      std::memcpy(trailer, kMagic.data(), kMagic.size());
      PutLittleEndian(checked.crc(), trailer + kMagic.size());
      file.Write(trailer, kTrailer);
      file.close();
    }
    tmp.Commit();  // on disk, then renamed: a power cut leaves the old map or the new one
  } catch (const std::exception& e) {  // MRPT's own message spans many lines: one is enough
    throw std::runtime_error(path + ": cannot save (folder missing, not writable or full?): " +
                             sensors::BriefMessage(e));
  }
}

bool IsMapFileOf(const std::string& path, const std::string& kind) {
  std::ifstream in(path, std::ios::binary);
  std::string head(64, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  return head.find(kind) != std::string::npos;
}

MapChecksum CheckMapChecksum(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the map file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < std::streamoff(kTrailer)) return MapChecksum::kMissing;
  unsigned char trailer[kTrailer];
  in.seekg(size - std::streamoff(kTrailer));
  in.read(reinterpret_cast<char*>(trailer), kTrailer);
  if (!in) throw std::runtime_error(path + ": cannot read the map file");
  if (std::memcmp(trailer, kMagic.data(), kMagic.size()) != 0) return MapChecksum::kMissing;
  in.seekg(0);
  uint32_t crc = uint32_t(crc32(0L, Z_NULL, 0));
  std::vector<char> buffer(1 << 20);
  for (std::streamoff left = size - std::streamoff(kTrailer); left > 0;) {
    const std::streamsize n = std::streamsize(std::min<std::streamoff>(left, buffer.size()));
    in.read(buffer.data(), n);
    if (in.gcount() != n) throw std::runtime_error(path + ": cannot read the map file");
    crc = Crc(crc, buffer.data(), std::size_t(n));
    left -= n;
  }
  return crc == GetLittleEndian(trailer + kMagic.size()) ? MapChecksum::kMatches
                                                         : MapChecksum::kMismatch;
}

void LoadInto(mrpt::serialization::CSerializable& object, const std::string& path,
              const std::string& kind) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such map file");
  if (std::filesystem::is_directory(path))
    throw std::runtime_error(path + ": is a folder, not a map file");
  if (CheckMapChecksum(path) == MapChecksum::kMismatch)
    throw std::runtime_error(path + ": the checksum does not match: the " + kind +
                             " file was changed or damaged after it was saved");
  try {
    mrpt::io::CFileGZInputStream file(path);
    auto arch = mrpt::serialization::archiveFrom(file);
    arch >> object;
  } catch (const std::exception& e) {
    // What our own reader says of the file's content (OptionTable: "map file: …") is kept; MRPT's
    // own message spans several lines of parser detail: say what matters.
    const std::string what = e.what();
    if (const auto ours = what.find(kMapFileError); ours != std::string::npos) {
      const auto from = ours + std::string(kMapFileError).size();
      throw std::runtime_error(path + ": " + what.substr(from, what.find('\n', from) - from));
    }
    throw std::runtime_error(path + ": not a readable " + kind +
                             " (truncated, or another kind of file)");
  }
}

}  // namespace novelty::mrpt_plugins
