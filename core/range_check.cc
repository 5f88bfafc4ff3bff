#include "core/range_check.h"

#include <sstream>
#include <stdexcept>

namespace novelty::core {

void CheckInRange(double value, double lo, double hi, const char* key) {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream o;
    o << key << " must be in [" << lo << ", " << hi << "], got " << value;
    throw std::invalid_argument(o.str());
  }
}

}  // namespace novelty::core
