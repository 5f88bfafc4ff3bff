// The one progress display of every program: on a terminal a bar redrawn in place with frames/s
// and the time left, otherwise (a log file, CI) a plain line every few seconds, so a long run
// shows it is alive without flooding the log. It goes to stderr, the results to stdout.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace novelty::apps {

struct ProgressOptions {
  /// Nothing is shown (the programs' --quiet).
  bool quiet = false;
  /// Draw the bar in place; by default when stderr is a terminal.
  bool terminal = false;
  /// Seconds between plain lines when not on a terminal.
  double line_every_s = 5.0;
  /// Seconds between redraws on a terminal.
  double redraw_every_s = 0.1;
};

/// What the display says after `done` of `total` steps (`total` 0: unknown) in `seconds`, e.g.
/// "learning [#######.......]  120/300 frames  14.2 frames/s  13 s left". `bar_width` 0 drops
/// the bar (the plain lines).
std::string FormatProgress(const std::string& what, int done, int total, double seconds,
                           int bar_width);

/// Quiet if asked, the bar when stderr is a terminal (isatty), plain lines otherwise.
ProgressOptions DefaultProgressOptions(bool quiet = false);

class Progress {
 public:
  /// `what` names the stage ("learning", "judging lighting 2/4"); `total` 0 if unknown.
  Progress(std::string what, int total, ProgressOptions options = DefaultProgressOptions(),
           std::FILE* out = stderr);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// `done` steps are done; drawn if it is time to.
  void Update(int done);
  /// The last state, on a line of its own (once; the destructor calls it).
  void Finish();

 private:
  void Draw(bool final_line);
  double Seconds() const;

  std::string what_;
  int total_;
  ProgressOptions options_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  int done_ = 0;
  bool drawn_ = false, finished_ = false;
};

}  // namespace novelty::apps
