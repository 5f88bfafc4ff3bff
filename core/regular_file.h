// A file an input reader may open: a regular file (after links) of at most a given size. A FIFO
// would block the reader forever, a device such as /dev/zero would feed it without end, and a
// folder cannot be read: each is refused by name before anything is opened.
#pragma once

#include <cstdint>
#include <string>

namespace novelty::core {

/// Throws std::runtime_error starting with `path`: missing, not a regular file, or larger than
/// `max_bytes`.
void CheckRegularFile(const std::string& path, std::uintmax_t max_bytes = std::uintmax_t(1) << 30);

}  // namespace novelty::core
