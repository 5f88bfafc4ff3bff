// novelty-info: what this NoveltyMaps build contains and which libraries it runs on.
//
// Links every external dependency and touches each at run time (an Embree device, an ODE world
// configuration, an OctoMap tree, a Ceres problem, MRPT's version), so a broken install shows up
// here first. Then it demonstrates the statistics core on one pixel (eq. 4.8-4.21).
// `--dump-options CLASS` prints instead a CMultiMetricMap .ini declaring one map of the class with
// every option's default and documentation (share/*.ini are that output).
#include <ceres/ceres.h>
#include <ceres/version.h>
#include <embree3/rtcore.h>
#include <mrpt/system/os.h>
#include <ode/ode.h>
#include <tclap/CmdLine.h>

#include <octomap/OcTree.h>
#include <Eigen/Core>
#include <cstdio>
#include <iostream>
#include <opencv2/core.hpp>
#include <random>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/shell/program.h"
#include "maps/stats/normal_gamma_kl.h"
#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/differencing_map_options.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"
#include "mrpt_plugins/object_database_map_options.h"

namespace {

std::string EmbreeVersion() {
  RTCDevice device = rtcNewDevice("threads=1");
  if (!device) return "unavailable (rtcNewDevice failed)";
  const long v = static_cast<long>(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION));
  rtcReleaseDevice(device);
  return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
         std::to_string(v % 100);
}

std::string OdeInfo() {
  dInitODE2(0);
  const bool dbl = dCheckConfiguration("ODE_double_precision") != 0;
  dCloseODE();
  return std::string(dbl ? "double" : "SINGLE (simulator needs double)") + " precision";
}

std::string OctomapInfo() {
  octomap::OcTree tree(0.05);
  tree.updateNode(octomap::point3d(0.1f, 0.2f, 0.3f), true);
  return std::string(NOVELTY_OCTOMAP_VERSION) + " (" + tree.getTreeType() + ", " +
         std::to_string(tree.size()) + " nodes after one insert)";
}

// Solves min (x - 3)² with Ceres: proves the solver links and runs.
struct ShiftResidual {
  template <class T>
  bool operator()(const T* x, T* r) const {
    r[0] = x[0] - T(3.0);
    return true;
  }
};
std::string CeresInfo() {
  double x = 0.0;
  ceres::Problem problem;
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ShiftResidual, 1, 1>(new ShiftResidual),
                           nullptr, &x);
  ceres::Solver::Options options;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  char buf[64];
  std::snprintf(buf, sizeof buf, " (test solve x=%.6f)", x);
  return std::string(CERES_VERSION_STRING) + buf;
}

// A pixel that has seen grey 100 ± 2 for 50 frames, then one observation: its surprise.
void SurpriseDemo() {
  using novelty::stats::NormalGammaT;
  const novelty::stats::ForgettingUpdateOptions o;
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(100.0, 2.0);
  NormalGammaT<double> p{1.0, 1.0, 0.0, 5.0};  // initial prior (4.3)
  for (int i = 0; i < 50; ++i) p = novelty::stats::UpdateWithForgetting(p, noise(rng), o);
  std::printf("  pixel learned: alpha=%.3f beta=%.2f tau=%.2f sigma=%.4f (beta/alpha=%.2f)\n",
              p.alpha, p.beta, p.tau, p.sigma, p.beta / p.alpha);
  for (double x : {101.0, 106.0, 130.0, 200.0}) {
    const auto post = novelty::stats::UpdateWithForgetting(p, x, o);
    std::printf("  observe %5.1f -> surprise KL = %.4f nats\n", x,
                novelty::stats::NormalGammaKL(post, p));
  }
}

int Run(int argc, char** argv) {
  std::vector<std::string> classes = {"CAppearanceMap", "CDifferencingMap", "CObjectDatabaseMap",
                                      "CIlluminationInvariantMap"};
  TCLAP::ValuesConstraint<std::string> allowed(classes);
  TCLAP::ValueArg<std::string> dump_options(
      "", "dump-options",
      "Print a CMultiMetricMap .ini with one map of the class and its options' defaults", false, "",
      &allowed);
  novelty::apps::CommandLine cmd(
      "Prints what this NoveltyMaps build contains and the libraries it uses.", NOVELTY_VERSION);
  cmd.add(dump_options);
  cmd.Parse(argc, argv);
  if (dump_options.isSet()) {
    const std::string& cls = dump_options.getValue();
    if (cls == "CAppearanceMap")
      novelty::mrpt_plugins::AppearanceMapConfig().dumpAsMultiMap(std::cout);
    else if (cls == "CDifferencingMap")
      novelty::mrpt_plugins::DifferencingMapConfig().dumpAsMultiMap(std::cout);
    else if (cls == "CObjectDatabaseMap")
      novelty::mrpt_plugins::ObjectDatabaseMapConfig().dumpAsMultiMap(std::cout);
    else
      novelty::mrpt_plugins::IlluminationInvariantMapConfig().dumpAsMultiMap(std::cout);
    return 0;
  }
  std::printf("NoveltyMaps %s\n\nLibraries:\n", NOVELTY_VERSION);
  std::printf("  MRPT     %s\n", mrpt::system::MRPT_getVersion().c_str());
  std::printf("  OpenCV   %s\n", cv::getVersionString().c_str());
  std::printf("  Eigen    %d.%d.%d\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
              EIGEN_MINOR_VERSION);
  std::printf("  Ceres    %s\n", CeresInfo().c_str());
  std::printf("  OctoMap  %s\n", OctomapInfo().c_str());
  std::printf("  OpenGV   %s\n", NOVELTY_OPENGV_VERSION);
  std::printf("  Embree   %s\n", EmbreeVersion().c_str());
  std::printf("  ODE      %s, %s\n", dGetConfiguration(), OdeInfo().c_str());
  std::printf(
      "\nBuilt components:\n"
      "  core             camera, rigid poses, Frame, image I/O, SIMD lanes and row helpers\n"
      "  maps/stats       normal-gamma updates (eq. 4.4-4.13), KL surprise (4.15-4.23),\n"
      "                   gamma ML fit (eq. 2.14-2.17), special functions\n"
      "  maps/color       YCbCr (ICT) and back, HSV\n"
      "  maps/views       view selection, depth-mesh warping, blending (ch. 3)\n"
      "  maps/appearance  appearance map and image differencing (ch. 4)\n"
      "  maps/objects     M-SURF, focus of attention, object learner and database (ch. 5)\n"
      "  maps/illumination invariant images, gamma models, Zernike shapes, novelty, NGC,\n"
      "                   SCT, the illumination-invariant map (ch. 6)\n"
      "  eval             AS/PAS, findings, PSNR, depth accuracy, panels, HTML report\n"
      "  sensors          RGB-D folders, rawlog frames, tracker, stereo, localization\n"
      "  sim              ODE world, Embree cameras, scenarios, rawlogs + ground truth\n"
      "  mrpt_plugins     CAppearanceMap, CDifferencingMap, CObjectDatabaseMap,\n"
      "                   CIlluminationInvariantMap, RawlogMapPlayer\n"
      "  apps             novelty (novelty COMMAND), novelty-sim, -synth, -run, -depth,\n"
      "                   -poses, -objects, -invariant, -illumination, -illumination-map,\n"
      "                   -soak, -info, over one program shell (apps/shell)\n");
  std::printf("\nStatistics core demo (one pixel, f=%.1f, xi=%.3g):\n", 0.8, 0.01);
  SurpriseDemo();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-info", [&] { return Run(argc, argv); });
}
