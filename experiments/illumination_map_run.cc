#include "experiments/illumination_map_run.h"

#include <mrpt/maps/CMultiMetricMap.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <regex>
#include <stdexcept>
#include <utility>

#include "core/false_color.h"
#include "core/write_rgb_image.h"
#include "eval/html_report.h"
#include "eval/roc.h"
#include "eval/roc_plot.h"
#include "eval/side_by_side.h"
#include "eval/skipped_frames.h"
#include "maps/illumination/illumination_map.h"
#include "maps/illumination/invariant_image.h"
#include "mrpt_plugins/c_illumination_invariant_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "mrpt_plugins/rawlog_map_player.h"
#include "sensors/dataset/fixed_camera_folder.h"
#include "sensors/rawlog/brief_message.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void Say(const IlluminationMapRunOptions& o, const std::string& line) {
  if (o.status) o.status(line);
}

// Says what a pass that gave no frame lacked.
std::string NoFrameHint(const std::string& poses) {
  return poses == "rawlog" ? " (--poses rawlog needs the pose observations novelty-poses writes; "
                             "a simulator's rawlog: --poses groundtruth --groundtruth DIR)"
                           : "";
}

struct Multimap {
  mrpt::maps::CMultiMetricMap maps;
  std::shared_ptr<mrpt_plugins::CIlluminationInvariantMap> map;
};

// The multimap of `ini`, or one default CIlluminationInvariantMap without.
void Open(Multimap& m, const std::string& ini) {
  if (ini.empty()) {
    m.map = std::make_shared<mrpt_plugins::CIlluminationInvariantMap>();
    m.maps.maps.push_back(m.map);
    return;
  }
  m.maps.setListOfMaps(mrpt_plugins::LoadMultiMapConfig(ini));
  m.map = m.maps.mapByClass<mrpt_plugins::CIlluminationInvariantMap>();
  if (!m.map) throw std::invalid_argument(ini + " declares no CIlluminationInvariantMap");
  if (m.maps.mapByClass<mrpt_plugins::CIlluminationInvariantMap>(1))
    throw std::invalid_argument(ini +
                                " declares more than one CIlluminationInvariantMap; one map "
                                "is saved");
}

// A pass's frames into the maps: a rawlog's, or a fixed camera's folder's images, each inserted
// with the robot at the origin; an image that cannot be used is skipped and counted.
class PassPlayer {
 public:
  PassPlayer(const RawlogPass& pass, const IlluminationMapRunOptions& o) {
    if (pass.folder) {
      folder_.emplace(pass.path, o.fixed_camera);
      return;
    }
    const mrpt_plugins::PoseSource source = mrpt_plugins::ParsePoseSource(o.poses);
    const bool truth_poses = source == mrpt_plugins::PoseSource::kGroundTruth;
    if (truth_poses && !o.truth)
      throw std::invalid_argument("--poses groundtruth needs --groundtruth");
    rawlog_ = std::make_unique<mrpt_plugins::RawlogMapPlayer>(
        pass.path, source,
        truth_poses ? o.truth->CameraPoses() : std::map<int, Eigen::Isometry3d>{});
    if (pass.last > 0) rawlog_->SetFrameRange(pass.first, pass.last);
  }
  bool Next(mrpt::maps::CMultiMetricMap& maps, int& frame) {
    if (rawlog_) return rawlog_->Next(maps, frame);
    while (next_ < folder_->size()) {
      const int k = next_++;
      mrpt::obs::CObservation3DRangeScan obs;
      try {
        obs = folder_->Observation(k);
      } catch (const std::runtime_error& e) {  // unreadable, another size
        skips_.push_back(sensors::BriefMessage(e));
        continue;
      }
      if (before_insert_) before_insert_(k + 1);  // the map's errors are not the image's
      try {
        if (maps.insertObservation(obs, mrpt::poses::CPose3D())) {
          frame = k + 1;
          return true;
        }
        skips_.push_back(folder_->name(k) + ": no map used it");
      } catch (const std::exception& e) {  // another size than the map's, ...
        skips_.push_back(folder_->name(k) + ": " + sensors::BriefMessage(e));
      }
    }
    return false;
  }
  /// Called with a frame's number just before it goes into the maps.
  void SetBeforeInsert(std::function<void(int)> hook) {
    if (rawlog_) rawlog_->SetBeforeInsert(hook);
    before_insert_ = std::move(hook);
  }
  int skipped() const { return int(skip_reasons().size()); }
  const std::vector<std::string>& skip_reasons() const {
    return rawlog_ ? rawlog_->skip_reasons() : skips_;
  }
  std::string stopped_by() const { return rawlog_ ? rawlog_->stopped_by() : std::string(); }
  /// Frames the pass holds (0: unknown).
  int length(const RawlogPass& pass) const {
    return folder_ ? folder_->size() : pass.last > 0 ? pass.last - pass.first + 1 : 0;
  }

