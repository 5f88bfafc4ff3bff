#include "apps/shell/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace novelty::apps {

std::string FormatProgress(const std::string& what, int done, int total, double seconds,
                           int bar_width) {
  std::string s = what;
  if (total > 0 && bar_width > 0) {
    const int filled = std::clamp(int(std::lround(double(bar_width) * done / total)), 0, bar_width);
    s += " [" + std::string(std::size_t(filled), '#') +
         std::string(std::size_t(bar_width - filled), '.') + "]";
  }
  char text[160];
  if (total > 0)
    std::snprintf(text, sizeof text, "  %d/%d frames", done, total);
  else
    std::snprintf(text, sizeof text, "  %d frames", done);
  s += text;
  if (seconds > 0 && done > 0) {
    const double rate = done / seconds;
    std::snprintf(text, sizeof text, "  %.1f frames/s", rate);
    s += text;
    if (total > done) {
      std::snprintf(text, sizeof text, "  %.0f s left", std::ceil((total - done) / rate));
      s += text;
    }
  }
  return s;
}

ProgressOptions DefaultProgressOptions(bool quiet) {
  ProgressOptions o;
  o.quiet = quiet;
  o.terminal = isatty(fileno(stderr)) != 0;
  return o;
}

Progress::Progress(std::string what, int total, ProgressOptions options, std::FILE* out)
    : what_(std::move(what)),
      total_(std::max(total, 0)),
      options_(options),
      out_(out),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  Finish();
}

double Progress::Seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::Update(int done) {
  done_ = done;
  if (options_.quiet || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_draw_).count();
  if (since < (options_.terminal ? options_.redraw_every_s : options_.line_every_s)) return;
  last_draw_ = now;
  Draw(false);
}

void Progress::Finish() {
  if (finished_) return;
  finished_ = true;
  if (options_.quiet) return;
  if (drawn_ || options_.terminal) Draw(true);
}

void Progress::Draw(bool final_line) {
  const std::string line =
      FormatProgress(what_, done_, total_, Seconds(), options_.terminal ? 30 : 0);
  if (options_.terminal)
    std::fprintf(out_, "\r%s\033[K%s", line.c_str(), final_line ? "\n" : "");
  else
    std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
  drawn_ = true;
}

}  // namespace novelty::apps
