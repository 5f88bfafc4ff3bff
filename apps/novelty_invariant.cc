// novelty-invariant: the illumination-invariant image of one viewpoint from images of it under
// different lights (thesis 6.1.2), its illumination images (eq. 6.14) and their statistics
// (6.2: gamma models, information maps, the shapes of highlights and strong shadows); the work
// is experiments/invariant_image_run.h's.
//
//   novelty-invariant DIR --out OUT [--colour per-channel|luminance-chromaticity]
//                     [--min-intensity 3] [--min-lightings 2] [--kappa 0.5]
//                     [--include GLOB ...] [--exclude GLOB ...]
//
// DIR holds the lightings (every image file in name order, or those the patterns pick; see
// sensors/dataset/lighting_folder_reader.h) and optionally mask.png; in the MIT Intrinsic Images
// layout (reflectance.png, shading.png, diffuse.png) the decomposition is also scored with the
// benchmark's LMSE. OUT gets invariant.png (linear, the inputs' bit depth and scale),
// illumination/ (L = I / R as 8 bits, 1 → 128), information/ (i_Y in false colour, 0 … 2 T_Y),
// shapes/ (255 where i_Y > T_Y), panels/, model.csv, findings.csv and report.html.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <string>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/table_flags.h"
#include "experiments/invariant_image_run.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"

using namespace novelty;

namespace {

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "Illumination-invariant image, illumination images and their statistics from images of "
      "one viewpoint under different lights (thesis 6.1.2, 6.2).",
      "0.1");
  TCLAP::UnlabeledValueArg<std::string> in("folder", "Folder of lightings", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output folder", true, "", "OUT", cmd);
  // The invariant image's and model's options are CIlluminationInvariantMap's, with its
  // table's defaults.
  apps::TableFlags<mrpt_plugins::IlluminationInvariantMapConfig> options(
      cmd, {{"colour", "colour"},
            {"min_intensity", "min-intensity"},
            {"min_lightings", "min-lightings"},
            {"kappa", "kappa"}});
  TCLAP::MultiArg<std::string> include(
      "", "include", "Only image files whose name matches GLOB are lightings (repeatable)", false,
      "GLOB", cmd);
  TCLAP::MultiArg<std::string> exclude(
      "", "exclude", "Image files whose name matches GLOB are not lightings, e.g. '*_Ambient*'",
      false, "GLOB", cmd);
  cmd.Parse(argc, argv);
  apps::OutputFolder out_folder("novelty-invariant", out.getValue(), {in.getValue()});
  const experiments::InvariantImageRunResult r = experiments::RunInvariantImage(
      in.getValue(), options.Values().map, out_folder.path(),
      [](const std::string& line) {
        std::fprintf(stderr, "[novelty-invariant] %s\n", line.c_str());
      },
      {include.getValue(), exclude.getValue()});
  out_folder.Commit();
  std::printf("%s\n→ %s/report.html\n", r.summary.c_str(), out_folder.final_path().c_str());
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-invariant", [&] { return Run(argc, argv); });
}