 private:
  std::unique_ptr<mrpt_plugins::RawlogMapPlayer> rawlog_;
  std::optional<sensors::FixedCameraFolder> folder_;
  int next_ = 0;
  std::vector<std::string> skips_;
  std::function<void(int)> before_insert_;
};

// Reports the frames a player skipped (one line), an early end and a range cut short; returns
// whether the pass ended before what was asked.
bool ReportEnd(const PassPlayer& player, const RawlogPass& pass, int frames, int last,
               const IlluminationMapRunOptions& o) {
  if (player.skipped())
    Say(o, pass.spec + ": " +
               eval::SkippedFramesSummary(frames + player.skipped(), player.skip_reasons()));
  if (!player.stopped_by().empty()) Say(o, pass.spec + " ends early: " + player.stopped_by());
  const bool short_range = pass.last > 0 && last < pass.last;
  if (short_range)
    Say(o, pass.spec + ": frames " + std::to_string(pass.first) + "-" + std::to_string(pass.last) +
               " asked, the last one used is " + std::to_string(last));
  return short_range || !player.stopped_by().empty();
}

[[noreturn]] void NoFrame(const std::string& what, const RawlogPass& pass, const PassPlayer& player,
                          const std::string& poses) {
  const std::string why = !player.stopped_by().empty() ? " (" + player.stopped_by() + ")"
                          : player.skipped()           ? " (" + player.skip_reasons().front() + ")"
                          : pass.last > 0 ? " (no camera frame in " + std::to_string(pass.first) +
                                                "-" + std::to_string(pass.last) + ")"
                                          : " (no camera frame in it)";
  throw std::invalid_argument(what + " (" + pass.spec + "): no frame could be used" + why +
                              (pass.folder ? "" : NoFrameHint(poses)));
}

// Per frame, what the report plots and the ROC scores.
struct Judged {
  eval::PlotSeries coverage{"covered share", "#0072b2", {}, 1.0},
      auc{"pixel AUC", "#d55e00", {}, 1.0}, mean{"mean Δ", "#009e73", {}, 1.0},
      max{"largest Δ", "#cc79a7", {}, 1.0}, novel{"share above τ", "#e69f00", {}, 1.0};
  long novel_pixels = 0, covered_pixels = 0;  // over all frames, with a decision threshold
  std::vector<double> scores;  // Δ of the covered pixels of all frames, with ground truth
  std::vector<bool> positive;
  std::vector<std::pair<std::string, std::string>> panels;  // (path, caption)
};

// Pixel AUC of Δ against the truth's novelty mask over the covered pixels (NaN when the frame
// shows no novelty or no background); the pixels join the run's ROC.
double FrameAuc(const illumination::IlluminationMapResult& r, const cv::Mat& truth, Judged& j) {
  std::vector<double> scores;
  std::vector<bool> positive;
  for (int y = 0; y < truth.rows; ++y)
    for (int x = 0; x < truth.cols; ++x)
      if (r.viewpoint.covered.at<uchar>(y, x)) {
        scores.push_back(r.novelty.novelty.at<float>(y, x));
        positive.push_back(truth.at<uchar>(y, x) != 0);
      }
  j.scores.insert(j.scores.end(), scores.begin(), scores.end());
  j.positive.insert(j.positive.end(), positive.begin(), positive.end());
  const long n = long(std::count(positive.begin(), positive.end(), true));
  if (n == 0 || n == long(positive.size())) return NAN;
  return eval::ComputeRoc(scores, positive).auc;
}

