// A self-contained HTML report: headings, text, tables, images and line plots drawn as inline
// SVG (no scripts, no external files besides the images it links), saved atomically.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace novelty::eval {

struct PlotSeries {
  std::string name;
  std::string color;                              ///< any CSS colour
  std::vector<std::pair<double, double>> points;  ///< (x, y); NaN y values leave gaps
  /// > 0: points farther apart in x than this are not joined (e.g. 1 for per-frame values, so a
  /// line never spans frames where the quantity was not measured); 0: all joined.
  double max_step = 0.0;
};

/// Round tick values covering [lo, hi]: about `count` multiples of 1, 2 or 5 × 10^k.
std::vector<double> NiceTicks(double lo, double hi, int count = 5);

struct PlotBand {
  double from, to;
  std::string label;  ///< shaded background interval (e.g. a phase)
};

/// An SVG line plot with axes, ticks, legend and shaded bands.
std::string SvgLinePlot(const std::string& title, const std::string& x_label,
                        const std::string& y_label, const std::vector<PlotSeries>& series,
                        const std::vector<PlotBand>& bands = {}, int width = 900, int height = 260);

class HtmlReport {
 public:
  explicit HtmlReport(std::string title);
  void Heading(const std::string& text);
  void Paragraph(const std::string& text);  ///< text is HTML-escaped
  void Table(const std::vector<std::string>& header,
             const std::vector<std::vector<std::string>>& rows);
  void Raw(const std::string& html);  ///< e.g. an SVG plot
  void Image(const std::string& relative_path, const std::string& caption);
  /// Writes to `path` via a temporary file and a rename; throws std::runtime_error naming it.
  void Save(const std::string& path) const;

 private:
  std::string title_;
  std::string body_;
};

std::string HtmlEscape(const std::string& text);

}  // namespace novelty::eval
