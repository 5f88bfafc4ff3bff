#include "apps/shell/table_flags.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "apps/command_line.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"

namespace novelty::apps {
namespace {

using Config = mrpt_plugins::IlluminationInvariantMapConfig;

// The options after parsing `args` (without the program name).
Config Parse(std::vector<std::string> args) {
  CommandLine cmd("test", "0");
  TableFlags<Config> flags(cmd, {{"kappa", "kappa"},
                                 {"colour", "colour"},
                                 {"zernike_grid", "grid"},
                                 {"missing_texture", "missing-texture"}});
  args.insert(args.begin(), "program");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  cmd.Parse(int(argv.size()), argv.data());
  return flags.Values();
}

std::string UsageMessage(std::vector<std::string> args) {
  try {
    Parse(std::move(args));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(TableFlags, NothingGivenIsTheTablesDefaults) {
  const Config c = Parse({});
  const Config defaults;
  EXPECT_EQ(c.map.model.kappa, defaults.map.model.kappa);
  EXPECT_EQ(c.map.model.kappa, 0.5);  // eq. 6.18's Lambertian value, the map's default
  EXPECT_EQ(c.map.zernike.grid, defaults.map.zernike.grid);
  EXPECT_TRUE(c.map.model.missing_texture) << "the best measured setting";
}

// --options reads a file first (the thesis's settings), then flags and --set go on top; a
// default-on flag is turned off with --set.
TEST(TableFlags, AnOptionsFileComesFirstAndFlagsGoOnTop) {
  const std::string thesis =
      std::string(NOVELTY_SOURCE_DIR) + "/share/thesis/illumination_invariant.ini";
  const Config c = Parse({"--options", thesis, "--kappa", "0.2"});
  EXPECT_EQ(c.map.invariant.colour, illumination::InvariantImageOptions::Colour::kPerChannel);
  EXPECT_FALSE(c.map.model.missing_texture);
  EXPECT_EQ(c.map.model.kappa, 0.2);
  EXPECT_FALSE(Parse({"--set", "missing_texture=false"}).map.model.missing_texture);
  EXPECT_TRUE(Parse({"--options", thesis, "--missing-texture"}).map.model.missing_texture);
  EXPECT_THROW(Parse({"--options", "/nonexistent.ini"}), std::runtime_error);
}

// AnySet: whether the command line gave any of the table's options.
TEST(TableFlags, AnySetSaysWhetherAnOptionWasGiven) {
  const auto any = [](std::vector<std::string> args) {
    CommandLine cmd("test", "0");
    TableFlags<Config> flags(cmd, {{"kappa", "kappa"}, {"missing_texture", "missing-texture"}});
    TCLAP::ValueArg<int> other("", "other", "not an option", false, 0, "N", cmd);
    args.insert(args.begin(), "program");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    cmd.Parse(int(argv.size()), argv.data());
    return flags.AnySet();
  };
  EXPECT_FALSE(any({}));
  EXPECT_FALSE(any({"--other", "3"}));
  EXPECT_TRUE(any({"--kappa", "0.3"}));
  EXPECT_TRUE(any({"--missing-texture"}));
  EXPECT_TRUE(any({"--set", "kappa=0.3"}));
}

TEST(TableFlags, FlagsAndSetReachTheFieldsAsTheIniDoes) {
  const Config c =
      Parse({"--kappa", "0.2", "--colour", "luminance-chromaticity", "--grid", "64",
             "--missing-texture", "--set", "texture_block=5", "--set", "viewpoint_angle_deg=10"});
  EXPECT_EQ(c.map.model.kappa, 0.2);
  EXPECT_EQ(c.map.invariant.colour,
            illumination::InvariantImageOptions::Colour::kLuminanceChromaticity);
  EXPECT_EQ(c.map.zernike.grid, 64);
  EXPECT_TRUE(c.map.model.missing_texture);
  EXPECT_EQ(c.map.model.texture.block, 5);
  EXPECT_EQ(c.map.viewpoint_angle_deg, 10.0);
}

TEST(TableFlags, BadValuesAreUsageErrorsNamingTheFlag) {
  EXPECT_EQ(UsageMessage({"--kappa", "1"}), "--kappa must be in [0, 0.999], got 1");
  EXPECT_EQ(UsageMessage({"--kappa", "x"}), "--kappa x: not a number");
  EXPECT_EQ(UsageMessage({"--grid", "2.5"}).rfind("--grid 2.5: ", 0), 0u);
  EXPECT_EQ(UsageMessage({"--colour", "rainbow"}),
            "--colour rainbow: not per-channel or luminance-chromaticity");
  EXPECT_NE(UsageMessage({"--set", "kapa=0.5"}).find("has no option 'kapa'"), std::string::npos);
  EXPECT_NE(UsageMessage({"--set", "kappa"}).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(UsageMessage({"--set", "texture_block=8"}).find("texture_block: 8 is even"),
            std::string::npos);
  // The probe's case: both took effect in silence, the --set one winning whatever the order.
  EXPECT_NE(UsageMessage({"--kappa", "0.3", "--set", "kappa=0.9"}).find("given twice"),
            std::string::npos);
  EXPECT_NE(UsageMessage({"--set", "kappa=0.9", "--set", "kappa=0.3"}).find("given twice"),
            std::string::npos);
}

}  // namespace
}  // namespace novelty::apps