// Δ's picture, and every `panels_every`-th frame a panel (camera, invariant image, i_Y, Δ).
void WritePictures(const mrpt_plugins::CIlluminationInvariantMap& map, int frame, int judged,
                   int panels_every, const fs::path& out, Judged& j) {
  const illumination::IlluminationMapResult& r = map.lastResult();
  // Δ on a fixed scale, so that frames compare: twice T_Y, where i_Y starts a region.
  const double scale = 2.0 * r.viewpoint.model.threshold;
  const cv::Mat delta = core::FalseColor(r.novelty.novelty, scale);
  core::WriteRgbImage((out / "novelty" / cv::format("%06d.png", frame)).string(), delta);
  if (panels_every == 0 || (judged - 1) % panels_every != 0) return;
  cv::Mat information = r.novelty.information_y.clone();
  information.setTo(0.0f, r.viewpoint.covered == 0);
  const std::string panel = cv::format("panels/%06d.png", frame);
  std::vector<cv::Mat> tiles = {
      map.lastFrame().rgb,
      illumination::LinearImage8(r.viewpoint.log_invariant, r.viewpoint.covered),
      core::FalseColor(information, scale), delta};
  std::vector<std::string> captions = {cv::format("frame %d", frame), "invariant image",
                                       "information i_Y", "novelty (6.3)"};
  if (!r.novel.empty()) {  // the decision: the camera image, red where Δ > τ
    cv::Mat decided = map.lastFrame().rgb.clone(), red(decided.size(), CV_8UC3, {255, 0, 0});
    cv::addWeighted(decided, 0.4, red, 0.6, 0.0, red);
    red.copyTo(decided, r.novel);
    tiles.push_back(decided);
    captions.push_back(cv::format("novel: %.1f %% above %.1f", 100 * r.novel_share,
                                  map.map().decision_threshold()));
  }
  core::WriteRgbImage((out / panel).string(), eval::SideBySide(tiles, int(tiles.size()), captions));
  j.panels.emplace_back(panel, cv::format("frame %d: %.0f %% covered, %d regions", frame,
                                          100 * r.coverage, r.novelty.region_count));
}

// One judged frame: its frames.csv row, the report's points, its pictures.
void RecordFrame(const mrpt_plugins::CIlluminationInvariantMap& map, int frame, int judged,
                 int panels_every, const IlluminationMapRunOptions& o, const fs::path& out,
                 std::ofstream& csv, Judged& j) {
  const illumination::IlluminationMapResult& r = map.lastResult();
  const bool covered = r.coverage > 0.0;
  double max_delta = 0.0, auc = NAN;
  if (covered) cv::minMaxLoc(r.novelty.novelty, nullptr, &max_delta);
  const double mean_delta = covered ? cv::mean(r.novelty.novelty, r.viewpoint.covered)[0] : 0.0;
  if (o.truth && covered) {
    const cv::Mat mask = o.truth->Novelty(frame);
    if (mask.size() == r.novelty.novelty.size()) auc = FrameAuc(r, mask, j);
  }
  j.coverage.points.emplace_back(frame, r.coverage);
  j.auc.points.emplace_back(frame, auc);
  j.mean.points.emplace_back(frame, covered ? mean_delta : NAN);
  j.max.points.emplace_back(frame, covered ? max_delta : NAN);
  j.novel.points.emplace_back(frame, r.novel_share);
  if (!r.novel.empty()) {
    j.novel_pixels += cv::countNonZero(r.novel);
    j.covered_pixels += cv::countNonZero(r.viewpoint.covered);
  }
  const auto blank_if_nan = [](double v) {
    return std::isnan(v) ? std::string() : eval::NumberText(v);
  };
  csv << frame << ',' << r.coverage << ',' << r.novelty.region_count << ','
      << r.novelty.matched_count << ',' << mean_delta << ',' << max_delta << ','
      << blank_if_nan(auc) << ',' << blank_if_nan(r.novel_share) << '\n';
  if (covered) WritePictures(map, frame, judged, panels_every, out, j);
}

