// The one name of a frame's files: its 1-based number zero-padded to six digits ("000042"), as
// the ground truth, the panels and the virtual views are named.
#pragma once

#include <string>

namespace novelty::core {

std::string FrameStem(int frame);

}  // namespace novelty::core
