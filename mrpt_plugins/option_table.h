// One table of a map's options, from which everything else about them comes: reading an `.ini`
// section (MRPT's CConfigFileBase), the dump of the values as an `.ini` section with each key's
// documentation (share/*.ini is the dump of the defaults, tested), and the options in a map file
// by key (MRPT serialization). A key is written once, in the table, with its field and its
// documentation; nothing else lists the options.
//
// Every value is a number on the way through: whole numbers and flags (true/false/1/0) are
// checked as such, a choice is stored as the index of its name, and a field may hold the value
// in other units than the file (`scale`: field = file value × scale, e.g. degrees → radians).
// Unknown keys, unreadable values and out-of-range checks are errors that name the file, the
// section and the key: a misspelt option must never fall back to a default in silence.
#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/range_check.h"
#include "mrpt_plugins/ini_file.h"

namespace novelty::mrpt_plugins {

/// How errors in a map file's content begin (LoadInto in map_file.h puts the path instead).
inline constexpr const char* kMapFileError = "map file: ";

/// Throws std::runtime_error "map file: WHAT": a map file's content cannot be right.
[[noreturn]] void ThrowMapFileError(const std::string& what);

/// A string as MRPT's `<<` writes it (uint32 length, bytes), refused before any allocation when
/// the length exceeds `max_length`: a corrupt length must not ask for gigabytes.
std::string ReadShortString(mrpt::serialization::CArchive& in, std::size_t max_length,
                            const std::string& what);

/// How an option's text is read and written.
enum class OptionKind { kNumber, kWhole, kFlag, kChoice };

/// One option, its value seen as a double (see the file comment).
struct OptionEntry {
  std::string key;
  std::string doc;  ///< one line: meaning, unit, where the default comes from
  OptionKind kind = OptionKind::kNumber;
  std::vector<std::string> choices;  ///< kChoice: the names, the value is the index
  double scale = 1.0;                ///< field = file value × scale
  /// The value a map file written before this option existed was made with (its behaviour then);
  /// none: the default.
  std::optional<double> legacy;
};

/// Throws std::invalid_argument unless `value` (file units) is finite and of the entry's kind (a
/// whole number, 0 or 1 for a flag, a choice's index).
void CheckOptionValue(const OptionEntry& entry, double value);
/// Parses `text` as the entry's kind (in file units); throws std::invalid_argument saying why.
double ParseOptionText(const OptionEntry& entry, const std::string& text);
/// A field's value as the `.ini` writes it (in file units): the shortest text that reads back to
/// exactly this field value.
std::string OptionText(const OptionEntry& entry, double field_value);

template <class Options>
class OptionTable {
 public:
  /// Adds `key` for the field `field(options)` returns a reference to (double, int, bool).
  template <class Field>
  OptionTable& Add(std::string key, Field field, std::string doc, double scale = 1.0,
                   std::optional<double> legacy = std::nullopt) {
    using T = std::remove_reference_t<decltype(field(std::declval<Options&>()))>;
    OptionEntry e{std::move(key), std::move(doc), KindOf<T>(), {}, scale, legacy};
    rows_.push_back({std::move(e),
                     [field](const Options& o) { return double(field(const_cast<Options&>(o))); },
                     [field](Options& o, double v) { field(o) = FromDouble<T>(v); }});
    return *this;
  }
  /// Adds `key` for an enum field whose values 0, 1, … are named by `choices`.
  template <class Field>
  OptionTable& AddChoice(std::string key, Field field, std::vector<std::string> choices,
                         std::string doc) {
    using T = std::remove_reference_t<decltype(field(std::declval<Options&>()))>;
    OptionEntry e{std::move(key), std::move(doc), OptionKind::kChoice, std::move(choices), 1.0,
                  std::nullopt};
    rows_.push_back({std::move(e),
                     [field](const Options& o) { return double(field(const_cast<Options&>(o))); },
                     [field](Options& o, double v) { field(o) = T(int(v)); }});
    return *this;
  }
  /// Adds every option of `sub`, for the part of Options that `part` returns.
  template <class Sub, class Part>
  OptionTable& Include(const OptionTable<Sub>& sub, Part part) {
    for (const auto& r : sub.rows()) {
      rows_.push_back(
          {r.entry,
           [get = r.get, part](const Options& o) { return get(part(const_cast<Options&>(o))); },
           [set = r.set, part](Options& o, double v) { set(part(o), v); }});
    }
    for (const auto& check : sub.checks()) {
      checks_.push_back([check, part](const Options& o) { check(part(const_cast<Options&>(o))); });
    }
    return *this;
  }
  /// Checks the options as a whole after a read (ranges, relations); throws
  /// std::invalid_argument saying what is wrong.
  OptionTable& Check(std::function<void(const Options&)> check) {
    checks_.push_back(std::move(check));
    return *this;
  }

