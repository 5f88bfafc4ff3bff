#include "eval/object_steps_csv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace novelty::eval {
namespace {

TEST(ObjectStepsCsv, WritesAHeaderAndOneLinePerFrame) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "object_steps_csv_test.csv").string();
  {
    ObjectStepsCsv csv(path);
    objects::AcquisitionStep s;
    s.focus.box = cv::Rect(10, 20, 30, 40);
    s.change.kind = objects::ChangeKind::kAdded;
    s.change.known_share = 1.0;
    s.change.observed_depth = 1.25;
    s.change.predicted_depth = 2.5;
    s.extracted = 14;
    s.not_nearer = 2;
    s.reconstructed = 11;
    s.learner.static_features = 7;
    s.learner.learnt = 3;
    s.learner.recognised = objects::LearnerStep::Recognised::kByDatabase;
    s.learner.object = 1;
    s.learner.matches_per_object = {0, 5};
    csv.Add(42, s, 88);
    csv.Add(43, objects::AcquisitionStep(), 88);  // nothing in focus, nothing known
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "frame,box_x,box_y,box_width,box_height,change,observed_depth,expected_depth,"
            "extracted,not_nearer,reconstructed,static,learnt,recognised,object,database_features,"
            "matches\n"
            "42,10,20,30,40,added,1.25,2.5,14,2,11,7,3,database,1,88,0;5\n"
            "43,,,,,unknown,,,0,0,0,0,0,nothing,-1,88,\n");
  std::filesystem::remove(path);
  EXPECT_THROW(ObjectStepsCsv("/nonexistent-dir/objects.csv"), std::runtime_error);
}

}  // namespace
}  // namespace novelty::eval
