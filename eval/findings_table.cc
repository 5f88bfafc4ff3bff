#include "eval/findings_table.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/csv_field.h"
#include "core/temporary_file.h"

namespace novelty::eval {

std::string HoldsText(const std::optional<bool>& holds) {
  return !holds ? "" : *holds ? "yes" : "no";
}

std::string NumberText(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

std::string PercentText(double fraction) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f %%", 100.0 * fraction);
  return b;
}

void FindingsTable::Add(const std::string& what, const std::string& value,
                        const std::string& target, std::optional<bool> holds) {
  rows_.push_back({what, value, target, holds});
  if (console_)
    std::fprintf(console_, "  %-58s %10s  (target %s)\n", what.c_str(), value.c_str(),
                 target.c_str());
}

void FindingsTable::WriteCsv(const std::string& path) const {
  core::TemporaryFile tmp(path);
  {
    std::ofstream out(tmp.path());
    out << "finding,value,target,holds\n";
    for (const FindingRow& r : rows_)
      out << core::CsvField(r.what) << ',' << core::CsvField(r.value) << ','
          << core::CsvField(r.target) << ',' << HoldsText(r.holds) << '\n';
    if (!out) throw std::runtime_error(path + ": cannot write the findings");
  }
  tmp.Commit();
}

void FindingsTable::AddTo(HtmlReport& report) const {
  std::vector<std::vector<std::string>> cells;
  for (const FindingRow& r : rows_)
    cells.push_back({r.what, r.value, r.target, HoldsText(r.holds)});
  report.Table({"finding", "value", "target", "holds"}, cells);
}

}  // namespace novelty::eval
