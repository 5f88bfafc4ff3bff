#include "core/resident_memory.h"

#include <unistd.h>

#include <cmath>
#include <fstream>

namespace novelty::core {

double ResidentMegabytes() {
  std::ifstream statm("/proc/self/statm");
  long total = 0, resident = 0;
  if (!(statm >> total >> resident)) return std::nan("");
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

}  // namespace novelty::core
