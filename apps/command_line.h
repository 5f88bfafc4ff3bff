// TCLAP's command line as every program here uses it: a bad argument throws TCLAP::ArgException,
// which the program prints in one line and answers with exit status 2 (docs/bad_inputs.md),
// instead of TCLAP printing its whole usage and exiting 1; --help and --version print as TCLAP
// does and exit 0.
#pragma once

#include <tclap/CmdLine.h>

#include <cstdlib>
#include <string>

namespace novelty::apps {

class CommandLine : public TCLAP::CmdLine {
 public:
  CommandLine(const std::string& message, const std::string& version)
      : TCLAP::CmdLine(message, ' ', version) {
    setExceptionHandling(false);
  }
  /// Parses argv; throws TCLAP::ArgException for a bad argument, exits after --help/--version.
  void Parse(int argc, char** argv) {
    try {
      parse(argc, argv);
    } catch (const TCLAP::ExitException& e) {
      std::exit(e.getExitStatus());
    }
  }
};

}  // namespace novelty::apps
