#include "eval/findings_report.h"

#include <cmath>
#include <cstdio>
#include <iomanip>

namespace novelty::eval {
namespace {

std::string HoldsCell(bool holds, int frames) {
  return frames == 0 ? "no frames" : holds ? "yes" : "no";
}

const char* HoldsText(bool holds, int frames) {
  return frames == 0 ? "no frames" : holds ? "holds" : "does NOT hold";
}

// "R2", "R4", "R1.5": the thesis's names of the sparser maps.
std::string RunName(double factor) {
  char name[32];
  std::snprintf(name, sizeof name, "R%g", factor);
  return name;
}

}  // namespace

std::string FormatDb(double v) {
  if (!std::isfinite(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::vector<std::string> MeanCells(const MeanSelectivity& m) {
  if (m.frames == 0) return {"0", "", "", "", "", ""};
  char coverage[16];
  std::snprintf(coverage, sizeof coverage, "%.3f", m.coverage);
  return {std::to_string(m.frames), FormatDb(m.as_surprise),    FormatDb(m.as_difference),
          FormatDb(m.pas_surprise), FormatDb(m.pas_difference), coverage};
}

FindingsReport::FindingsReport(std::ostream& csv, std::ostream* console)
    : csv_(csv), console_(console) {
  csv_ << "finding,region,first_frame,last_frame,frames,AS_surprise,AS_diff,PAS_surprise,"
          "PAS_diff,coverage,holds\n";
}

void FindingsReport::WriteRow(const std::string& what, const Finding& f, const MeanSelectivity& m,
                              bool holds) {
  csv_ << '"' << what << "\"," << f.region << "," << f.first << "," << f.last;
  for (const std::string& cell : MeanCells(m)) csv_ << "," << cell;
  csv_ << "," << HoldsCell(holds, m.frames) << "\n";
}

void FindingsReport::Print(const std::string& what, bool holds, int frames,
                           const std::string& numbers) {
  if (!console_) return;
  *console_ << "  " << std::left << std::setw(78) << what << std::right << " "
            << HoldsText(holds, frames) << " (" << numbers << ")\n";
}

void FindingsReport::AddFindings(const std::vector<SelectivityRow>& rows,
                                 const std::vector<Finding>& findings, HtmlReport& report) {
  std::vector<std::vector<std::string>> table;
  for (const Finding& f : findings) {
    const FindingResult r = Evaluate(rows, f);
    const std::string frames = std::to_string(f.first) + "–" + std::to_string(f.last);
    std::vector<std::string> line = {f.what, frames};
    for (const std::string& cell : MeanCells(r.mean)) line.push_back(cell);
    line.push_back(HoldsCell(r.holds, r.mean.frames));
    table.push_back(line);
    WriteRow(f.what, f, r.mean, r.holds);
    Print(f.what, r.holds, r.mean.frames,
          "AS " + FormatDb(r.mean.as_surprise) + " vs " + FormatDb(r.mean.as_difference) +
              " dB, PAS " + FormatDb(r.mean.pas_surprise) + " vs " +
              FormatDb(r.mean.pas_difference) + " dB, coverage " +
              (r.mean.frames ? MeanCells(r.mean)[5] : "-") + ", frames " + frames);
  }
  report.Heading("Findings of thesis 4.3, over the first run after each change");
  report.Paragraph(
      "Means over the frames of the first run (Q1 to Q2) of each phase that show the region; "
      "surprise / differencing.");
  report.Table({"finding", "frames", "frames with region", "AS surprise", "AS differencing",
                "PAS surprise", "PAS differencing", "coverage", "holds"},
               table);
}

void FindingsReport::AddSparser(const std::vector<SelectivityRow>& rows, int views,
                                const std::vector<SparserRun>& sparser,
                                const std::vector<Finding>& findings, HtmlReport& report) {
  if (sparser.empty()) return;
  std::vector<std::vector<std::string>> table;
  for (const Finding& f : findings) {
    const MeanSelectivity full = Evaluate(rows, f).mean;
    table.push_back({f.region, "F", std::to_string(views), FormatDb(full.pas_surprise),
                     FormatDb(full.pas_difference), "", ""});
    for (const SparserRun& s : sparser) {
      const MeanSelectivity m = Evaluate(*s.rows, f).mean;
      const bool holds = SurpriseLosesLess(full, m);
      const std::string name = RunName(s.factor);
      const std::string loss_surprise = FormatDb(full.pas_surprise - m.pas_surprise);
      const std::string loss_difference = FormatDb(full.pas_difference - m.pas_difference);
      table.push_back({f.region, name, std::to_string(s.views), FormatDb(m.pas_surprise),
                       FormatDb(m.pas_difference), loss_surprise + " / " + loss_difference,
                       HoldsCell(holds, m.frames)});
      WriteRow(f.region + ", " + name + ": surprise loses less PAS than differencing (fig. 4.13)",
               f, m, holds);
      Print(f.region + ", " + name + ": surprise loses less PAS (fig. 4.13)", holds, m.frames,
            "PAS loss " + loss_surprise + " vs " + loss_difference + " dB, " +
                std::to_string(s.views) + " views");
    }
  }
  report.Heading("Fewer reference views (fig. 4.13)");
  report.Paragraph(
      "The same frames with reference views spaced N times wider (RN), over each finding's "
      "first run. The thesis: surprise keeps more of its peak selectivity than differencing.");
  report.Table({"region", "views", "reference views", "PAS surprise", "PAS differencing",
                "PAS loss surprise / differencing", "surprise loses less"},
               table);
}

}  // namespace novelty::eval
