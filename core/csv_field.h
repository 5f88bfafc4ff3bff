// One field of a CSV row (RFC 4180): as it is, or in double quotes with its quotes doubled when
// it holds a comma, a quote or a line break — so that a finding such as "TPR at FPR <= 1 %,
// matches" stays one column in a spreadsheet or pandas.
#pragma once

#include <string>

namespace novelty::core {

std::string CsvField(const std::string& text);

}  // namespace novelty::core