// The decision threshold's findings: τ, the share of covered pixels above it (with nothing new
// in view, the false-alarm rate; its target the map's), and with ground truth its false-alarm
// rate and TPR over the pixels the truth labels.
void AddDecisionFindings(const illumination::IlluminationMap& map, const Judged& j,
                         JudgeIlluminationMapResult& r) {
  const double tau = map.decision_threshold(), target = map.options().threshold.false_alarm_rate;
  if (std::isnan(tau)) {
    r.findings.Add("decision threshold",
                   "none (the map has none: it needs min_lightings + 1 lightings and "
                   "threshold_viewpoints > 0; maps saved before format 2 have none)");
    return;
  }
  if (j.covered_pixels == 0) return;  // no frame covered: nothing was decided
  r.novel_share = double(j.novel_pixels) / double(j.covered_pixels);
  r.findings.Add("decision threshold τ (nats)", eval::NumberText(tau),
                 "learnt at " + eval::PercentText(target) + " false alarms");
  r.findings.Add("covered pixels above τ", eval::PercentText(r.novel_share),
                 "(with nothing new: ≈ " + eval::PercentText(target) + ")");
  r.summary += "; " + eval::PercentText(r.novel_share) +
               " of the covered pixels above τ = " + eval::NumberText(tau);
  const long positives = long(std::count(j.positive.begin(), j.positive.end(), true));
  const eval::RocPoint at = eval::OperatingPoint(j.scores, j.positive, tau);
  if (long(j.positive.size()) > positives) {
    r.false_alarm_rate = at.fpr;
    r.summary += " (false alarms " + eval::PercentText(r.false_alarm_rate) + ")";
    r.findings.Add("false-alarm rate at τ (ground truth)", eval::PercentText(r.false_alarm_rate),
                   "(reported; the map's target " + eval::PercentText(target) + ")");
  }
  if (positives > 0)
    r.findings.Add("TPR at τ (ground truth)", eval::PercentText(at.tpr), "(reported)");
}

void WriteReport(const std::string& title, const JudgeIlluminationMapResult& r,
                 const std::optional<eval::Roc>& roc, const Judged& j, const fs::path& out) {
  eval::HtmlReport report(title);
  report.Paragraph(r.summary);
  r.findings.AddTo(report);
  report.Paragraph(
      "frames.csv: per frame the share of pixels the map covers, the regions of i_Y > T_Y and how "
      "many a stored highlight or shadow shape explains, the mean and largest novelty Δ (nats, "
      "eq. 6.24), the share of covered pixels above the map's decision threshold τ (learnt from "
      "the training lightings: with nothing new in view it is the false-alarm rate) and, with "
      "--groundtruth, the pixel AUC of Δ against the novelty mask. Pictures: Δ and i_Y in false "
      "colour from 0 to 2·T_Y; the last tile of a panel is red where Δ > τ.");
  report.Heading("Per frame");
  report.Raw(
      eval::SvgLinePlot("Novelty Δ over the covered pixels", "frame", "Δ (nats)", {j.mean, j.max}));
  std::vector<eval::PlotSeries> shares = {j.coverage, j.novel};
  if (roc) shares.push_back(j.auc);
  report.Raw(eval::SvgLinePlot(
      roc ? "Coverage, share above τ and pixel AUC" : "Coverage and share above τ", "frame",
      "share", shares));
  if (roc) {
    report.Heading("ROC of Δ over the covered pixels of all frames");
    report.Raw(eval::SvgLinePlot("ROC", "FPR (%)", "TPR (%)",
                                 {eval::RocPlotSeries(*roc, "novelty Δ", "#0072b2")}));
    report.Raw(eval::SvgLinePlot("ROC at FPR up to 5 %", "FPR (%)", "TPR (%)",
                                 {eval::RocPlotSeries(*roc, "novelty Δ", "#0072b2", {0.05})}));
  }
  if (!j.panels.empty()) report.Heading("Panels");
  for (const auto& [path, caption] : j.panels) report.Image(path, caption);
  report.Save((out / "report.html").string());
}

}  // namespace

