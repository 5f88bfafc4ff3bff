// novelty COMMAND [ARGS…]: runs novelty-COMMAND from the same folder with ARGS, as git runs
// git-COMMAND. The programs stay separate executables — each links only what its job needs
// (novelty-sim has no MRPT map classes, novelty-invariant no simulator), as MRPT's own tools
// (rawlog-edit, RawLogViewer) are — and this front gives them one name to remember.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/shell/program.h"

namespace fs = std::filesystem;

namespace {

constexpr const char* kCommands[][2] = {
    {"import",
     "an RGB-D sequence (TUM, ICL-NUIM, 7-Scenes) or a fixed camera's images into a rawlog"},
    {"sim", "simulate a scenario into an MRPT rawlog with ground truth"},
    {"run", "play a rawlog through the maps: surprise, panels, metrics, report"},
    {"insert", "a synthetic box drawn into a real RGB-D rawlog, scored against differencing"},
    {"depth", "depth maps from a stereo or trinocular rawlog"},
    {"poses", "camera poses from the LED tracker or visual odometry into a rawlog"},
    {"synth", "view synthesis from a rawlog or an RGB-D folder"},
    {"objects", "learn and recognise objects (thesis ch. 5)"},
    {"foreground", "a fixed camera's foreground, scored beside OpenCV's subtractors (CDnet)"},
    {"learn-objects", "named objects from photos into an object database"},
    {"find-objects", "the known objects in images or a rawlog: what, where, verified"},
    {"invariant", "the illumination-invariant image of one viewpoint (thesis 6.1-6.2)"},
    {"illumination", "illumination novelty against NGC and SCT (thesis 6.4)"},
    {"illumination-map", "learn an illumination-invariant map from rawlogs or photos, judge them"},
    {"soak", "a long run: memory and speed over time"},
    {"info", "versions of the libraries and a self-check"},
};

int Usage(std::FILE* out) {
  std::fprintf(out,
               "usage: novelty COMMAND [ARGS...]   (novelty COMMAND --help for its flags)\n\n");
  for (const auto& c : kCommands) std::fprintf(out, "  %-17s %s\n", c[0], c[1]);
  return out == stdout ? novelty::apps::kExitOk : novelty::apps::kExitUsage;
}

int Run(int argc, char** argv) {
  if (argc < 2) return Usage(stderr);
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") return Usage(stdout);
  if (command == "--version") {
    std::printf("novelty %s\n", NOVELTY_VERSION);
    return novelty::apps::kExitOk;
  }
  bool known = false;
  for (const auto& c : kCommands) known = known || command == c[0];
  if (!known)
    throw novelty::apps::UsageError("no command '" + command + "' (novelty --help lists them)");
  const fs::path self = fs::read_symlink("/proc/self/exe");
  const std::string program = (self.parent_path() / ("novelty-" + command)).string();
  std::vector<char*> args{const_cast<char*>(program.c_str())};
  for (int k = 2; k < argc; ++k) args.push_back(argv[k]);
  args.push_back(nullptr);
  execv(program.c_str(), args.data());
  throw std::runtime_error(program + ": cannot run it (not installed beside novelty?)");
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty", [&] { return Run(argc, argv); });
}
