#include "eval/selectivity_csv.h"

#include <stdexcept>

#include "eval/findings_report.h"

namespace novelty::eval {

SelectivityCsv::SelectivityCsv(const std::string& path) : path_(path), out_(path) {
  out_ << "frame,phase,object,AS_surprise,PAS_surprise,AS_diff,PAS_diff,coverage\n";
  if (!out_) throw std::runtime_error(path + ": cannot write");
}

void SelectivityCsv::Add(const SelectivityRow& r, const std::string& phase) {
  out_ << r.frame << "," << phase << "," << r.region << "," << FormatDb(r.surprise.as_db) << ","
       << FormatDb(r.surprise.pas_db) << "," << FormatDb(r.difference.as_db) << ","
       << FormatDb(r.difference.pas_db) << "," << r.surprise.coverage << "\n";
  if (!out_) throw std::runtime_error(path_ + ": cannot write");
}

}  // namespace novelty::eval