RawlogPass ParseRawlogPass(const std::string& spec, const sim::GroundTruthReader* truth) {
  static const std::regex range(R"((.*):(\d+)-(\d+))"), named(R"((.*):([A-Za-z_][\w-]*))");
  static const std::string each = ":each";
  std::smatch m;
  RawlogPass pass{spec, spec, 1, 0};
  if (fs::is_directory(spec)) {
    pass.folder = pass.each = true;
    return pass;
  }
  if (!fs::exists(spec) && spec.size() > each.size() &&
      spec.compare(spec.size() - each.size(), each.size(), each) == 0) {
    pass = ParseRawlogPass(spec.substr(0, spec.size() - each.size()), truth);
    if (pass.folder) throw std::invalid_argument(spec + ": ':each' is for a rawlog");
    pass.spec = spec;
    pass.each = true;
    return pass;
  }
  if (fs::is_regular_file(spec)) {
    pass.path = spec;
  } else if (std::regex_match(spec, m, range)) {
    pass.path = m[1].str();
    try {
      pass.first = std::stoi(m[2].str()), pass.last = std::stoi(m[3].str());
    } catch (const std::out_of_range&) {
      pass.first = pass.last = 0;
    }
    if (pass.first < 1 || pass.last < pass.first)
      throw std::invalid_argument(spec + ": frames " + m[2].str() + "-" + m[3].str() +
                                  " are no range (1-based, first <= last)");
  } else if (std::regex_match(spec, m, named)) {
    pass.path = m[1].str();
    if (!truth)
      throw std::invalid_argument(spec +
                                  ": a phase name needs --groundtruth (novelty-sim's folder)");
    const auto& phases = truth->Phases();
    const auto phase = std::find_if(phases.begin(), phases.end(),
                                    [&](const auto& p) { return p.name == m[2].str(); });
    if (phase == phases.end())
      throw std::invalid_argument(spec + ": no phase '" + m[2].str() + "' in " + truth->dir());
    pass.first = phase->first, pass.last = phase->last;
  }
  if (!fs::is_regular_file(pass.path))
    throw std::invalid_argument(spec + (fs::exists(pass.path)
                                            ? ": " + pass.path + " is not a file"
                                            : ": no such rawlog or folder (DIR, RAWLOG, "
                                              "RAWLOG:FIRST-LAST or RAWLOG:PHASE)"));
  return pass;
}

LearnIlluminationMapResult LearnIlluminationMap(const std::vector<std::string>& lightings,
                                                const std::string& ini, const std::string& map_out,
                                                const IlluminationMapRunOptions& o) {
  std::vector<RawlogPass> passes;
  std::size_t count = 0;  // lightings: a folder gives one per image
  for (const std::string& spec : lightings) {
    passes.push_back(ParseRawlogPass(spec, o.truth));
    // A rawlog pass of one lighting per frame whose length is unknown counts as two here: the
    // map refuses too few or too many lightings when they are played.
    const int length = PassPlayer(passes.back(), o).length(passes.back());
    count += !passes.back().each ? 1 : length > 0 ? std::size_t(length) : 2;
  }
  if (count > std::size_t(illumination::kMaxLightings))
    throw std::invalid_argument(std::to_string(count) + " lightings; a map holds at most " +
                                std::to_string(illumination::kMaxLightings) +
                                " (pick fewer with --include/--exclude)");
  if (count < 2)
    throw std::invalid_argument(
        "learning needs at least two lightings: two --lighting passes, or a folder of two images "
        "or more (the median of one lighting is not invariant)");
  Multimap m;
  Open(m, ini);
  const auto start = Clock::now();
  LearnIlluminationMapResult r;
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const RawlogPass& pass = passes[k];
    const std::string what =
        pass.each ? "lightings of " + pass.spec
                  : "lighting " + std::to_string(k + 1) + "/" + std::to_string(passes.size());
    PassPlayer player(pass, o);
    int frames = 0, last = 0;
    // A rawlog pass is one lighting; each image of a folder (or frame of an ":each" pass) is one
    // of its own, begun just before the frame goes in (a frame the maps refuse leaves it open for
    // the next).
    bool open = false;
    if (!pass.each) m.map->beginLighting();
    if (pass.each)
      player.SetBeforeInsert([&](int) {
        if (!open) m.map->beginLighting(), open = true;
      });
    for (int frame = 0; player.Next(m.maps, frame); last = frame) {
      open = false;
      ++frames;
      if (o.progress) o.progress(what, frames, player.length(pass));
    }
    if (frames == 0) NoFrame(what, pass, player, o.poses);
    Say(o, what + ": " + std::to_string(frames) + (pass.folder ? " images" : " frames") + " from " +
               pass.spec);
    ReportEnd(player, pass, frames, last, o);
    r.frames += frames;
    r.skipped += player.skipped();
  }
  Say(o, "invariant images at the viewpoints ...");
  m.map->finishAcquisition();
  m.map->SaveToFile(map_out);
  r.map_summary = m.map->asString();
  r.seconds = SecondsSince(start);
  return r;
}

