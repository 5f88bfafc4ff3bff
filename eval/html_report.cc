#include "eval/html_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/temporary_file.h"

namespace novelty::eval {

std::string HtmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

std::vector<double> NiceTicks(double lo, double hi, int count) {
  if (!(hi > lo) || count < 1) return {lo};
  const double raw = (hi - lo) / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw) break;
  }
  std::vector<double> ticks;
  const long first = std::lround(std::ceil(lo / step - 1e-9)),
             last = std::lround(std::floor(hi / step + 1e-9));
  for (long k = first; k <= last; ++k) ticks.push_back(k == 0 ? 0.0 : double(k) * step);
  return ticks;
}

std::string SvgLinePlot(const std::string& title, const std::string& x_label,
                        const std::string& y_label, const std::vector<PlotSeries>& series,
                        const std::vector<PlotBand>& bands, int width, int height) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const PlotSeries& s : series) {
    for (const auto& [x, y] : s.points) {
      if (!std::isfinite(y)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 <= y0) y1 = y0 + 1;
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad, y1 += pad;
  const int l = 60, r = 150, t = 28, b = 40;
  const double pw = width - l - r, ph = height - t - b;
  auto X = [&](double x) { return l + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double y) { return t + (y1 - y) / (y1 - y0) * ph; };
  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
    << "' font-family='sans-serif' font-size='11'>\n";
  o << "<text x='" << l << "' y='16' font-size='13' font-weight='bold'>" << HtmlEscape(title)
    << "</text>\n";
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const double a = X(std::max(bands[i].from, x0)), c = X(std::min(bands[i].to, x1));
    if (c <= a) continue;
    o << "<rect x='" << a << "' y='" << t << "' width='" << c - a << "' height='" << ph
      << "' fill='" << (i % 2 ? "#f2f2f2" : "#e6eef7") << "'/>\n<text x='" << a + 3 << "' y='"
      << t + 12 << "' fill='#777'>" << HtmlEscape(bands[i].label) << "</text>\n";
  }
  if (y0 < 0 && y1 > 0) {  // the 0 dB line
    o << "<line x1='" << l << "' x2='" << l + pw << "' y1='" << Y(0) << "' y2='" << Y(0)
      << "' stroke='#999' stroke-dasharray='4 3'/>\n";
  }
  o << "<rect x='" << l << "' y='" << t << "' width='" << pw << "' height='" << ph
    << "' fill='none' stroke='#333'/>\n";
  for (const double xv : NiceTicks(x0, x1)) {
    o << "<text x='" << X(xv) << "' y='" << t + ph + 14 << "' text-anchor='middle'>" << Num(xv)
      << "</text>\n";
  }
  for (const double yv : NiceTicks(y0, y1)) {
    o << "<text x='" << l - 5 << "' y='" << Y(yv) + 4 << "' text-anchor='end'>" << Num(yv)
      << "</text>\n";
  }
  o << "<text x='" << l + pw / 2 << "' y='" << height - 6 << "' text-anchor='middle'>"
    << HtmlEscape(x_label) << "</text>\n<text x='14' y='" << t + ph / 2
    << "' transform='rotate(-90 14 " << t + ph / 2 << ")' text-anchor='middle'>"
    << HtmlEscape(y_label) << "</text>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    // Runs of joined points; a run of one point (nothing to join it to) is drawn as a dot.
    std::string path, dots;
    std::vector<std::pair<double, double>> run;
    const auto end_run = [&] {
      if (run.size() == 1) {
        dots += "<circle cx='" + Num(run[0].first) + "' cy='" + Num(run[0].second) +
                "' r='1.5' fill='" + s.color + "'/>\n";
      }
      for (std::size_t i = 0; i < run.size() && run.size() > 1; ++i)
        path += (i ? " L" : " M") + Num(run[i].first) + " " + Num(run[i].second);
      run.clear();
    };
    double last_x = 0.0;
    for (const auto& [x, y] : s.points) {
      if (!std::isfinite(y)) {
        end_run();
        continue;
      }
      if (s.max_step > 0.0 && std::abs(x - last_x) > s.max_step) end_run();
      last_x = x;
      run.emplace_back(X(x), Y(std::clamp(y, y0, y1)));
    }
    end_run();
    o << "<path d='" << path << "' fill='none' stroke='" << s.color << "' stroke-width='1.3'/>\n"
      << dots;
    const double ly = t + 14 + 16.0 * k;
    o << "<line x1='" << l + pw + 10 << "' x2='" << l + pw + 30 << "' y1='" << ly << "' y2='" << ly
      << "' stroke='" << s.color << "' stroke-width='2'/><text x='" << l + pw + 35 << "' y='"
      << ly + 4 << "'>" << HtmlEscape(s.name) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::Heading(const std::string& text) {
  body_ += "<h2>" + HtmlEscape(text) + "</h2>\n";
}
void HtmlReport::Paragraph(const std::string& text) {
  body_ += "<p>" + HtmlEscape(text) + "</p>\n";
}
void HtmlReport::Raw(const std::string& html) {
  body_ += html;
}

void HtmlReport::Table(const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows) {
  body_ += "<table><tr>";
  for (const std::string& h : header) body_ += "<th>" + HtmlEscape(h) + "</th>";
  body_ += "</tr>\n";
  for (const auto& row : rows) {
    body_ += "<tr>";
    for (const std::string& c : row) body_ += "<td>" + HtmlEscape(c) + "</td>";
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

void HtmlReport::Image(const std::string& path, const std::string& caption) {
  body_ += "<figure><img src='" + HtmlEscape(path) + "' alt='" + HtmlEscape(caption) +
           "'><figcaption>" + HtmlEscape(caption) + "</figcaption></figure>\n";
}

void HtmlReport::Save(const std::string& path) const {
  core::TemporaryFile tmp(path);
  {
    std::ofstream out(tmp.path());
    out << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>" << HtmlEscape(title_)
        << "</title>\n<style>body{font-family:sans-serif;max-width:1700px;margin:20px}"
           "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:3px 8px;"
           "text-align:right}figure{margin:8px 0}img{max-width:100%}</style></head><body>\n<h1>"
        << HtmlEscape(title_) << "</h1>\n"
        << body_ << "</body></html>\n";
    if (!out) throw std::runtime_error(path + ": cannot write the report");
  }
  tmp.Commit();
}

}  // namespace novelty::eval
