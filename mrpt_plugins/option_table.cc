#include "mrpt_plugins/option_table.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace novelty::mrpt_plugins {

void CheckOptionValue(const OptionEntry& entry, double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("not a number");
  switch (entry.kind) {
    case OptionKind::kNumber:
      return;
    case OptionKind::kWhole:
      if (value != std::round(value) || std::abs(value) > 1e9)
        throw std::invalid_argument("not a whole number");
      return;
    case OptionKind::kFlag:
      if (value != 0.0 && value != 1.0) throw std::invalid_argument("not true/false");
      return;
    case OptionKind::kChoice:
      if (value != std::round(value) || value < 0 || value >= double(entry.choices.size()))
        throw std::invalid_argument("not a known choice");
      return;
  }
}

double ParseOptionText(const OptionEntry& entry, const std::string& text) {
  if (entry.kind == OptionKind::kFlag) {
    if (text == "true" || text == "1") return 1.0;
    if (text == "false" || text == "0") return 0.0;
    throw std::invalid_argument("not true/false");
  }
  if (entry.kind == OptionKind::kChoice) {
    for (std::size_t i = 0; i < entry.choices.size(); ++i)
      if (text == entry.choices[i]) return double(i);
    std::string names;
    for (std::size_t i = 0; i < entry.choices.size(); ++i)
      names += (i == 0 ? "" : i + 1 == entry.choices.size() ? " or " : ", ") + entry.choices[i];
    throw std::invalid_argument("not " + names);
  }
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw std::invalid_argument("not a number");
  }
  if (text.find_first_not_of(" \t", used) != std::string::npos) {
    throw std::invalid_argument("not a number");
  }
  CheckOptionValue(entry, value);
  return value;
}

void CheckPositive(double value, const char* key) {
  if (!(value > 0.0)) throw std::invalid_argument(std::string(key) + " must be > 0");
}
void CheckNotNegative(double value, const char* key) {
  if (!(value >= 0.0)) throw std::invalid_argument(std::string(key) + " must be >= 0");
}

void ThrowMapFileError(const std::string& what) {
  throw std::runtime_error(std::string(kMapFileError) + what);
}

std::string ReadShortString(mrpt::serialization::CArchive& in, std::size_t max_length,
                            const std::string& what) {
  uint32_t length = 0;
  in >> length;
  if (length > max_length) {
    ThrowMapFileError(what + " of " + std::to_string(length) + " bytes (at most " +
                      std::to_string(max_length) + ")");
  }
  std::string s(length, '\0');
  if (length > 0) in.ReadBuffer(s.data(), length);
  return s;
}

std::string OptionText(const OptionEntry& entry, double field_value) {
  const double value = field_value / entry.scale;
  switch (entry.kind) {
    case OptionKind::kFlag:
      return value != 0.0 ? "true" : "false";
    case OptionKind::kChoice:
      return entry.choices.at(std::size_t(value));
    default:
      break;
  }
  char buf[40];
  // The shortest text that reads back exactly, without an exponent for ordinary magnitudes
  // (180, not 1.8e+02).
  const bool plain = std::abs(value) >= 1e-4 && std::abs(value) < 1e15;
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (plain && digits < 17 && std::strchr(buf, 'e')) continue;
    if (std::stod(buf) * entry.scale == field_value) break;
  }
  return buf;
}

}  // namespace novelty::mrpt_plugins
