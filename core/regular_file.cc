#include "core/regular_file.h"

#include <filesystem>
#include <stdexcept>

namespace novelty::core {

void CheckRegularFile(const std::string& path, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  if (ec || !fs::exists(s)) throw std::runtime_error(path + ": no such file");
  if (!fs::is_regular_file(s))
    throw std::runtime_error(path + ": not a regular file (a folder, device or FIFO)");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) throw std::runtime_error(path + ": cannot read its size");
  if (bytes > max_bytes)
    throw std::runtime_error(path + ": " + std::to_string(bytes) + " bytes, more than the " +
                             std::to_string(max_bytes) + " expected of it");
}

}  // namespace novelty::core