  /// Reads `section` on top of `options`. Throws std::runtime_error naming `source`, the
  /// section and the key for an unknown key, an unreadable value or a failed check.
  void Load(const mrpt::config::CConfigFileBase& config, const std::string& section,
            const std::string& source, Options& options) const {
    std::vector<std::string> present;
    config.getAllKeys(section, present);
    for (const std::string& key : present) {
      const Row* r = Find(key);
      const std::string where = source + ": [" + section + "] " + key;
      if (!r) throw std::runtime_error(where + ": unknown option");
      const std::string text = StripIniComment(config.read_string(section, key, "", true));
      try {
        r->set(options, ParseOptionText(r->entry, text) * r->entry.scale);
      } catch (const std::exception& e) {
        throw std::runtime_error(where + " = '" + text + "': " + e.what());
      }
    }
    RunChecks(options, source + ": [" + section + "] ");
  }

  /// The options as an `.ini` section: `key = value ; doc`, one line each, in table order.
  void Dump(std::ostream& out, const std::string& section, const Options& options) const {
    std::size_t key_width = 0, value_width = 0;
    std::vector<std::string> values;
    for (const Row& r : rows_) {
      values.push_back(OptionText(r.entry, r.get(options)));
      key_width = std::max(key_width, r.entry.key.size());
      value_width = std::max(value_width, values.back().size());
    }
    out << "[" << section << "]\n";
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      std::string line = rows_[i].entry.key;
      line.resize(key_width, ' ');
      line += " = " + values[i];
      if (!rows_[i].entry.doc.empty()) {
        line.resize(key_width + 3 + value_width, ' ');
        line += " ; " + rows_[i].entry.doc;
      }
      out << line << "\n";
    }
  }

  /// Writes every option into `section` of `target` as Dump would (without the documentation).
  void Save(mrpt::config::CConfigFileBase& target, const std::string& section,
            const Options& options) const {
    for (const Row& r : rows_) {
      target.write(section, r.entry.key, OptionText(r.entry, r.get(options)));
    }
  }

  /// Every option by key: a count, then (key, value) pairs.
  void Write(mrpt::serialization::CArchive& out, const Options& options) const {
    out << uint32_t(rows_.size());
    for (const Row& r : rows_) out << r.entry.key << r.get(options);
  }
  /// Reads what Write wrote into `options`: keys the file lacks get their legacy value (or keep
  /// the default); an unknown key or a failed check throws std::runtime_error.
  void Read(mrpt::serialization::CArchive& in, Options& options) const {
    uint32_t n = 0;
    in >> n;
    if (n > 4 * rows_.size() + 64) ThrowMapFileError("implausible option count");
    std::vector<bool> seen(rows_.size(), false);
    for (uint32_t i = 0; i < n; ++i) {
      const std::string key = ReadShortString(in, 256, "option name");
      double value = 0.0;
      in >> value;
      const Row* r = Find(key);
      if (!r) {
        ThrowMapFileError("unknown option '" + key + "' (written by a newer version?)");
      }
      seen[std::size_t(r - rows_.data())] = true;
      SetChecked(*r, value, options);
    }
    SetLegacyExcept(seen, options);
    RunChecks(options, kMapFileError);
  }
  /// Reads the fields `keys` stored one after another as raw values (a flag as a bool, anything
  /// else as a double), as map files before option tables did; the others get their legacy value.
  /// Each value is checked as a value (finite, whole, …) but not against the table's checks,
  /// which are newer than these files: a map that loaded before loads now.
  void ReadPositional(mrpt::serialization::CArchive& in, const std::vector<std::string>& keys,
                      Options& options) const {
    std::vector<bool> seen(rows_.size(), false);
    for (const std::string& key : keys) {
      const Row* r = Find(key);
      if (!r) throw std::logic_error("OptionTable::ReadPositional: no option " + key);
      double value = 0.0;
      if (r->entry.kind == OptionKind::kFlag) {
        uint8_t b = 0;  // MRPT writes a bool as one byte; any other value than 0 or 1 is corrupt
        in >> b;
        if (b > 1) ThrowMapFileError(key + ": flag byte " + std::to_string(b) + ", not 0 or 1");
        value = b;
      } else {
        in >> value;
      }
      seen[std::size_t(r - rows_.data())] = true;
      SetChecked(*r, value, options);
    }
    SetLegacyExcept(seen, options);
  }

