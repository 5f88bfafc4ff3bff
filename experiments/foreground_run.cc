#include "experiments/foreground_run.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <opencv2/bgsegm.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/background_segm.hpp>
#include <stdexcept>

#include "core/frame_stem.h"
#include "core/pinhole_camera.h"
#include "core/write_rgb_image.h"
#include "eval/cdnet_panel.h"
#include "maps/appearance/appearance_map.h"
#include "sensors/dataset/cdnet_folder.h"
#include "sensors/dataset/fixed_camera_folder.h"
#include "sensors/dataset/fixed_camera_frames.h"

namespace novelty::experiments {

namespace fs = std::filesystem;

namespace {

// One method: a frame (R G B) in, a mask (CV_8UC1, 255 foreground) out.
class ForegroundMethodRunner {
 public:
  virtual ~ForegroundMethodRunner() = default;
  virtual cv::Mat Apply(const cv::Mat& rgb) = 0;
};

class OpenCvSubtractor : public ForegroundMethodRunner {
 public:
  explicit OpenCvSubtractor(cv::Ptr<cv::BackgroundSubtractor> s) : s_(std::move(s)) {}
  cv::Mat Apply(const cv::Mat& rgb) override {
    cv::Mat bgr, mask;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    s_->apply(bgr, mask);
    return mask == 255;  // MOG2 and KNN mark shadows 127: not foreground
  }

 private:
  cv::Ptr<cv::BackgroundSubtractor> s_;
};

// The appearance map as a static camera: a nominal camera at the origin, a plane as depth.
class NoveltyMethod : public ForegroundMethodRunner {
 public:
  explicit NoveltyMethod(const ForegroundRunOptions& o) : labels_(o.labels) {
    appearance::AppearanceMapOptions m;
    m.predictive_novelty = true;
    if (o.hold_foreground) {
      m.hold_above_nats = o.labels.threshold_nats;
      m.max_hold_frames = o.max_hold_frames;
    }
    map_ = std::make_unique<appearance::AppearanceMap>(m);
  }
  cv::Mat Apply(const cv::Mat& rgb) override {
    if (depth_.size() != rgb.size()) {
      camera_ = sensors::NominalCamera(rgb.size());
      depth_ = cv::Mat(rgb.size(), CV_32FC1, cv::Scalar(1.0f));
    }
    const appearance::AppearanceProducts p =
        map_->Insert(rgb, depth_, camera_, Eigen::Isometry3d::Identity());
    // NaN (the first frame: no background yet) is background.
    return appearance::ForegroundLabels(p.predictive, rgb, p.expected_rgb, labels_) ==
           appearance::kForegroundLabel;
  }

