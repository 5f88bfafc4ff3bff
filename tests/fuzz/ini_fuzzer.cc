// libFuzzer target: a CMultiMetricMap `.ini` as a program reads it — our line check, the map
// declarations and every option table — and the maps it declares, constructed.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "mrpt_plugins/multi_map_config.h"
#include "mrpt_plugins/option_table.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::unique_ptr<mrpt::config::CConfigFileMemory> ini;
  try {
    novelty::mrpt_plugins::CheckIniText(text, "fuzz.ini");
    ini = std::make_unique<mrpt::config::CConfigFileMemory>(text);
  } catch (const std::exception&) {  // MRPT's parser ($eval{…} etc.): OpenConfigFile reports it
    return 0;
  }
  try {
    const auto maps = novelty::mrpt_plugins::LoadMultiMapConfig(*ini, "map", "fuzz.ini");
    mrpt::maps::CMultiMetricMap multi;
    multi.setListOfMaps(maps);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
