#include "eval/findings_report.h"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "tests/eval/selectivity_row.h"

namespace novelty::eval {
namespace {

// One file per test: ctest runs this file's tests in parallel processes.
std::string Saved(const HtmlReport& report) {
  const std::string path = testing::TempDir() + "/findings_report_test_" +
                           testing::UnitTest::GetInstance()->current_test_info()->name() + ".html";
  report.Save(path);
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(FormatDb, TwoDecimalsAndBlankForNoValue) {
  EXPECT_EQ(FormatDb(4.186), "4.19");
  EXPECT_EQ(FormatDb(-0.005), "-0.01");
  EXPECT_EQ(FormatDb(std::numeric_limits<double>::quiet_NaN()), "");
  EXPECT_EQ(MeanCells({}), (std::vector<std::string>{"0", "", "", "", "", ""}));
}

// The glass (frames 10–11: AS surprise 0.5 > differencing −0.5 on average) holds; the cup has
// no frame in its range, which is said rather than judged.
TEST(FindingsReport, WritesEachFindingToTheCsvTheConsoleAndTheReportAlike) {
  const std::vector<SelectivityRow> rows = {Row(10, "glass", 1.0, 4.0, -1.0, 2.0),
                                            Row(11, "glass", 0.0, 3.0, 0.0, 1.0),
                                            Row(30, "cup", 1.0, 1.0, 1.0, 1.0)};
  const std::vector<Finding> findings = {
      {"glass: surprise more selective", "glass", Claim::kSurpriseMoreSelective, 10, 12},
      {"cup: detected by both", "cup", Claim::kBothDetect, 10, 12}};
  std::ostringstream csv, console;
  HtmlReport report("test");
  FindingsReport(csv, &console).AddFindings(rows, findings, report);
  EXPECT_EQ(csv.str(),
            "finding,region,first_frame,last_frame,frames,AS_surprise,AS_diff,PAS_surprise,"
            "PAS_diff,coverage,holds\n"
            "\"glass: surprise more selective\",glass,10,12,2,0.50,-0.50,3.50,1.50,0.900,yes\n"
            "\"cup: detected by both\",cup,10,12,0,,,,,,no frames\n");
  EXPECT_NE(console.str().find("glass: surprise more selective"), std::string::npos);
  EXPECT_NE(console.str().find(
                " holds (AS 0.50 vs -0.50 dB, PAS 3.50 vs 1.50 dB, coverage 0.900, frames 10–12)"),
            std::string::npos)
      << console.str();
  EXPECT_NE(console.str().find(" no frames (AS"), std::string::npos) << console.str();
  const std::string html = Saved(report);
  EXPECT_NE(html.find("Findings of thesis 4.3"), std::string::npos);
  EXPECT_NE(html.find("3.50"), std::string::npos);
}

// Fig. 4.13: from the full map's PAS 3.50 / 1.50 dB, R2 loses 0.50 / 1.00 dB (holds), R4 loses
// 2.00 / 1.00 dB (does not).
TEST(FindingsReport, ComparesSparserRunsWithTheFullMap) {
  const std::vector<SelectivityRow> full = {Row(10, "glass", 1.0, 4.0, -1.0, 2.0),
                                            Row(11, "glass", 0.0, 3.0, 0.0, 1.0)};
  const std::vector<SelectivityRow> r2 = {Row(10, "glass", 0.0, 3.0, 0.0, 0.5)};
  const std::vector<SelectivityRow> r4 = {Row(10, "glass", 0.0, 1.5, 0.0, 0.5)};
  const std::vector<Finding> findings = {{"glass", "glass", Claim::kSurpriseMoreSelective, 10, 12}};
  std::ostringstream csv, console;
  HtmlReport report("test");
  FindingsReport out(csv, &console);
  out.AddSparser(full, 150, {{2, 75, &r2}, {4, 50, &r4}}, findings, report);
  const std::string kHeader =
      "finding,region,first_frame,last_frame,frames,AS_surprise,AS_diff,PAS_surprise,PAS_diff,"
      "coverage,holds\n";
  EXPECT_EQ(csv.str(),
            kHeader +
                "\"glass, R2: surprise loses less PAS than differencing (fig. 4.13)\",glass,10,12,"
                "1,0.00,0.00,3.00,0.50,0.900,yes\n"
                "\"glass, R4: surprise loses less PAS than differencing (fig. 4.13)\",glass,10,12,"
                "1,0.00,0.00,1.50,0.50,0.900,no\n");
  EXPECT_NE(console.str().find("does NOT hold (PAS loss 2.00 vs 1.00 dB, 50 views)"),
            std::string::npos)
      << console.str();
  EXPECT_NE(Saved(report).find("0.50 / 1.00"), std::string::npos);
  // Without sparser runs: nothing beyond the header.
  std::ostringstream only_header;
  FindingsReport(only_header).AddSparser(full, 150, {}, findings, report);
  EXPECT_EQ(only_header.str(), kHeader);
}

}  // namespace
}  // namespace novelty::eval