 private:
  appearance::ForegroundLabelOptions labels_;
  std::unique_ptr<appearance::AppearanceMap> map_;
  core::PinholeCamera camera_;
  cv::Mat depth_;
};

std::unique_ptr<ForegroundMethodRunner> MakeMethod(const std::string& name,
                                                   const ForegroundRunOptions& o) {
  if (name == "novelty") return std::make_unique<NoveltyMethod>(o);
  if (name == "mog2")
    return std::make_unique<OpenCvSubtractor>(cv::createBackgroundSubtractorMOG2());
  if (name == "knn") return std::make_unique<OpenCvSubtractor>(cv::createBackgroundSubtractorKNN());
  if (name == "gsoc")
    return std::make_unique<OpenCvSubtractor>(cv::bgsegm::createBackgroundSubtractorGSOC());
  if (name == "cnt")
    return std::make_unique<OpenCvSubtractor>(cv::bgsegm::createBackgroundSubtractorCNT());
  throw std::invalid_argument("foreground method '" + name +
                              "': not one of novelty, mog2, knn, gsoc, cnt");
}

void AddFindings(ForegroundRunResult& r) {
  const auto find = [&](const std::string& name) -> const ForegroundMethod* {
    for (const ForegroundMethod& m : r.methods)
      if (m.name == name) return &m;
    return nullptr;
  };
  for (const ForegroundMethod& m : r.methods) {
    if (r.scored > 0)
      r.findings.Add(m.name + ": F-measure", eval::NumberText(m.scores.f_measure), "(reported)");
    r.findings.Add(m.name + ": ms per frame", eval::NumberText(m.ms_per_frame), "(reported)");
  }
  const ForegroundMethod *ours = find("novelty"), *knn = find("knn"), *mog2 = find("mog2");
  if (ours && knn && r.scored > 0)
    r.findings.Add("novelty F above KNN's", eval::NumberText(ours->scores.f_measure),
                   "> " + eval::NumberText(knn->scores.f_measure),
                   ours->scores.f_measure > knn->scores.f_measure);
  if (ours && mog2)
    r.findings.Add("novelty ms per frame no more than MOG2's", eval::NumberText(ours->ms_per_frame),
                   "<= " + eval::NumberText(mog2->ms_per_frame),
                   ours->ms_per_frame <= mog2->ms_per_frame);
  r.findings.Add("frames", std::to_string(r.frames));
  r.findings.Add("scored frames", std::to_string(r.scored));
}

void WriteScores(const ForegroundRunResult& r, const fs::path& out) {
  std::ofstream csv(out / "scores.csv");
  csv << "method,recall,precision,f_measure,pwc,fpr,shadow_fpr,ms_per_frame\n";
  const auto score = [&](double v) {  // empty where nothing was scored
    return r.scored > 0 && std::isfinite(v) ? std::to_string(v) : std::string();
  };
  for (const ForegroundMethod& m : r.methods)
    csv << m.name << ',' << score(m.scores.recall) << ',' << score(m.scores.precision) << ','
        << score(m.scores.f_measure) << ',' << score(m.scores.pwc) << ',' << score(m.scores.fpr)
        << ',' << score(m.scores.shadow_fpr) << ',' << m.ms_per_frame << '\n';
  if (!csv) throw std::runtime_error((out / "scores.csv").string() + ": cannot be written");
}

}  // namespace

ForegroundRunResult RunForeground(const ForegroundRunOptions& o, const std::string& out_dir) {
  if (!(o.labels.threshold_nats > 0)) throw std::invalid_argument("threshold_nats must be > 0");
  if (o.methods.empty()) throw std::invalid_argument("no foreground method to run");
  for (std::size_t k = 0; k < o.methods.size(); ++k)
    if (std::find(o.methods.begin(), o.methods.begin() + long(k), o.methods[k]) !=
        o.methods.begin() + long(k))
      throw std::invalid_argument("foreground method '" + o.methods[k] + "' given twice");
  sensors::FixedCameraFrames frames(o.folder, o.max_pixels);
  std::vector<std::unique_ptr<ForegroundMethodRunner>> methods;
  ForegroundRunResult r;
  fs::create_directories(out_dir);
  for (const std::string& name : o.methods) {
    methods.push_back(MakeMethod(name, o));
    r.methods.push_back({name, {}, {}, 0});
    if (o.write_masks) fs::create_directories(fs::path(out_dir) / name);
  }
  if (o.panel_every > 0) fs::create_directories(fs::path(out_dir) / "panels");
  const int n = o.max_frames > 0 && (frames.size() == 0 || o.max_frames < frames.size())
                    ? o.max_frames
                    : frames.size();  // 0: a video that does not say
  std::vector<double> seconds(methods.size(), 0.0);
  sensors::FixedCameraFrame frame;
  while ((o.max_frames <= 0 || r.frames < o.max_frames) && frames.Next(frame)) {
    const cv::Mat& rgb = frame.rgb;
    const int number = frame.number;
    const bool scored = frames.scored(number) && !frame.truth.empty();
    r.unscored_in_roi += frames.kind() == "CDnet folder" && frames.scored(number) && !scored;
    const cv::Mat truth = scored ? sensors::ReadCdnetTruth(frame.truth) : cv::Mat();
    r.scored += scored;
    std::vector<cv::Mat> masks;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const auto start = std::chrono::steady_clock::now();
      masks.push_back(methods[m]->Apply(rgb));
      seconds[m] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (scored) r.methods[m].counts += eval::CountCdnetFrame(masks[m], truth, frames.roi());
      if (o.write_masks)
        core::WriteImage(
            (fs::path(out_dir) / r.methods[m].name / ("bin" + core::FrameStem(number) + ".png"))
                .string(),
            masks[m]);
    }
    if (o.panel_every > 0 && r.frames % o.panel_every == 0)
      core::WriteRgbImage(
          (fs::path(out_dir) / "panels" / (core::FrameStem(number) + ".png")).string(),
          eval::CdnetPanel(rgb, truth, frames.roi(), masks, o.methods,
                           "frame " + std::to_string(number)));
    ++r.frames;
    if (o.progress) o.progress(r.frames, std::max(n, r.frames));
  }
  r.expected_frames = frames.size();
  // A container's count can be an estimate from the duration: one frame short is not a cut.
  r.cut_short = r.frames + 1 < r.expected_frames && (o.max_frames <= 0 || r.frames < o.max_frames);
  for (std::size_t m = 0; m < methods.size(); ++m) {
    r.methods[m].scores = eval::ScoreCdnet(r.methods[m].counts);
    r.methods[m].ms_per_frame = r.frames ? 1000 * seconds[m] / r.frames : 0;
  }
  AddFindings(r);
  WriteScores(r, out_dir);
  r.findings.WriteCsv((fs::path(out_dir) / "findings.csv").string());
  return r;
}

}  // namespace novelty::experiments