JudgeIlluminationMapResult JudgeIlluminationMap(const std::string& map_in,
                                                const std::string& rawlog,
                                                const std::string& out_dir, int panels_every,
                                                const IlluminationMapRunOptions& o) {
  if (panels_every < 0) throw std::invalid_argument("--panels-every must be >= 0");
  const RawlogPass pass = ParseRawlogPass(rawlog, o.truth);
  Multimap m;
  Open(m, "");
  m.map->LoadFromFile(map_in);
  PassPlayer player(pass, o);
  const fs::path out(out_dir);
  fs::create_directories(out / "novelty");
  fs::create_directories(out / "panels");
  std::ofstream csv(out / "frames.csv");
  csv << "frame,coverage,regions,matched,mean_delta,max_delta,auc,novel_share\n";
  Judged j;
  JudgeIlluminationMapResult r;
  int last = 0;
  double seconds = 0.0;
  for (int frame = 0;; last = frame) {
    const auto t0 = Clock::now();
    if (!player.Next(m.maps, frame)) break;
    seconds += SecondsSince(t0);
    RecordFrame(*m.map, frame, ++r.frames, panels_every, o, out, csv, j);
    if (o.progress) o.progress("judging", r.frames, player.length(pass));
  }
  if (r.frames == 0) NoFrame("judging", pass, player, o.poses);
  r.skipped = player.skipped();
  r.ended_early = ReportEnd(player, pass, r.frames, last, o);
  const double ms = 1000 * seconds / r.frames;
  r.findings.Add("frames judged", std::to_string(r.frames));
  r.findings.Add("frames skipped", std::to_string(r.skipped));
  r.findings.Add("ms per frame", eval::NumberText(ms));
  r.summary = cv::format("%d frames judged, %d skipped, %.1f ms a frame", r.frames, r.skipped, ms);
  AddDecisionFindings(m.map->map(), j, r);
  const long n = long(std::count(j.positive.begin(), j.positive.end(), true));
  std::optional<eval::Roc> roc;
  if (n > 0 && n < long(j.positive.size())) {
    roc = eval::ComputeRoc(j.scores, j.positive);
    r.auc = roc->auc;
    r.findings.Add("pixel AUC of novelty over all frames", eval::NumberText(roc->auc),
                   "(reported)");
    r.findings.Add("TPR at FPR 1 %", eval::NumberText(roc->TprAtFpr(0.01)), "(reported)");
    r.summary += cv::format("; pixel AUC %.3f, TPR at FPR 1 %% %.1f %%", roc->auc,
                            100 * roc->TprAtFpr(0.01));
  }
  WriteReport("novelty-illumination-map: " + rawlog + " against " + map_in, r, roc, j, out);
  r.findings.WriteCsv((out / "findings.csv").string());
  return r;
}

}  // namespace novelty::experiments
