// A file written under a temporary name beside its final one and renamed over it at the end, so
// that a reader sees the old file or the complete new one, never half of one. The temporary name
// is new and created exclusively (O_CREAT | O_EXCL, as mkstemp does): a file or a symbolic link
// already there under a fixed name such as "out.map.tmp" is never opened, followed or replaced.
#pragma once

#include <string>

namespace novelty::core {

class TemporaryFile {
 public:
  /// Creates "<final_path>.tmp.XXXXXX" (an empty file, mode 0644 less the umask). Throws
  /// std::runtime_error naming `final_path` if its folder is missing or not writable.
  explicit TemporaryFile(const std::string& final_path);
  /// Removes the temporary file unless Commit() has renamed it.
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  /// The temporary file's name: write the content there, then call Commit().
  const std::string& path() const { return path_; }
  const std::string& final_path() const { return final_path_; }

  /// Flushes the temporary file to disk, renames it to the final name (replacing what was there:
  /// a link there is replaced, not followed) and flushes the folder, so that a power cut leaves
  /// the old file or the new one. Throws std::runtime_error naming the final path on failure.
  void Commit();

 private:
  std::string final_path_;
  std::string path_;
  bool committed_ = false;
};

/// fsync of a file or folder by name; false if it cannot be opened or synced.
bool SyncToDisk(const std::string& path);

}  // namespace novelty::core
