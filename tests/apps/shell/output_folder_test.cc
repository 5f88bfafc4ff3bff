#include "apps/shell/output_folder.h"

#include "apps/shell/program.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace novelty::apps {
namespace {

namespace fs = std::filesystem;

class OutputFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("novelty_output_folder_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "gt");
    std::ofstream(dir_ / "in.rawlog") << "rawlog";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string P(const std::string& name) const { return (dir_ / name).string(); }
  // The message OutputFolder throws, "" if it accepts.
  std::string Refusal(const std::string& out, const std::vector<std::string>& inputs,
                      const std::string& program = "novelty-run") {
    try {
      OutputFolder o(program, out, inputs);
      return "";
    } catch (const std::runtime_error& e) {
      return e.what();
    }
  }
  fs::path dir_;
};

TEST_F(OutputFolderTest, WritesIntoPartialAndPublishesOnCommit) {
  {
    OutputFolder o("novelty-run", P("out"), {P("in.rawlog")});
    EXPECT_EQ(o.path(), P("out.partial"));
    std::ofstream(o.File("report.html")) << "r";
    EXPECT_FALSE(fs::exists(P("out")));
    o.Commit();
  }
  EXPECT_TRUE(fs::exists(P("out/report.html")));
  EXPECT_FALSE(fs::exists(P("out.partial")));
}

TEST_F(OutputFolderTest, AFailedRunLeavesTheEarlierOutputWhole) {
  {
    OutputFolder o("novelty-run", P("out"), {});
    std::ofstream(o.File("report.html")) << "first";
    o.Commit();
  }
  {
    OutputFolder o("novelty-run", P("out"), {});
    std::ofstream(o.File("report.html")) << "second, half";
    // no Commit: the run failed
  }
  std::ifstream in(P("out/report.html"));
  std::string s;
  std::getline(in, s);
  EXPECT_EQ(s, "first");
  EXPECT_FALSE(fs::exists(P("out.partial")));
  {
    OutputFolder o("novelty-run", P("out"), {});  // its own earlier output: replaced
    std::ofstream(o.File("new.csv")) << "x";
    o.Commit();
  }
  EXPECT_TRUE(fs::exists(P("out/new.csv")));
  EXPECT_FALSE(fs::exists(P("out/report.html")));
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir_))
    entries += e.path().filename() != "gt" && e.path().filename() != "in.rawlog";
  EXPECT_EQ(entries, 1);  // no .old or .partial folder left
}

// The probe's case: a file put into an earlier output was deleted with it by the next run.
TEST_F(OutputFolderTest, RefusesAnEarlierOutputThatNowHoldsAFileItDidNotWrite) {
  {
    OutputFolder o("novelty-run", P("out"), {});
    std::ofstream(o.File("report.html")) << "r";
    o.Commit();
  }
  std::ofstream(P("out/notes.txt")) << "mine";
  EXPECT_NE(Refusal(P("out"), {}).find("holds 'notes.txt', which novelty-run did not write"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(P("out/notes.txt")));
  fs::remove(P("out/notes.txt"));
  EXPECT_EQ(Refusal(P("out"), {}), "");
}

TEST_F(OutputFolderTest, APartialFolderAKilledRunLeftIsRemoved) {
  {
    OutputFolder o("novelty-run", P("out"), {});
    std::ofstream(o.File("half.csv")) << "x";
    // killed: the destructor does not run
    fs::copy(P("out.partial"), P("kept.partial"), fs::copy_options::recursive);
  }
  fs::rename(P("kept.partial"), P("out.partial"));
  OutputFolder o("novelty-run", P("out"), {});
  EXPECT_FALSE(fs::exists(P("out.partial/half.csv")));
}

TEST_F(OutputFolderTest, RefusesAFolderThatHoldsAnInput) {
  EXPECT_NE(Refusal(P("gt"), {P("in.rawlog"), P("gt")}).find("holds an input"), std::string::npos);
  EXPECT_NE(Refusal(dir_.string(), {P("in.rawlog")}).find("holds an input"), std::string::npos);
  EXPECT_NE(Refusal(dir_.string() + "/./", {P("in.rawlog")}).find("holds an input"),
            std::string::npos);
  fs::create_directory_symlink(dir_, P("link"));
  EXPECT_NE(Refusal(P("link"), {P("in.rawlog")}).find("holds an input"), std::string::npos);
  EXPECT_EQ(Refusal(P("gt/results"), {P("gt")}).find("holds an input"), std::string::npos)
      << "a new folder inside an input's folder holds no input";
}

TEST_F(OutputFolderTest, RefusesAnotherProgramsResultsAndAUsersFolder) {
  {
    OutputFolder o("novelty-run", P("run"), {});
    o.Commit();
  }
  EXPECT_NE(Refusal(P("run"), {}, "novelty-objects").find("holds novelty-run's results"),
            std::string::npos);
  fs::create_directories(P("mine"));
  std::ofstream(P("mine/thesis.tex")) << "x";
  EXPECT_NE(Refusal(P("mine"), {}).find("not novelty-run's results"), std::string::npos);
  EXPECT_TRUE(fs::exists(P("mine/thesis.tex")));
  fs::create_directories(P("mine2.partial"));
  std::ofstream(P("mine2.partial/notes.txt")) << "x";
  EXPECT_NE(Refusal(P("mine2"), {}), "");
  EXPECT_TRUE(fs::exists(P("mine2.partial/notes.txt")));
  EXPECT_NE(Refusal(P("in.rawlog"), {}).find("is not a folder"), std::string::npos);
  fs::create_directories(P("empty"));
  EXPECT_EQ(Refusal(P("empty"), {}), "");
  EXPECT_THROW(OutputFolder("p", "", {}), UsageError);
}

}  // namespace
}  // namespace novelty::apps