  struct Row {
    OptionEntry entry;
    std::function<double(const Options&)> get;  ///< the field's value (field units)
    std::function<void(Options&, double)> set;  ///< sets the field (field units)
  };
  const std::vector<Row>& rows() const { return rows_; }
  const std::vector<std::function<void(const Options&)>>& checks() const { return checks_; }

 private:
  template <class T>
  static constexpr OptionKind KindOf() {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, int> || std::is_same_v<T, bool>,
                  "options are double, int or bool (AddChoice for enums)");
    if constexpr (std::is_same_v<T, bool>) return OptionKind::kFlag;
    if constexpr (std::is_same_v<T, int>) return OptionKind::kWhole;
    return OptionKind::kNumber;
  }
  template <class T>
  static T FromDouble(double v) {
    if constexpr (std::is_same_v<T, bool>) return v != 0.0;
    if constexpr (std::is_same_v<T, int>) return int(v);
    return v;
  }
  const Row* Find(const std::string& key) const {
    for (const Row& r : rows_)
      if (r.entry.key == key) return &r;
    return nullptr;
  }
  // A value read from a map file (field units) must be one the `.ini` could have given.
  static void SetChecked(const Row& r, double value, Options& options) {
    try {
      CheckOptionValue(r.entry, value / r.entry.scale);
    } catch (const std::invalid_argument& e) {
      ThrowMapFileError("option " + r.entry.key + ": " + e.what());
    }
    r.set(options, value);
  }
  void SetLegacyExcept(const std::vector<bool>& seen, Options& options) const {
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (!seen[i] && rows_[i].entry.legacy) rows_[i].set(options, *rows_[i].entry.legacy);
    }
  }
  void RunChecks(const Options& options, const std::string& where) const {
    try {
      for (const auto& check : checks_) check(options);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(where + e.what());
    }
  }

  std::vector<Row> rows_;
  std::vector<std::function<void(const Options&)>> checks_;
};

/// MRPT's CLoadableOptions for a struct `Derived` that has a table (static Table()), its map class
/// (static kClass) and a section name (static kSection): load, save and dump all come from the
/// table.
template <class Derived>
class TabledOptions : public mrpt::config::CLoadableOptions {
 public:
  /// Reads `section` on top of the current values; errors name the file, section and key
  /// (std::runtime_error).
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                          const std::string& section) override {
    Derived::Table().Load(source, section, ConfigSourceName(source), Self());
  }
  void saveToConfigFile(mrpt::config::CConfigFileBase& target,
                        const std::string& section) const override {
    Derived::Table().Save(target, section, Self());
  }
  /// The values as an `.ini` section named Derived::kSection, each key with its documentation.
  void dumpToTextStream(std::ostream& out) const override {
    Derived::Table().Dump(out, Derived::kSection, Self());
  }
  /// A CMultiMetricMap .ini declaring one map of class Derived::kClass in [map] with these
  /// values in its options section (Derived::kSection): share/appearance.ini and
  /// share/differencing.ini are this dump of the defaults and drop into a user's .ini as they are.
  void dumpAsMultiMap(std::ostream& out) const {
    out << "[map]\n" << Derived::kClass << "_count = 1\n\n";
    dumpToTextStream(out);
  }
  /// The defaults overridden by `section` of `source` (errors name `source_name`).
  static Derived FromConfig(const mrpt::config::CConfigFileBase& source, const std::string& section,
                            const std::string& source_name) {
    Derived d;
    Derived::Table().Load(source, section, source_name, d);
    return d;
  }
  /// The same from a file; throws std::runtime_error naming it if it does not exist.
  static Derived FromFile(const std::string& path, const std::string& section = Derived::kSection);

 private:
  Derived& Self() { return static_cast<Derived&>(*this); }
  const Derived& Self() const { return static_cast<const Derived&>(*this); }
};

/// Range checks for OptionTable::Check: throw std::invalid_argument "KEY must be > 0" (>= 0).
void CheckPositive(double value, const char* key);
void CheckNotNegative(double value, const char* key);
/// Throws std::invalid_argument "KEY must be in [lo, hi], got VALUE" (NaN fails too).
using core::CheckInRange;

template <class Derived>
Derived TabledOptions<Derived>::FromFile(const std::string& path, const std::string& section) {
  return FromConfig(*OpenConfigFile(path), section, path);
}

}  // namespace novelty::mrpt_plugins
