// libFuzzer target: scenario files, parsed and — when they parse — built into the simulated world
// (ODE bodies, Embree geometry), where out-of-range numbers used to abort.
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_world.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const novelty::sim::Scenario s = novelty::sim::ParseScenario(in, "fuzz.scn", "/nonexistent");
    novelty::sim::ScenarioWorld world(s, 0.05);
    world.AdvanceTo(0.1);
  } catch (const std::runtime_error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
