// The program shell: what every NoveltyMaps program does the same way. Each `main` is
//
//   int main(int argc, char** argv) {
//     return novelty::apps::RunProgram("novelty-run", [&] { return Run(argc, argv); });
//   }
//
// and errors are exceptions: the shell prints exactly one line "novelty-run: MESSAGE" on stderr
// (MRPT's multi-line traces cut to their messages, sensors::BriefMessage) and exits with the code
// below. The libraries' own chatter on stderr — OpenCV's log lines, libpng's "libpng error:" and
// warnings — is silenced while the program runs: the program's message names the file instead.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace novelty::apps {

/// The exit codes of every program (docs/commands.md).
enum ExitCode : int {
  kExitOk = 0,       ///< done
  kExitFailed = 1,   ///< an input, option file or run failed; stderr says which, in one line
  kExitUsage = 2,    ///< a bad command line (unknown flag, missing or malformed value)
  kExitPartial = 3,  ///< done, but stopped early or judged less than asked (the summary says why)
};

/// A command line that parses but cannot be right: a value out of range, flags that conflict.
/// Exit code kExitUsage.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Runs `body` as the program `name` and returns its exit code: the body's own, or kExitUsage for
/// TCLAP::ArgException and UsageError, kExitFailed for any other exception (one line on stderr).
int RunProgram(const std::string& name, const std::function<int()>& body);

/// The one line RunProgram prints for an exception (without the program name); a message
/// longer than `max_length` characters is cut with "…".
std::string ErrorLine(const std::exception& e, std::size_t max_length = 600);

}  // namespace novelty::apps
