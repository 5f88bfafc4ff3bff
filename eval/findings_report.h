// The findings of thesis 4.3 (selectivity_findings) reported three ways at once — rows of
// findings.csv, tables of the HTML report and lines for the console — by one piece of code that
// formats a finding's numbers, so the three always agree. Used by novelty-run.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "eval/html_report.h"
#include "eval/selectivity_findings.h"

namespace novelty::eval {

/// Two decimals; empty for a value that is not finite.
std::string FormatDb(double v);

/// Frames and the four means (AS surprise, AS differencing, PAS surprise, PAS differencing) as
/// table cells; the means blank when no frame showed the region.
std::vector<std::string> MeanCells(const MeanSelectivity& m);

/// The same frames run with reference views spaced `factor` times wider (fig. 4.13).
struct SparserRun {
  double factor = 2.0;                                ///< named R2, R4… as in the thesis
  int views = 0;                                      ///< reference views its map held
  const std::vector<SelectivityRow>* rows = nullptr;  ///< its selectivity, frame by frame
};

class FindingsReport {
 public:
  /// Writes the header of findings.csv to `csv`; `console`, when given, gets a line per finding.
  explicit FindingsReport(std::ostream& csv, std::ostream* console = nullptr);

  /// Each finding over `rows`: whether its claim holds, with its means — a csv row, a console
  /// line, and together one table in `report`.
  void AddFindings(const std::vector<SelectivityRow>& rows, const std::vector<Finding>& findings,
                   HtmlReport& report);

  /// Fig. 4.13: each finding's region in every sparser run against the full map (`rows`, with
  /// `views` reference views): whether surprise's PAS falls less than differencing's. Nothing
  /// when `sparser` is empty.
  void AddSparser(const std::vector<SelectivityRow>& rows, int views,
                  const std::vector<SparserRun>& sparser, const std::vector<Finding>& findings,
                  HtmlReport& report);

 private:
  void WriteRow(const std::string& what, const Finding& f, const MeanSelectivity& m, bool holds);
  void Print(const std::string& what, bool holds, int frames, const std::string& numbers);

  std::ostream& csv_;
  std::ostream* console_;
};

}  // namespace novelty::eval
