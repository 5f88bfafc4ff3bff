#include "eval/findings_table.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace novelty::eval {
namespace {

namespace fs = std::filesystem;

TEST(FindingsTable, CsvHtmlAndConsoleSayTheSame) {
  FindingsTable t;
  char console[512] = {};
  std::FILE* out = fmemopen(console, sizeof console - 1, "w");
  t.EchoTo(out);
  t.Add("objects learnt", "3", "3 (thesis)", true);
  t.Add("TPR at FPR <= 1 %, matches", "90.9 %", "(reported)");
  t.Add("AUC", "0.9", ">= 0.95", false);
  std::fclose(out);
  EXPECT_EQ(std::string(console).substr(0, 34), "  objects learnt                  ");
  EXPECT_NE(std::string(console).find("(target >= 0.95)"), std::string::npos);

  const fs::path csv = fs::temp_directory_path() / ("novelty_findings_" + std::to_string(getpid()));
  t.WriteCsv(csv.string());
  std::ifstream in(csv);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(text,
            "finding,value,target,holds\n"
            "objects learnt,3,3 (thesis),yes\n"
            "\"TPR at FPR <= 1 %, matches\",90.9 %,(reported),\n"
            "AUC,0.9,>= 0.95,no\n");
  fs::remove(csv);

  HtmlReport report("r");
  t.AddTo(report);
  const fs::path html =
      fs::temp_directory_path() / ("novelty_findings_" + std::to_string(getpid()) + ".html");
  report.Save(html.string());
  std::ifstream h(html);
  const std::string page{std::istreambuf_iterator<char>(h), std::istreambuf_iterator<char>()};
  EXPECT_NE(page.find("TPR at FPR &lt;= 1 %, matches"), std::string::npos);
  EXPECT_NE(page.find(">no<"), std::string::npos);
  fs::remove(html);
}

TEST(FindingsTable, PercentTextRoundsToOneDecimal) {
  EXPECT_EQ(PercentText(0.1234), "12.3 %");
  EXPECT_EQ(PercentText(0.99951), "100.0 %");
  EXPECT_EQ(PercentText(0.0), "0.0 %");
  EXPECT_EQ(PercentText(-0.005), "-0.5 %");
}

}  // namespace
}  // namespace novelty::eval
