// Whether two paths name the same file, however they are written ("run.rawlog", "./run.rawlog",
// "../data/run.rawlog", a symbolic link): programs compare their outputs with their inputs so that
// an output never overwrites an input.
#pragma once

#include <string>

namespace novelty::core {

/// True if `a` and `b` resolve to the same file: the same existing file (std::filesystem::
/// equivalent), or, where one does not exist yet, the same canonical path.
bool SameFile(const std::string& a, const std::string& b);

}  // namespace novelty::core
