// libFuzzer target: map files of every map class, through the path a program loads them by
// (LoadFromFile: MRPT's archive, our options table, views and planes, their checks). The first
// byte picks the class (% 3 == 2: the object database, else odd: differencing, even: appearance); the rest is the file (MRPT reads plain and gzip'd files alike, and the
// seeds are plain, so that mutations reach the content).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "mrpt_plugins/c_object_database_map.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const std::string path = "/tmp/novelty_map_fuzz_" + std::to_string(getpid());
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  try {
    if (data[0] % 3 == 2) {
      novelty::mrpt_plugins::CObjectDatabaseMap map;
      map.LoadFromFile(path);
    } else if (data[0] & 1) {
      novelty::mrpt_plugins::CDifferencingMap map;
      map.LoadFromFile(path);
    } else {
      novelty::mrpt_plugins::CAppearanceMap map;
      map.LoadFromFile(path);
    }
  } catch (const std::runtime_error&) {  // the documented failure: anything else is a finding
  }
  return 0;
}
