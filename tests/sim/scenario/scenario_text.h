// Test helper: a scenario parsed from the text of a .scn file.
#pragma once

#include <sstream>
#include <string>

#include "sim/scenario/scenario_parser.h"

namespace novelty::sim {

inline Scenario ParseScenarioText(const std::string& text) {
  std::istringstream in(text);
  return ParseScenario(in, "test.scn");
}

}  // namespace novelty::sim
