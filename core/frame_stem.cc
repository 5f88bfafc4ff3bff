#include "core/frame_stem.h"

#include <cstdio>

namespace novelty::core {

std::string FrameStem(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d", frame);
  return buf;
}

}  // namespace novelty::core
