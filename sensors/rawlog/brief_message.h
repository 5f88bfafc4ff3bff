// One line for a log from any exception: MRPT's exceptions carry a banner, the message, its
// location and a call stack over many lines (nested ones repeat that), and texts read from a
// foreign file may hold binary bytes. A tool that skips a bad frame prints one line per frame.
#pragma once

#include <exception>
#include <string>

namespace novelty::sensors {

/// The "Message:" parts of an MRPT exception joined by ": " (any other text as is), on one line,
/// with control bytes and bytes that are not UTF-8 shown as '?', at most `max_length` bytes (cut
/// between characters, then "…").
std::string BriefMessage(const std::exception& e, std::size_t max_length = 300);

/// The same for a message text.
std::string BriefMessage(const std::string& what, std::size_t max_length = 300);

}  // namespace novelty::sensors
