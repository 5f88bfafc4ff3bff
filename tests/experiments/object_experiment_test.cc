#include "experiments/object_experiment.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "experiments/surprise_experiment.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_runner.h"
#include "tests/mrpt_plugins/box_clip.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

// c_object_database_map_test's clip (tests/mrpt_plugins/box_clip.h): the box put down at 4 s
// (frame 29). The whole of 5.2 on it: learnt with novelty-run's experiment (the object database
// from frame 29 on), then recognised along the same clip.
std::string Value(const ObjectExperimentResult& r, const std::string& what) {
  for (const auto& row : r.findings.rows())
    if (row.what == what) return row.value;
  return "";
}

TEST(ObjectExperiment, TheBoxPutDownIsLearntFromItsOwnFeaturesAndJudgedInEveryFrame) {
  const std::string textures = mrpt_plugins::Textures();
  if (textures.empty()) GTEST_SKIP() << "textures/ of the shared test data is absent";
  const fs::path dir =
      fs::temp_directory_path() / ("novelty_object_experiment_" + std::to_string(getpid()));
  fs::remove_all(dir);
  std::istringstream scn(mrpt_plugins::ClipText(true, 0.5));
  sim::RunOptions run;
  run.out_dir = (dir / "sim").string();
  run.progress = false;
  const std::string rawlog =
      sim::RunScenario(sim::ParseScenario(scn, "objects.scn", textures), run).rawlog;
  const std::string truth = (dir / "sim" / "groundtruth").string();

  // Learning: the maps of share/, as docs/objects.md has them for 5.2.
  const fs::path ini = dir / "objects.ini";
  {
    std::ofstream out(ini);
    for (const char* part : {"appearance.ini", "differencing.ini", "object_database.ini"})
      out << std::ifstream(std::string(NOVELTY_SOURCE_DIR) + "/share/" + part).rdbuf() << "\n";
  }
  SurpriseExperimentOptions learn;
  learn.rawlog = rawlog;
  learn.groundtruth = truth;
  learn.config = ini.string();
  learn.objects_from = 29;
  fs::create_directories(dir / "learn");
  RunSurpriseExperiment(learn, (dir / "learn").string());

  ObjectExperimentOptions o;
  o.learnt = (dir / "learn").string();
  o.learn_truth = truth;
  o.rawlog = rawlog;
  o.truth = truth;
  o.consistency.enabled = true;
  const fs::path out = dir / "objects";
  fs::create_directories(out);
  const ObjectExperimentResult r = RunObjectExperiment(o, out.string());
  EXPECT_EQ(r.objects, 1) << "one object was put down";
  EXPECT_GE(r.features, 1);
  EXPECT_EQ(r.recognition_frames, 54);
  // The thesis's rule that features come from the new object only (docs/objects.md: every learnt
  // feature lies on its object); 2 cm of depth noise may put one beside it.
  const std::string on_object = Value(r, "learnt features on their object");
  ASSERT_FALSE(on_object.empty());
  EXPECT_GE(std::stod(on_object), 90.0) << on_object;
  // recognition.csv: a row per frame and learnt object.
  std::ifstream csv(out / "recognition.csv");
  int rows = -1;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 54);
  for (const char* file : {"findings.csv", "features.csv", "focus.csv", "report.html"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  fs::remove_all(dir);
}

TEST(ObjectExperiment, ALearntFolderWithoutADatabaseIsNamed) {
  ObjectExperimentOptions o;
  o.learnt = (fs::temp_directory_path() / "novelty_no_such_learnt_folder").string();
  try {
    RunObjectExperiment(o, fs::temp_directory_path().string());
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("map.object_database"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace novelty::experiments
