#include "core/temporary_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace novelty::core {

TemporaryFile::TemporaryFile(const std::string& final_path) : final_path_(final_path) {
  std::vector<char> name(final_path.begin(), final_path.end());
  const std::string suffix = ".tmp.XXXXXX";
  name.insert(name.end(), suffix.begin(), suffix.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());  // O_CREAT | O_EXCL: never an existing name or link
  if (fd < 0)
    throw std::runtime_error(final_path + ": cannot create a temporary file beside it (" +
                             std::strerror(errno) + ")");
  // mkstemp gives 0600; a saved map or rawlog is as readable as any file the user writes.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  close(fd);
  path_ = name.data();
}

TemporaryFile::~TemporaryFile() {
  if (!committed_) std::remove(path_.c_str());
}

bool SyncToDisk(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = fsync(fd) == 0;
  close(fd);
  return ok;
}

void TemporaryFile::Commit() {
  if (committed_) return;
  if (!SyncToDisk(path_))
    throw std::runtime_error(final_path_ + ": cannot write (" + std::strerror(errno) + ")");
  // rename(2) replaces a symbolic link at the final name; it never writes through it.
  if (std::rename(path_.c_str(), final_path_.c_str()) != 0)
    throw std::runtime_error(final_path_ + ": cannot replace (" + std::strerror(errno) + ")");
  committed_ = true;
  SyncToDisk(std::filesystem::absolute(final_path_).parent_path().string());
}

}  // namespace novelty::core
