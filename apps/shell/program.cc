#include "apps/shell/program.h"

#include <tclap/ArgException.h>

#include <cstdio>
#include <opencv2/core/utils/logger.hpp>

#include "apps/shell/quiet_libpng.h"
#include "sensors/rawlog/brief_message.h"

namespace novelty::apps {

std::string ErrorLine(const std::exception& e, std::size_t max_length) {
  if (const auto* arg = dynamic_cast<const TCLAP::ArgException*>(&e)) {
    const std::string id = arg->argId();
    return sensors::BriefMessage(arg->error() + (id.empty() ? "" : " (" + id + ")"), max_length);
  }
  return sensors::BriefMessage(e, max_length);
}

int RunProgram(const std::string& name, const std::function<int()>& body) {
  // OpenCV's warnings ("imread_(…): can't open/read file") come before the program's own message
  // and say less; errors still reach the program as exceptions.
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR);
  QuietLibpng();
  int code = kExitFailed;
  try {
    code = body();
  } catch (const TCLAP::ArgException& e) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), ErrorLine(e).c_str());
    code = kExitUsage;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), ErrorLine(e).c_str());
    code = kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), ErrorLine(e).c_str());
    code = kExitFailed;
  }
  std::fflush(stdout);
  return code;
}

}  // namespace novelty::apps
