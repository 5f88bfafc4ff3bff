#include "mrpt_plugins/option_table.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

namespace novelty::mrpt_plugins {
namespace {

enum class Mode { kFast, kExact };

struct Toy {
  double rate = 0.8;
  double angle = 5.0 * M_PI / 180.0;  // radians; degrees in the file
  int count = 64;
  bool on = true;
  Mode mode = Mode::kExact;
  double added_later = 1.0 / 12.0;  // files from before it existed behave as 0
};

const OptionTable<Toy>& ToyTable() {
  static const OptionTable<Toy> table = [] {
    OptionTable<Toy> t;
    t.Add(
         "rate", [](Toy & o) -> auto& { return o.rate; }, "a rate")
        .Add(
            "angle_deg", [](Toy & o) -> auto& { return o.angle; }, "degrees", M_PI / 180.0)
        .Add(
            "count", [](Toy & o) -> auto& { return o.count; }, "")
        .Add(
            "on", [](Toy & o) -> auto& { return o.on; }, "a flag")
        .AddChoice(
            "mode", [](Toy & o) -> auto& { return o.mode; }, {"fast", "exact"}, "")
        .Add(
            "added_later", [](Toy & o) -> auto& { return o.added_later; }, "", 1.0, 0.0)
        .Check([](const Toy& o) {
          if (!(o.rate > 0 && o.rate <= 1)) throw std::invalid_argument("rate must be in (0, 1]");
        });
    return t;
  }();
  return table;
}

// What ToyTable().Read makes of the archive that `write` fills.
Toy ReadBack(const std::function<void(mrpt::serialization::CArchive&)>& write) {
  mrpt::io::CMemoryStream buffer;
  auto out = mrpt::serialization::archiveFrom(buffer);
  write(out);
  buffer.Seek(0);
  auto in = mrpt::serialization::archiveFrom(buffer);
  Toy o;
  ToyTable().Read(in, o);
  return o;
}

std::string LoadError(const std::string& text) {
  Toy o;
  try {
    ToyTable().Load(mrpt::config::CConfigFileMemory(text), "s", "toy.ini", o);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(OptionTable, WritesTheShortestTextThatReadsBack) {
  const OptionEntry number{"x", "", OptionKind::kNumber, {}, 1.0, std::nullopt};
  EXPECT_EQ(OptionText(number, 0.8), "0.8");
  EXPECT_EQ(OptionText(number, 5.0), "5");
  EXPECT_EQ(OptionText(number, 1e-7), "1e-07");
  EXPECT_EQ(std::stod(OptionText(number, 1.0 / 12.0)), 1.0 / 12.0);
  EXPECT_EQ(std::stod(OptionText(number, M_PI)), M_PI);
  EXPECT_EQ(StripIniComment("  4 ; m "), "4");
  EXPECT_EQ(StripIniComment("true // yes"), "true");
}

TEST(OptionTable, LoadsEveryKindAndConvertsUnits) {
  Toy o;
  ToyTable().Load(
      mrpt::config::CConfigFileMemory(
          "[s]\nrate = 0.5\nangle_deg = 90 ; deg\ncount = 7\non = false\nmode = fast\n"),
      "s", "toy.ini", o);
  EXPECT_EQ(o.rate, 0.5);
  EXPECT_NEAR(o.angle, M_PI / 2, 1e-15);
  EXPECT_EQ(o.count, 7);
  EXPECT_FALSE(o.on);
  EXPECT_EQ(o.mode, Mode::kFast);
  EXPECT_EQ(o.added_later, 1.0 / 12.0);  // absent: the default stays
}

TEST(OptionTable, NamesTheFileSectionAndKeyOfEveryBadValue) {
  EXPECT_EQ(LoadError("[s]\nrat = 0.5\n"), "toy.ini: [s] rat: unknown option");
  EXPECT_EQ(LoadError("[s]\nrate = fast\n"), "toy.ini: [s] rate = 'fast': not a number");
  EXPECT_EQ(LoadError("[s]\nrate = 0.5x\n"), "toy.ini: [s] rate = '0.5x': not a number");
  EXPECT_EQ(LoadError("[s]\nrate = nan\n"), "toy.ini: [s] rate = 'nan': not a number");
  EXPECT_EQ(LoadError("[s]\ncount = 2.5\n"), "toy.ini: [s] count = '2.5': not a whole number");
  EXPECT_EQ(LoadError("[s]\non = yes\n"), "toy.ini: [s] on = 'yes': not true/false");
  EXPECT_EQ(LoadError("[s]\nmode = slow\n"), "toy.ini: [s] mode = 'slow': not fast or exact");
  EXPECT_EQ(LoadError("[s]\nrate = 1.5\n"), "toy.ini: [s] rate must be in (0, 1]");
  EXPECT_EQ(LoadError("[s]\nrate = 1\n"), "");
}

TEST(OptionTable, DumpReadsBackToTheSameValues) {
  Toy o;
  o.rate = 0.3;
  o.angle = 0.123456789;
  o.mode = Mode::kFast;
  std::ostringstream dump;
  ToyTable().Dump(dump, "s", o);
  EXPECT_TRUE(std::regex_search(dump.str(), std::regex("\\[s\\]\nrate +=  ?0\\.3 +; a rate\n")))
      << dump.str();
  Toy back;
  ToyTable().Load(mrpt::config::CConfigFileMemory(dump.str()), "s", "dump", back);
  EXPECT_EQ(back.rate, 0.3);
  EXPECT_NEAR(back.angle, 0.123456789, 1e-15);
  EXPECT_EQ(back.mode, Mode::kFast);
  EXPECT_EQ(back.added_later, o.added_later);
}

TEST(OptionTable, MapFileByKeyRoundTripsAndGivesMissingKeysTheirLegacyValue) {
  Toy o;
  o.rate = 0.25, o.count = 3, o.on = false, o.mode = Mode::kFast, o.added_later = 0.5;
  const Toy back = ReadBack([&](auto& out) { ToyTable().Write(out, o); });
  EXPECT_EQ(back.rate, 0.25);
  EXPECT_EQ(back.count, 3);
  EXPECT_FALSE(back.on);
  EXPECT_EQ(back.mode, Mode::kFast);
  EXPECT_EQ(back.added_later, 0.5);

  // A file written before `added_later` existed: two keys only.
  const Toy legacy = ReadBack([](auto& w) {
    w << uint32_t(2) << std::string("rate") << 0.5 << std::string("count") << 9.0;
  });
  EXPECT_EQ(legacy.rate, 0.5);
  EXPECT_EQ(legacy.count, 9);
  EXPECT_EQ(legacy.added_later, 0.0);
  EXPECT_TRUE(legacy.on);  // no legacy value: the default
}

TEST(OptionTable, MapFileValuesAreCheckedAsTheIniChecksThem) {
  for (const auto& [key, value] : std::vector<std::pair<std::string, double>>{{"count", 2.5},
                                                                              {"on", 2.0},
                                                                              {"mode", 5.0},
                                                                              {"rate", NAN},
                                                                              {"rate", 3.0},
                                                                              {"bogus", 1}}) {
    const std::string k = key;
    const double v = value;
    EXPECT_THROW(ReadBack([&](auto& w) { w << uint32_t(1) << k << v; }), std::runtime_error)
        << k << " = " << v;
  }
  EXPECT_THROW(ReadBack([](auto& w) { w << uint32_t(0xFFFFFFFF); }), std::runtime_error);
}

TEST(OptionTable, ReadsPositionalFilesWithFlagsAsBools) {
  mrpt::io::CMemoryStream buffer;
  auto w = mrpt::serialization::archiveFrom(buffer);
  w << 0.4 << false << 0.2;  // rate, on, angle (radians, as the field holds it)
  buffer.Seek(0);
  auto r = mrpt::serialization::archiveFrom(buffer);
  Toy o;
  ToyTable().ReadPositional(r, {"rate", "on", "angle_deg"}, o);
  EXPECT_EQ(o.rate, 0.4);
  EXPECT_FALSE(o.on);
  EXPECT_EQ(o.angle, 0.2);
  EXPECT_EQ(o.added_later, 0.0);  // legacy
  // A flag byte other than 0 or 1 (found by map_file_fuzzer: reading it as a bool was undefined).
  mrpt::io::CMemoryStream corrupt;
  auto c = mrpt::serialization::archiveFrom(corrupt);
  c << 0.4 << uint8_t(97) << 0.2;
  corrupt.Seek(0);
  auto cr = mrpt::serialization::archiveFrom(corrupt);
  try {
    ToyTable().ReadPositional(cr, {"rate", "on", "angle_deg"}, o);
    ADD_FAILURE() << "flag byte 97 was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("on: flag byte 97, not 0 or 1"), std::string::npos)
        << e.what();
  }
}

TEST(OptionTable, IncludeCarriesEntriesAndChecks) {
  struct Outer {
    Toy toy;
    double extra = 2.0;
  };
  OptionTable<Outer> t;
  t.Add(
       "extra", [](Outer & o) -> auto& { return o.extra; }, "")
      .Include(
          ToyTable(), [](Outer & o) -> auto& { return o.toy; });
  Outer o;
  t.Load(mrpt::config::CConfigFileMemory("[s]\nextra = 3\nrate = 0.1\n"), "s", "x", o);
  EXPECT_EQ(o.extra, 3.0);
  EXPECT_EQ(o.toy.rate, 0.1);
  EXPECT_THROW(t.Load(mrpt::config::CConfigFileMemory("[s]\nrate = 2\n"), "s", "x", o),
               std::runtime_error);
}

TEST(CheckInRange, NamesKeyRangeAndValueAndRefusesNaN) {
  try {
    CheckInRange(1e30, 0, 255, "initial_tau");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "initial_tau must be in [0, 255], got 1e+30");
  }
  EXPECT_THROW(CheckInRange(std::nan(""), 0, 1, "k"), std::invalid_argument);
  EXPECT_NO_THROW(CheckInRange(255, 0, 255, "k"));
}

}  // namespace
}  // namespace novelty::mrpt_plugins
