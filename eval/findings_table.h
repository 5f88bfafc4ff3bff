// The one findings vocabulary of every experiment: a finding is what was measured, the value,
// the target it is held against (the thesis's number, the issue's, or "(reported)" for a number
// without one) and whether it holds. One table gives findings.csv (finding,value,target,holds;
// RFC 4180), the HTML report's table and the console's lines, so the three always agree.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "eval/html_report.h"

namespace novelty::eval {

struct FindingRow {
  std::string what, value, target;
  std::optional<bool> holds;  ///< none: nothing to hold it against
};

class FindingsTable {
 public:
  /// Adds a finding (and prints it on `console` if one was given: "  WHAT  VALUE  (target T)").
  void Add(const std::string& what, const std::string& value, const std::string& target = "",
           std::optional<bool> holds = std::nullopt);
  const std::vector<FindingRow>& rows() const { return rows_; }

  /// Prints each finding as it is added.
  void EchoTo(std::FILE* console) { console_ = console; }

  /// findings.csv: the header "finding,value,target,holds" and a row a finding ("yes", "no" or
  /// empty), each field quoted as RFC 4180 needs. Written atomically; throws std::runtime_error
  /// naming the file.
  void WriteCsv(const std::string& path) const;
  /// The findings as one table of `report`.
  void AddTo(HtmlReport& report) const;

 private:
  std::vector<FindingRow> rows_;
  std::FILE* console_ = nullptr;
};

/// "yes", "no" or "" for none.
std::string HoldsText(const std::optional<bool>& holds);

/// A number as a default std::ostream writes it (six significant digits): the findings' values
/// where no unit or precision is chosen.
std::string NumberText(double v);

/// A fraction as a percentage with one decimal: 0.1234 -> "12.3 %".
std::string PercentText(double fraction);

}  // namespace novelty::eval
