// A map's options on a command line, from its option table (mrpt_plugins/option_table.h), so that
// each option is written once: the flag's help is the table's documentation with the default the
// table's struct gives, a value is parsed, scaled and checked as the `.ini` does it, and any other
// key of the table is reachable with --set KEY=VALUE; --options FILE reads the options from an
// .ini first (share/thesis/*.ini: the thesis's settings). No program declares a map option's
// default or range itself.
//
//   apps::TableFlags<IlluminationInvariantMapConfig> flags(
//       cmd, {{"kappa", "kappa"}, {"zernike_grid", "grid"}});
//   cmd.Parse(argc, argv);
//   IlluminationInvariantMapConfig config = flags.Values();  // defaults + flags + --set, checked
#pragma once

#include <tclap/CmdLine.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "apps/shell/program.h"
#include "mrpt_plugins/option_table.h"

namespace novelty::apps {

template <class Config>
class TableFlags {
 public:
  struct Flag {
    std::string key;   ///< the table's key
    std::string flag;  ///< the command line's name, without "--"
  };

  /// Adds a flag for each of `flags` and --set KEY=VALUE (repeatable, any key of the table) to
  /// `cmd`. A flag option (true/false) becomes a switch.
  TableFlags(TCLAP::CmdLine& cmd, std::vector<Flag> flags) : flags_(std::move(flags)) {
    const Config defaults;
    for (const Flag& f : flags_) {
      const Row& r = RowOf(f.key);
      const std::string help =
          r.entry.doc + " [" + Config::kClass + " option " + f.key +
          (r.entry.kind != mrpt_plugins::OptionKind::kFlag
               ? ", default " + mrpt_plugins::OptionText(r.entry, r.get(defaults)) + "]"
           : r.get(defaults) != 0.0 ? ", on by default; --set " + f.key + "=false turns it off]"
                                    : "]");
      if (r.entry.kind == mrpt_plugins::OptionKind::kFlag) {
        switches_.push_back(std::make_unique<TCLAP::SwitchArg>("", f.flag, help, cmd));
        values_.push_back(nullptr);
      } else {
        values_.push_back(std::make_unique<TCLAP::ValueArg<std::string>>(
            "", f.flag, help, false, "",
            r.entry.kind == mrpt_plugins::OptionKind::kChoice ? Join(r.entry.choices) : "VALUE",
            cmd));
        switches_.push_back(nullptr);
      }
    }
    options_ = std::make_unique<TCLAP::ValueArg<std::string>>(
        "", "options",
        std::string("A CMultiMetricMap .ini whose [") + Config::kSection + "] sets options on " +
            "top of the defaults, before the flags and --set (e.g. share/thesis/*.ini for the " +
            "thesis's settings)",
        false, "", "FILE", cmd);
    set_ = std::make_unique<TCLAP::MultiArg<std::string>>(
        "", "set",
        std::string("Any option of ") + Config::kClass +
            " (share/*.ini lists them with their defaults), as KEY=VALUE; repeatable",
        false, "KEY=VALUE", cmd);
  }

  /// Whether any of the flags, --set or --options was given.
  bool AnySet() const {
    for (std::size_t i = 0; i < flags_.size(); ++i)
      if ((switches_[i] && switches_[i]->isSet()) || (values_[i] && values_[i]->isSet()))
        return true;
    return options_->isSet() || set_->isSet();
  }

  /// The defaults with the flags and --set given on top, checked as the `.ini` is. Throws
  /// UsageError naming the flag and why.
  Config Values() const {
    Config c = options_->isSet() ? Config::FromFile(options_->getValue()) : Config();
    std::vector<std::string> given;  // keys set so far: a key given twice is a contradiction
    const auto once = [&given](const std::string& key, const std::string& where) {
      if (std::find(given.begin(), given.end(), key) != given.end())
        throw UsageError(where + ": option " + key + " is given twice (a flag and --set?)");
      given.push_back(key);
    };
    for (std::size_t i = 0; i < flags_.size(); ++i) {
      if ((switches_[i] && switches_[i]->isSet()) || (values_[i] && values_[i]->isSet()))
        once(flags_[i].key, "--" + flags_[i].flag);
      if (switches_[i] && switches_[i]->isSet())
        Set(c, flags_[i].key, "true", "--" + flags_[i].flag);
      if (values_[i] && values_[i]->isSet())
        Set(c, flags_[i].key, values_[i]->getValue(), "--" + flags_[i].flag);
    }
    for (const std::string& kv : set_->getValue()) {
      const std::size_t eq = kv.find('=');
      if (eq == std::string::npos || eq == 0)
        throw UsageError("--set " + kv + ": expected KEY=VALUE");
      const std::string key = kv.substr(0, eq);
      if (!Find(key))
        throw UsageError("--set " + kv + ": " + Config::kClass + " has no option '" + key + "'");
      once(key, "--set " + key);
      Set(c, key, kv.substr(eq + 1), "--set " + key);
    }
    try {
      for (const auto& check : Config::Table().checks()) check(c);
    } catch (const std::invalid_argument& e) {
      throw UsageError(NameTheFlag(e.what()));
    }
    return c;
  }

 private:
  using Row = typename mrpt_plugins::OptionTable<Config>::Row;

  static const Row* Find(const std::string& key) {
    for (const Row& r : Config::Table().rows())
      if (r.entry.key == key) return &r;
    return nullptr;
  }
  static const Row& RowOf(const std::string& key) {
    if (const Row* r = Find(key)) return *r;
    throw std::logic_error(std::string(Config::kClass) + " has no option '" + key + "'");
  }
  // The table's checks say "KEY must be …" (core::CheckInRange): the user typed the flag.
  std::string NameTheFlag(const std::string& message) const {
    for (const Flag& f : flags_)
      if (message.rfind(f.key + " ", 0) == 0 || message.rfind(f.key + ":", 0) == 0)
        return "--" + f.flag + message.substr(f.key.size());
    return std::string(Config::kClass) + " option " + message;
  }
  static std::string Join(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : "|") + n;
    return s;
  }
  static void Set(Config& c, const std::string& key, const std::string& text,
                  const std::string& where) {
    const Row& r = RowOf(key);
    try {
      r.set(c, mrpt_plugins::ParseOptionText(r.entry, text) * r.entry.scale);
    } catch (const std::invalid_argument& e) {
      throw UsageError(where + " " + text + ": " + e.what());
    }
  }

  std::vector<Flag> flags_;
  std::vector<std::unique_ptr<TCLAP::SwitchArg>> switches_;
  std::unique_ptr<TCLAP::ValueArg<std::string>> options_;
  std::vector<std::unique_ptr<TCLAP::ValueArg<std::string>>> values_;
  std::unique_ptr<TCLAP::MultiArg<std::string>> set_;
};

}  // namespace novelty::apps
