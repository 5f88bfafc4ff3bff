// novelty-learn-objects: named objects from one's own photos into an object database
// (experiments/object_photo_learning.h) — the CObjectDatabaseMap file novelty-find-objects
// recognises from and novelty-run takes with --objects-in.
//
//   novelty-learn-objects OBJECT... --out OBJECTS.object_database [--add-to DB]
//       [--metres-per-pixel 0.001] [--extractor sift|msurf|akaze] [--options FILE]
//       [--include GLOB ...] [--exclude GLOB ...]
//
// OBJECT is [NAME=]PATH[@X,Y,W,H]: an image or a folder of images of one object (one class per
// photo, all named NAME; without NAME the file's stem or the folder's name), and optionally the
// box (pixels) the object fills in each. An image X.jpg with a mask X.mask.png beside it is
// learnt where the mask is non-zero. The database is written atomically, and only when every
// photo was learnt.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/table_flags.h"
#include "experiments/object_photo_learning.h"
#include "mrpt_plugins/map_file.h"
#include "mrpt_plugins/object_database_map_options.h"

using namespace novelty;

namespace {

int Run(int argc, char** argv) {
  apps::CommandLine cmd("Learns named objects from photos into an object database (thesis ch. 5)",
                        "0.1");
  TCLAP::UnlabeledMultiArg<std::string> objects(
      "objects", "[NAME=]PATH[@X,Y,W,H]: an image or folder of images of one object", true,
      "OBJECT", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "The database to write", true, "",
                                   "OBJECTS.object_database", cmd);
  TCLAP::ValueArg<std::string> add_to("", "add-to", "Add to this database (its options kept)",
                                      false, "", "DB", cmd);
  const objects::PhotoObjectOptions defaults;
  TCLAP::ValueArg<double> scale("", "metres-per-pixel",
                                "The photos' scale in the object's plane; scales only the pose "
                                "of a found object (default 0.001)",
                                false, defaults.metres_per_pixel, "M", cmd);
  apps::TableFlags<mrpt_plugins::ObjectDatabaseMapConfig> options(cmd,
                                                                  {{"extractor", "extractor"}});
  TCLAP::MultiArg<std::string> include(
      "", "include", "In a folder, only files matching GLOB are photos", false, "GLOB", cmd);
  TCLAP::MultiArg<std::string> exclude(
      "", "exclude", "In a folder, files matching GLOB are not photos", false, "GLOB", cmd);
  cmd.Parse(argc, argv);
  if (add_to.isSet() && options.AnySet())
    throw apps::UsageError(
        "--add-to keeps its database's options: no --extractor, --set or "
        "--options with it");
  if (!(scale.getValue() > 0 && scale.getValue() <= 1))
    throw apps::UsageError("--metres-per-pixel must be in (0, 1] m");
  experiments::ObjectPhotoLearningOptions o;
  try {
    for (const std::string& text : objects.getValue())
      o.objects.push_back(experiments::ParseObjectPhotoSpec(text));
  } catch (const std::invalid_argument& e) {
    throw apps::UsageError(e.what());
  }
  o.photo.metres_per_pixel = scale.getValue();
  o.pick = {include.getValue(), exclude.getValue()};
  std::vector<std::string> inputs = {add_to.getValue()};
  for (const auto& s : o.objects) inputs.push_back(s.path);
  apps::CheckOutputFile("--out", out.getValue(), inputs, [](const std::string& p) {
    return mrpt_plugins::IsMapFileOf(p, "CObjectDatabaseMap");
  });

  mrpt_plugins::CObjectDatabaseMap map(options.Values());
  if (add_to.isSet()) map.LoadFromFile(add_to.getValue());
  const auto learnt = experiments::LearnObjectPhotos(map, o);
  for (const auto& l : learnt)
    std::printf("  %s: %d features from %s\n", l.name.c_str(), l.features, l.photo.c_str());
  map.SaveToFile(out.getValue());
  std::printf("%zu photo%s → %s (%d objects, %d features, %s)\n", learnt.size(),
              learnt.size() == 1 ? "" : "s", out.getValue().c_str(), map.database().objects(),
              map.database().features(),
              objects::FeatureExtractorName(map.config().map.extractor).c_str());
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-learn-objects", [&] { return Run(argc, argv); });
}
