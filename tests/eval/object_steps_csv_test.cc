#include "eval/object_steps_csv.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace novelty::eval {
namespace {

// Per process: ctest runs this file's tests in parallel, and two once shared one file.
std::string TempPath(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::to_string(getpid()) + "_" + name))
      .string();
}

// What ReadObjectStepsCsv reads from a file (object_steps_csv_text_test.csv) holding `text`.
std::vector<ObjectStepRow> ReadText(const std::string& text) {
  const std::string path = TempPath("object_steps_csv_text_test.csv");
  std::ofstream(path) << text;
  struct Remove {
    std::string path;
    ~Remove() { std::filesystem::remove(path); }
  } remove{path};
  return ReadObjectStepsCsv(path);
}

// A frame's step with every column set.
objects::AcquisitionStep AStep() {
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
  return s;
}

TEST(ObjectStepsCsv, WritesAHeaderAndOneLinePerFrame) {
  const std::string path = TempPath("object_steps_csv_test.csv");
  {
    ObjectStepsCsv csv(path);
    csv.Add(42, AStep(), 88);
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

void ExpectRow(const ObjectStepRow& row, const ObjectStepRow& expected) {
  EXPECT_EQ(row.frame, expected.frame);
  EXPECT_EQ(row.has_box, expected.has_box);
  EXPECT_EQ(row.box, expected.box);
  EXPECT_EQ(row.change, expected.change);
  EXPECT_EQ(row.extracted, expected.extracted);
  EXPECT_EQ(row.learnt, expected.learnt);
  EXPECT_EQ(row.object, expected.object);
  EXPECT_EQ(row.database_features, expected.database_features);
}

TEST(ReadObjectStepsCsv, ReadsBackWhatTheWriterWrote) {
  const std::string path = TempPath("object_steps_csv_read_test.csv");
  {
    ObjectStepsCsv csv(path);
    csv.Add(42, AStep(), 88);
    csv.Add(43, objects::AcquisitionStep(), 91);
  }
  const std::vector<ObjectStepRow> rows = ReadObjectStepsCsv(path);
  std::filesystem::remove(path);
  ASSERT_EQ(rows.size(), 2u);
  ExpectRow(rows[0], {42, true, cv::Rect(10, 20, 30, 40), "added", 14, 3, 1, 88});
  ExpectRow(rows[1], {43, false, cv::Rect(), "unknown", 0, 0, -1, 91});
}

TEST(ReadObjectStepsCsv, ReadsAFileWithoutTheLaterColumnsAndWithColumnsItDoesNotKnow) {
  // Before not_nearer; and a column that a later version might add, before the ones read.
  const std::vector<ObjectStepRow> rows = ReadText(
      "frame,box_x,box_y,box_width,box_height,change,extra,observed_depth,expected_depth,"
      "extracted,reconstructed,static,learnt,recognised,object,database_features,matches\n"
      "7,1,2,3,4,added,x,0.75,1.25,20,18,5,4,new,0,4,0\n");
  ASSERT_EQ(rows.size(), 1u);
  ExpectRow(rows[0], {7, true, cv::Rect(1, 2, 3, 4), "added", 20, 4, 0, 4});
}

TEST(ReadObjectStepsCsv, ReadsCrlfLineEndsAndSkipsBlankLines) {
  const std::vector<ObjectStepRow> rows = ReadText(
      "frame,box_x,box_y,box_width,box_height,change,observed_depth,expected_depth,"
      "extracted,not_nearer,reconstructed,static,learnt,recognised,object,database_features,"
      "matches\r\n"
      "7,1,2,3,4,added,0.75,1.25,20,2,18,5,4,new,0,4,3\r\n"
      "\r\n"
      "8,,,,,unknown,,,0,0,0,0,0,nothing,-1,4,\r\n"
      "\n");
  ASSERT_EQ(rows.size(), 2u);
  ExpectRow(rows[0], {7, true, cv::Rect(1, 2, 3, 4), "added", 20, 4, 0, 4});
  ExpectRow(rows[1], {8, false, cv::Rect(), "unknown", 0, 0, -1, 4});
}

// The message of the error ReadObjectStepsCsv throws for `text`, "" if none.
std::string ReadError(const std::string& text) {
  try {
    ReadText(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ReadObjectStepsCsv, ABadFileOrRowIsAnErrorNamingTheFileAndLine) {
  const std::string header =
      "frame,box_x,box_y,box_width,box_height,change,observed_depth,expected_depth,extracted,"
      "not_nearer,reconstructed,static,learnt,recognised,object,database_features,matches\n";
  const std::string good = "5,1,2,3,4,added,0.7,1.2,20,2,18,5,4,new,0,4,0\n";
  EXPECT_EQ(ReadError(header + good), "");
  EXPECT_NE(ReadError("frame,x,y\n1,2,3\n").find("not novelty-run's objects.csv"),
            std::string::npos);
  EXPECT_NE(ReadError("frame,box_x,box_y,box_width,box_height,change,object\n")
                .find("no column extracted"),
            std::string::npos);
  const std::string short_row = ReadError(header + good + "6,1,2,3,4,added\n");
  EXPECT_NE(short_row.find(":3: malformed row (not as many cells"), std::string::npos) << short_row;
  EXPECT_NE(short_row.find("object_steps_csv_text_test.csv"), std::string::npos) << short_row;
  EXPECT_NE(ReadError(header + "5,1,2,3,4,added,0.7,1.2,2O,2,18,5,4,new,0,4,0\n")
                .find(":2: malformed row (extracted \"2O\" is not an integer)"),
            std::string::npos);
  EXPECT_NE(ReadError(header + "5,1,2,,4,added,0.7,1.2,20,2,18,5,4,new,0,4,0\n")
                .find("a box with empty cells"),
            std::string::npos);
  EXPECT_NE(ReadError(header + "5,1,2,3,4,added,0.7,1.2,20,2,18,5,4,new,,4,0\n")
                .find("object \"\" is not an integer"),
            std::string::npos);
  EXPECT_NE(ReadError(header + "99999999999,1,2,3,4,added,0.7,1.2,20,2,18,5,4,new,0,4,0\n")
                .find("frame \"99999999999\" is not an integer"),
            std::string::npos);
  EXPECT_THROW(ReadObjectStepsCsv("/nonexistent-dir/objects.csv"), std::runtime_error);
}

}  // namespace
}  // namespace novelty::eval
