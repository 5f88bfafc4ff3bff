#include "experiments/object_experiment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/csv_field.h"
#include "core/frame_stem.h"
#include "core/nearest_pixel.h"
#include "eval/html_report.h"
#include "eval/matches_on_object.h"
#include "eval/object_steps_csv.h"
#include "eval/object_visibility.h"
#include "eval/roc.h"
#include "eval/roc_plot.h"
#include "maps/color/ycbcr.h"
#include "maps/objects/eigenbackground.h"
#include "maps/objects/feature_extractor.h"
#include "maps/objects/object_recognition.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sim/output/ground_truth_format.h"
#include "sim/output/ground_truth_reader.h"

namespace novelty::experiments {
namespace {

std::string Num(double v, const char* format = "%.3f") {
  char b[32];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

// The new object a learning frame shows (none if its ground-truth images are missing); a file
// that does not fit is an error naming the frame.
eval::NewObjectView NewObjectAt(const sim::GroundTruthReader& truth, int frame) {
  const cv::Mat ids = truth.Ids(frame), novelty = truth.Novelty(frame);
  if (ids.empty() || novelty.empty()) return {};
  try {
    return eval::NewObjectInView(ids, novelty, sim::ground_truth::kArmId,
                                 sim::ground_truth::kNoveltyAdded);
  } catch (const std::exception& e) {
    throw std::runtime_error(truth.dir() + ", frame " + std::to_string(frame) + ": " + e.what());
  }
}

// The q-quantile of `v`, the element at q·(n − 1) in sorted order (NaN if empty).
double Quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  const auto at = v.begin() + long(q * double(v.size() - 1));
  std::nth_element(v.begin(), at, v.end());
  return *at;
}

// Learning: the focus against the new object's true box (fig. 5.3), and each db object's name:
// the new object most often in view where it learnt.
struct LearningEvaluation {
  std::vector<std::string> names;  // per database object
  std::vector<int> name_ids;       // its id in the learning ground truth, −1 unknown
  std::vector<eval::PlotSeries> plots_x, plots_y, plots_features;
  double median_centre_error_px = NAN;
  double median_box_covered = NAN;  // share of the true box inside the focus box
  int compared_frames = 0, centre_inside = 0;
};

LearningEvaluation EvaluateLearning(const std::vector<eval::ObjectStepRow>& steps,
                                    const sim::GroundTruthReader& truth, int objects,
                                    const std::string& out) {
  LearningEvaluation e;
  std::vector<std::map<int, int>> votes(static_cast<std::size_t>(objects));
  eval::PlotSeries mx{"focus box", "#0072b2", {}, 1}, tx{"true box", "#000000", {}, 1};
  eval::PlotSeries my = mx, ty = tx, feats{"features in the box", "#d55e00", {}, 1};
  std::vector<double> errors, covered;
  std::ofstream csv(out + "/focus.csv");
  csv << "frame,box_cx,box_cy,true_cx,true_cy,true_object,arm_in_view,extracted,"
         "true_box_covered\n";
  for (const eval::ObjectStepRow& r : steps) {
    const eval::NewObjectView view = NewObjectAt(truth, r.frame);
    if (r.learnt > 0 && r.object >= 0 && r.object < objects && view.id >= 0)
      ++votes[std::size_t(r.object)][view.id];
    const double bx = r.has_box ? r.box.x + 0.5 * r.box.width : NAN;
    const double by = r.has_box ? r.box.y + 0.5 * r.box.height : NAN;
    // As the thesis: the truth where the object stands still (no arm in view).
    const bool still = view.id >= 0 && view.arm_pixels == 0;
    const double gx = still ? view.box.x + 0.5 * view.box.width : NAN;
    const double gy = still ? view.box.y + 0.5 * view.box.height : NAN;
    const double cover = still && r.has_box && !view.box.empty()
                             ? double((r.box & view.box).area()) / view.box.area()
                             : NAN;
    csv << r.frame << ',' << bx << ',' << by << ',' << gx << ',' << gy << ','
        << core::CsvField(view.id >= 0 ? truth.ObjectNames().count(view.id)
                                             ? truth.ObjectNames().at(view.id)
                                             : "?"
                                       : "")
        << ',' << (view.arm_pixels > 0) << ',' << r.extracted << ',' << cover << '\n';
    mx.points.emplace_back(r.frame, bx);
    my.points.emplace_back(r.frame, by);
    tx.points.emplace_back(r.frame, gx);
    ty.points.emplace_back(r.frame, gy);
    feats.points.emplace_back(r.frame, r.extracted);
    if (still && r.has_box) {
      ++e.compared_frames;
      errors.push_back(std::hypot(bx - gx, by - gy));
      covered.push_back(cover);
      e.centre_inside += view.box.contains(cv::Point(int(bx), int(by)));
    }
  }
  e.median_centre_error_px = Quantile(errors, 0.5);
  e.median_box_covered = Quantile(covered, 0.5);
  e.plots_x = {mx, tx};
  e.plots_y = {my, ty};
  e.plots_features = {feats};
  for (int k = 0; k < objects; ++k) {
    int best = -1, most = 0;
    for (const auto& [id, n] : votes[std::size_t(k)])
      if (n > most) best = id, most = n;
    e.name_ids.push_back(best);
    e.names.push_back(best >= 0 && truth.ObjectNames().count(best) ? truth.ObjectNames().at(best)
                                                                   : "object " + std::to_string(k));
  }
  return e;
}

// Per database feature, the frame it was learnt in (−1 unknown): the database appends each
// step's learnt features, so a step's are the rows [database_features − learnt,
// database_features) — also after a database loaded with --objects-in, whose own are unknown.
std::vector<int> FeatureFrames(const std::vector<eval::ObjectStepRow>& steps, int features) {
  std::vector<int> frames(std::size_t(features), -1);
  for (const eval::ObjectStepRow& r : steps)
    for (int h = r.database_features - r.learnt; h < r.database_features; ++h)
      if (h >= 0 && h < features) frames[std::size_t(h)] = r.frame;
  return frames;
}

// Whether feature h's learnt place lies on its object (−1: cannot tell): seen from the frame it
// was learnt in, it projects onto the ids of the object its class is named for, at the true
// depth (2 cm). Feature by feature, so that a class that took in several objects (one passed
// for another by eq. 5.4) counts those of the others as off.
int FeatureOnObject(const objects::FeatureDatabase& db, int h, int frame,
                    const LearningEvaluation& e, const sim::GroundTruthReader& truth,
                    const core::PinholeCamera& camera) {
  const int k = db.MostProbableObject(h);
  const Eigen::Vector3d& p = db.Position(h);
  if (!p.allFinite() || frame < 0 || e.name_ids[std::size_t(k)] < 0) return -1;
  const auto pose = truth.CameraPoses().find(frame);
  const cv::Mat ids = truth.Ids(frame), depth = truth.Depth(frame);
  if (pose == truth.CameraPoses().end() || ids.empty() || depth.empty()) return -1;
  const Eigen::Vector3d c = pose->second.inverse() * p;
  if (c.z() <= 0) return 0;
  const Eigen::Vector2d uv = camera.Project(c);
  if (!(uv.x() > -0.5 && uv.y() > -0.5 && uv.x() < ids.cols - 0.5 && uv.y() < ids.rows - 0.5) ||
      depth.size() != ids.size())
    return 0;
  const int u = int(std::lround(uv.x())), v = int(std::lround(uv.y()));
  return ids.at<int>(v, u) == e.name_ids[std::size_t(k)] &&
         std::abs(depth.at<float>(v, u) - c.z()) < 0.02;
}

// The recognition scores compared (each an ROC): N_k with the thesis's ratio test, and the
// matches of N_k that agree on a pose; the same with the ratio test's second candidate of
// another place (ratio_matches.h); and the features' nearest keypoints, without the ratio test,
// that agree on a pose (ObjectRecognitionOptions::verify_nearest).
constexpr int kScores = 6;
const char* const kScoreNames[kScores] = {
    "matches (thesis)",           "verified matches",
    "matches, distinct second",   "verified matches, distinct second",
    "verified nearest keypoints", "matches of consistent keypoints"};
const char* const kScoreColumns[kScores] = {"matches",          "verified_matches",
                                            "matches_distinct", "verified_matches_distinct",
                                            "verified_nearest", "matches_consistent"};
const char* const kScoreColours[kScores] = {"#0072b2", "#d55e00", "#009e73",
                                            "#cc79a7", "#e69f00", "#56b4e9"};

struct RecognitionRow {
  int frame, object, visible_pixels;
  int scores[kScores];
  eval::MatchesOnObject on_object;  // visible decisions only: eq. 5.4 among its own keypoints
};

// Keypoints this close to the object's pixels count as on it (matches_on_object.h): the
// smallest M-SURF blob's radius at 320 x 240 (size 10 s, s ≥ 1.2 → 6 px), and some.
constexpr int kOnObjectMarginPx = 10;

void DrawPanel(const core::Frame& f, const objects::FrameRecognition& r,
               const objects::FeatureDatabase& db, const std::vector<std::string>& names,
               const std::string& path) {
  cv::Mat bgr;
  cv::cvtColor(f.rgb, bgr, cv::COLOR_RGB2BGR);
  for (const objects::RatioMatch& m : r.matches) {  // fig. 5.4's cyan squares
    const cv::Point2f& p = r.keypoints[std::size_t(m.candidate)].pt;
    cv::rectangle(bgr, cv::Rect(int(p.x) - 3, int(p.y) - 3, 7, 7), cv::Scalar(255, 255, 0), 1);
  }
  int y = 14;
  for (int k = 0; k < db.objects(); ++k) {
    const objects::ObjectEvidence& e = r.per_object[std::size_t(k)];
    const std::string text = names[std::size_t(k)] + ": " + std::to_string(e.matches) + " (" +
                             std::to_string(e.pose.verified ? e.pose.inliers : 0) + " verified)";
    cv::putText(bgr, text, cv::Point(4, y), cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 3);
    cv::putText(bgr, text, cv::Point(4, y), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                cv::Scalar(255, 255, 255), 1);
    y += 14;
  }
  if (!cv::imwrite(path, bgr)) throw std::runtime_error(path + ": cannot write the panel");
}

// Recognition of `db`'s objects over the I3 rawlog: a row per frame and object, and the ROC of
// each score. With on_object_diagnostic, also MatchOnObject for each visible decision.
struct RecognitionRun {
  std::vector<RecognitionRow> rows;
  std::vector<eval::Roc> rocs;
  std::vector<int> panels;  // frames whose panel was written
  int frames = 0, skipped = 0;
  // Per ratio match, how its keypoint turned and changed metric size from the learnt one's
  // (keypoint_consistency.h): [1] for matches on the object of their feature's class (ground
  // truth), [0] elsewhere. What the tolerances of "matches of consistent keypoints" rest on.
  std::vector<double> turn_deg[2], size_ratio[2];
  // Ratio matches away from their class's object, by the ground-truth name of the pixel they land
  // on, and each name's pixels over the frames: whether repetitive clutter draws more false
  // matches than photo-printed clutter of its size.
  std::map<std::string, long> elsewhere_matches, pixels;
};

// "name matches (per 10⁶ of its pixels)" for each name with matches, most first.
std::string ElsewhereByName(const RecognitionRun& run) {
  std::vector<std::pair<long, std::string>> by_count;
  for (const auto& [name, n] : run.elsewhere_matches) by_count.emplace_back(n, name);
  std::sort(by_count.rbegin(), by_count.rend());
  std::string text;
  for (const auto& [n, name] : by_count) {
    const auto p = run.pixels.find(name);
    const long px = p == run.pixels.end() ? 0 : p->second;
    text += (text.empty() ? "" : ", ") + name + " " + std::to_string(n) + " (" +
            (px > 0 ? Num(1e6 * double(n) / double(px), "%.1f") : "-") + ")";
  }
  return text.empty() ? "-" : text;
}

// Median and 95th percentile of `v` ("-" if empty).
std::string MedianAnd95(const std::vector<double>& v, const char* format) {
  if (v.empty()) return "-";
  return Num(Quantile(v, 0.5), format) + " / " + Num(Quantile(v, 0.95), format) + " (" +
         std::to_string(v.size()) + ")";
}

RecognitionRun RunRecognition(const objects::FeatureDatabase& db,
                              const std::vector<std::string>& names, cv::Feature2D& extractor,
                              const objects::ObjectRecognitionOptions& thesis,
                              const ObjectExperimentOptions& a, const sim::GroundTruthReader& truth,
                              const std::string& csv_path, const std::string& panels,
                              bool on_object_diagnostic) {
  std::map<std::string, std::vector<int>> ids_by_name;  // names may repeat ("mug", "mug")
  for (const auto& [id, name] : truth.ObjectNames()) ids_by_name[name].push_back(id);
  objects::ObjectRecognitionOptions distinct = thesis;
  distinct.distinct_second = true;
  objects::ObjectRecognitionOptions nearest = thesis;
  nearest.verify_nearest = a.verify_nearest;
  RecognitionRun run;
  std::ofstream csv(csv_path);
  csv << "frame,object,name,visible_pixels,visible";
  for (const char* c : kScoreColumns) csv << ',' << c;
  csv << ",keypoints_on_object,matches_on_object,nearest_on_object\n";
  sensors::RawlogFrameReader reader(a.rawlog);
  const std::vector<objects::RatioMatch> none;  // the diagnostics are read for `db` only
  for (core::Frame frame; (a.frames == 0 || run.frames < a.frames) && reader.Next(frame);) {
    ++run.frames;
    cv::Mat grey;
    cv::cvtColor(frame.rgb, grey, cv::COLOR_RGB2GRAY);
    const objects::FrameFeatures features =
        objects::ExtractFrameFeatures(grey, extractor, frame.depth, frame.camera);
    const objects::FrameRecognition r = objects::MatchObjects(features, db, frame.camera, thesis);
    const objects::FrameRecognition rd =
        objects::MatchObjects(features, db, frame.camera, distinct);
    const objects::FrameRecognition rn =
        nearest.verify_nearest > 0 ? objects::MatchObjects(features, db, frame.camera, nearest)
                                   : objects::FrameRecognition{};
    const objects::FeatureDatabase::Recognition consistent =
        objects::KeepConsistentMatches(db, features, a.consistency, r.matches);
    const cv::Mat ids = truth.Ids(frame.index);
    if (ids.empty())
      throw std::runtime_error(a.truth + ": no ids image for frame " + std::to_string(frame.index));
    if (ids.size() != frame.rgb.size())
      throw std::runtime_error(a.truth + ": the ids image of frame " + std::to_string(frame.index) +
                               " is not the size of its RGB image");
    std::map<int, int> pixels_of_id;  // each ground-truth id's visible pixels, counted once
    for (const auto& [i, name] : truth.ObjectNames()) {
      pixels_of_id[i] = eval::VisiblePixels(ids, i);
      if (on_object_diagnostic) run.pixels[name] += pixels_of_id[i];
    }
    for (int k = 0; k < db.objects(); ++k) {
      int visible = 0;
      const auto id = ids_by_name.find(names[std::size_t(k)]);
      if (id != ids_by_name.end())
        for (int i : id->second) visible += pixels_of_id[i];
      const objects::ObjectEvidence& e = r.per_object[std::size_t(k)];
      const objects::ObjectEvidence& ed = rd.per_object[std::size_t(k)];
      for (const objects::RatioMatch& m : on_object_diagnostic ? r.matches : none) {
        if (db.MostProbableObject(m.reference) != k) continue;
        const std::size_t c = std::size_t(m.candidate);
        const cv::Point2f& p = features.keypoints[c].pt;
        const std::optional<cv::Point> pixel = core::NearestPixel(p, ids.size());
        const int at = pixel ? ids.at<int>(*pixel) : -1;
        const bool on =
            id != ids_by_name.end() && std::count(id->second.begin(), id->second.end(), at) > 0;
        const objects::LearntKeypoint& learnt = db.Keypoint(m.reference);
        const double turn = objects::TurnDeg(learnt, features.keypoints[c]),
                     ratio = objects::SizeRatio(learnt, features.metric_sizes.empty()
                                                            ? std::nan("")
                                                            : features.metric_sizes[c]);
        if (!on) {
          const auto name = truth.ObjectNames().find(at);
          ++run.elsewhere_matches[name == truth.ObjectNames().end() ? "unlabelled" : name->second];
        }
        if (std::isfinite(turn)) run.turn_deg[on].push_back(turn);
        if (std::isfinite(ratio)) run.size_ratio[on].push_back(ratio);
      }
      const int nearest_score =  // 0 when not computed
          rn.per_object.empty() || !rn.per_object[std::size_t(k)].pose.verified
              ? 0
              : rn.per_object[std::size_t(k)].pose.inliers;
      run.rows.push_back({frame.index,
                          k,
                          visible,
                          {e.matches, e.pose.verified ? e.pose.inliers : 0, ed.matches,
                           ed.pose.verified ? ed.pose.inliers : 0, nearest_score,
                           consistent.matches_per_object[std::size_t(k)]},
                          {}});
      RecognitionRow& row = run.rows.back();
      if (on_object_diagnostic && visible >= a.min_visible) {  // visible: the object has ids
        cv::Mat on_object(ids.size(), CV_8UC1, cv::Scalar(0));
        for (int i : id->second) on_object |= ids == i;
        row.on_object =
            eval::MatchOnObject(db, k, features, on_object, kOnObjectMarginPx, thesis.match_ratio);
      }
      csv << frame.index << ',' << k << ',' << core::CsvField(names[std::size_t(k)]) << ','
          << visible << ',' << (visible >= a.min_visible);
      for (int score : row.scores) csv << ',' << score;
      csv << ',' << row.on_object.keypoints << ',' << row.on_object.matches << ','
          << row.on_object.mean_nearest_distance << '\n';
    }
    if (!panels.empty() && a.panels_every > 0 && (run.frames - 1) % a.panels_every == 0) {
      DrawPanel(frame, r, db, names, panels + "/" + core::FrameStem(frame.index) + ".png");
      run.panels.push_back(frame.index);
    }
    if (run.frames % 25 == 0)
      if (a.status) a.status("recognition frame " + std::to_string(frame.index));
  }
  run.skipped = reader.skipped();
  if (!csv) throw std::runtime_error(csv_path + ": cannot write");
  std::vector<bool> visible;
  for (const RecognitionRow& r : run.rows) visible.push_back(r.visible_pixels >= a.min_visible);
  const long shown = std::count(visible.begin(), visible.end(), true);
  if (shown == 0 || shown == long(visible.size()))
    throw std::runtime_error(csv_path + ": in " + std::to_string(run.frames) +
                             " frames the learnt objects are " + (shown ? "always" : "never") +
                             " visible (>= " + std::to_string(a.min_visible) +
                             " px): a ROC needs frames with and without them");
  for (int i = 0; i < kScores; ++i) {
    std::vector<double> scores;
    for (const RecognitionRow& r : run.rows) scores.push_back(r.scores[i]);
    run.rocs.push_back(eval::ComputeRoc(scores, visible));
  }
  return run;
}

// The baseline of 5.2 ([WIS+10] with the eigenbackground of [ORP00]): in each I2 frame that
// shows a new object standing still, seven reference views of the appearance map learnt in I1,
// chosen by view selection (3.3.1) and warped to the frame's pose, give the eigenbackground; the
// largest foreground region is the object; features are extracted from the frame with the rest
// set to grey, and every one on the object is learnt — as the object the ground truth names
// ([WIS+10]'s robot knows which object it holds).
struct Baseline {
  objects::FeatureDatabase db;
  std::vector<std::string> names;
  int frames = 0;
  double mean_iou = 0.0;  // segmentation against the object's true pixels
};

Baseline LearnBaseline(const ObjectExperimentOptions& a, const sim::GroundTruthReader& truth,
                       cv::Feature2D& extractor) {
  mrpt_plugins::CAppearanceMap i1;
  i1.LoadFromFile(a.baseline_map);
  const appearance::ViewBasedMap& vm = i1.map().view_map();
  if (vm.store().size() < 2)
    throw std::runtime_error(a.baseline_map + ": the baseline needs a map of at least 2 views");
  Baseline b;
  std::map<int, int> class_of_id;
  sensors::RawlogFrameReader reader(a.learn_rawlog);
  for (core::Frame frame; reader.Next(frame);) {
    if (frame.index < a.baseline_from) continue;
    const auto pose = truth.CameraPoses().find(frame.index);
    if (pose == truth.CameraPoses().end()) continue;
    const eval::NewObjectView view = NewObjectAt(truth, frame.index);
    if (view.id < 0 || view.arm_pixels > 0) continue;
    const cv::Mat ids = truth.Ids(frame.index);
    if (ids.size() != frame.rgb.size())
      throw std::runtime_error(truth.dir() + ", frame " + std::to_string(frame.index) +
                               ": ids image of another size than the rawlog's frame");
    // The seven views closest in space (5.2; with views 1 cm apart, 3.3.1's ray-wise selection
    // gives one view for every ray).
    std::vector<int> nearest(vm.anchors().size());
    std::iota(nearest.begin(), nearest.end(), 0);
    const auto distance = [&](int j) {
      return (vm.anchors()[std::size_t(j)].translation() - pose->second.translation()).norm();
    };
    std::sort(nearest.begin(), nearest.end(),
              [&](int i, int j) { return distance(i) < distance(j); });
    nearest.resize(std::min<std::size_t>(nearest.size(), 7));
    std::vector<cv::Mat> backgrounds;
    for (int j : nearest) {
      appearance::ViewBasedMap one(vm.options());
      one.Restore({vm.store().view(j)}, {vm.anchors()[std::size_t(j)]});
      const appearance::Prediction p = one.Predict(frame.camera, pose->second, {{"tau", 3}});
      cv::Mat y;
      cv::extractChannel(p.value[0], y, 0);
      backgrounds.push_back(y.clone());
    }
    if (backgrounds.size() < 2) continue;
    cv::Mat y;
    cv::extractChannel(color::RgbToYCbCr(frame.rgb), y, 0);
    const cv::Mat object =
        objects::LargestRegion(objects::EigenbackgroundForeground(backgrounds, y));
    const cv::Mat truth_mask = ids == view.id;
    b.mean_iou += double(cv::countNonZero(object & truth_mask)) /
                  std::max(1, cv::countNonZero(object | truth_mask));
    ++b.frames;
    cv::Mat grey;
    cv::cvtColor(frame.rgb, grey, cv::COLOR_RGB2GRAY);
    grey.setTo(128, object == 0);
    const objects::FrameFeatures features = objects::ExtractFrameFeatures(grey, extractor);
    const std::vector<cv::KeyPoint>& keypoints = features.keypoints;
    const cv::Mat& descriptors = features.descriptors;
    cv::Mat learnt;
    std::vector<Eigen::Vector3d> places;
    std::vector<objects::LearntKeypoint> learnt_keypoints;
    const std::vector<double> sizes = objects::MetricSizes(keypoints, frame.depth, frame.camera);
    for (std::size_t i = 0; i < keypoints.size(); ++i) {
      const cv::Point p(int(keypoints[i].pt.x), int(keypoints[i].pt.y));
      if (!object.at<uchar>(p)) continue;
      learnt.push_back(descriptors.row(int(i)));
      const float z = frame.depth.at<float>(p);
      places.push_back(
          z > 0.0f ? Eigen::Vector3d(pose->second * frame.camera.Unproject(keypoints[i].pt.x,
                                                                           keypoints[i].pt.y, z))
                   : Eigen::Vector3d::Constant(std::nan("")));
      learnt_keypoints.push_back(objects::ToLearntKeypoint(keypoints[i], sizes[i]));
    }
    if (learnt.empty()) continue;
    if (!class_of_id.count(view.id)) {
      class_of_id[view.id] = b.db.AddObject();
      b.names.push_back(truth.ObjectNames().count(view.id) ? truth.ObjectNames().at(view.id) : "?");
    }
    b.db.AddFeatures(learnt, class_of_id[view.id], places, learnt_keypoints);
    if (b.frames % 25 == 0)
      if (a.status)
        a.status("baseline frame " + std::to_string(frame.index) + ", " +
                 std::to_string(b.db.features()) + " features");
  }
  if (b.frames > 0) b.mean_iou /= b.frames;
  return b;
}

}  // namespace

ObjectExperimentResult RunObjectExperiment(const ObjectExperimentOptions& a,
                                           const std::string& out) {
  if (a.frames < 0) throw std::invalid_argument("frames must be >= 0");
  if (a.panels_every < 0) throw std::invalid_argument("panels_every must be >= 0");
  if (a.verify_nearest < 0) throw std::invalid_argument("verify_nearest must be >= 0");
  if (a.min_visible < 1) throw std::invalid_argument("min_visible must be >= 1");
  mrpt_plugins::CObjectDatabaseMap map;
  map.LoadFromFile(a.learnt + "/map.object_database");
  const objects::FeatureDatabase& db = map.database();
  if (db.objects() == 0)
    throw std::runtime_error(a.learnt +
                             "/map.object_database: no object was learnt; nothing to recognise");
  const objects::ObjectAcquisitionOptions& options = map.config().map;
  const std::vector<eval::ObjectStepRow> steps =
      eval::ReadObjectStepsCsv(a.learnt + "/objects.csv");
  const sim::GroundTruthReader learn_truth(a.learn_truth), truth(a.truth);
  std::filesystem::create_directories(out + "/panels");

  // 1. Learning (figs. 5.3) and what was learnt.
  const LearningEvaluation learning = EvaluateLearning(steps, learn_truth, db.objects(), out);
  core::Frame frame;  // its camera: the experiment's runs share one
  if (!sensors::RawlogFrameReader(a.rawlog).Next(frame))
    throw std::runtime_error(a.rawlog + ": no RGB-D frame");
  int on_object = 0, judged = 0;
  {
    const std::vector<int> feature_frames = FeatureFrames(steps, db.features());
    std::ofstream csv(out + "/features.csv");
    csv << "feature,object,name,x,y,z,on_object\n";
    for (int h = 0; h < db.features(); ++h) {
      const int k = db.MostProbableObject(h);
      const int on = FeatureOnObject(db, h, feature_frames[std::size_t(h)], learning, learn_truth,
                                     frame.camera);
      const Eigen::Vector3d& p = db.Position(h);
      csv << h << ',' << k << ',' << core::CsvField(learning.names[std::size_t(k)]) << ',' << p.x()
          << ',' << p.y() << ',' << p.z() << ',' << on << '\n';
      if (on >= 0) ++judged, on_object += on;
    }
  }

  // 2. Recognition in the other room (fig. 5.5), and the baseline's.
  cv::Ptr<cv::Feature2D> extractor = objects::CreateFeatureExtractor(options.extractor);
  objects::ObjectRecognitionOptions thesis;
  thesis.match_ratio = options.learner.match_ratio;
  thesis.verify = true;  // N_k is the same; the pose adds the verified score
  thesis.verification = options.learner.verification;
  const RecognitionRun run = RunRecognition(db, learning.names, *extractor, thesis, a, truth,
                                            out + "/recognition.csv", out + "/panels", true);
  const std::vector<RecognitionRow>& rows = run.rows;
  const std::vector<eval::Roc>& rocs = run.rocs;
  const int n = run.frames;
  std::optional<Baseline> baseline;
  std::optional<RecognitionRun> baseline_run;
  if (!a.baseline_map.empty()) {
    baseline = LearnBaseline(a, learn_truth, *extractor);
    if (baseline->db.objects() == 0)
      throw std::runtime_error("the baseline learnt no object from " + a.learn_rawlog);
    // Only its matches are compared; its 26 868 features' nearest keypoints would take
    // RANSAC over some 18 000 pairs per object and frame (most of the run's time).
    ObjectExperimentOptions without_nearest = a;
    without_nearest.verify_nearest = 0;
    baseline_run =
        RunRecognition(baseline->db, baseline->names, *extractor, thesis, without_nearest, truth,
                       out + "/recognition_baseline.csv", "", false);
  }
  const eval::Roc& roc = rocs[0];

  // 3. Findings, report.
  eval::HtmlReport report("Object learning and recognition (thesis 5.2)");
  eval::FindingsTable findings;
  if (a.console) findings.EchoTo(a.console);
  const auto finding = [&](const std::string& what, const std::string& value,
                           const std::string& target, int holds) {  // holds -1: nothing to hold
    findings.Add(what, value, target, holds < 0 ? std::nullopt : std::optional<bool>(holds != 0));
  };
  if (a.console)
    std::fprintf(a.console,
                 "%d objects, %d features learnt; %d recognition frames, %d (frame, object) "
                 "decisions (%d visible)\n",
                 db.objects(), db.features(), n, roc.positives + roc.negatives, roc.positives);
  finding("objects learnt", std::to_string(db.objects()), "3 (thesis)", db.objects() == 3);
  finding("features in the database", std::to_string(db.features()), "88 (thesis)", -1);
  finding("learnt features on their object",
          judged ? eval::PercentText(double(on_object) / judged) +
                       (judged < db.features() ? " of " + std::to_string(judged) + " judged"
                                               : std::string())
                 : "-",
          "100 % (none from background)", judged ? on_object == judged : -1);
  finding("focus box centre inside the new object's true box",
          learning.compared_frames
              ? eval::PercentText(double(learning.centre_inside) / learning.compared_frames)
              : "-",
          "(reported)", -1);
  finding("median focus box centre error (px)", Num(learning.median_centre_error_px, "%.1f"),
          "(reported)", -1);
  finding("median share of the new object's true box inside the focus box",
          std::isnan(learning.median_box_covered) ? "-"
                                                  : eval::PercentText(learning.median_box_covered),
          "(reported)", -1);
  for (int i = 0; i < kScores; ++i) {
    const std::string what = kScoreNames[i];
    const eval::Roc& r = rocs[std::size_t(i)];
    finding("TPR at FPR <= 0.3 %, " + what, eval::PercentText(r.TprAtFpr(0.003)),
            ">= 90 % (thesis 81.5 %)", r.TprAtFpr(0.003) >= 0.9);
    finding("TPR at FPR <= 1 %, " + what, eval::PercentText(r.TprAtFpr(0.01)), "(reported)", -1);
    finding("TPR at FPR <= 5 %, " + what, eval::PercentText(r.TprAtFpr(0.05)), "(reported)", -1);
    finding("AUC, " + what, Num(r.auc), "(reported)", -1);
  }
  // What the consistent keypoints' tolerances rest on (keypoint_consistency.h).
  for (int on : {1, 0}) {
    const std::string where = on ? "ratio matches on their object" : "ratio matches elsewhere";
    finding(where + ": keypoint turn, median / 95th percentile (deg; matches)",
            MedianAnd95(run.turn_deg[on], "%.1f"), "(diagnostic)", -1);
    finding(where + ": metric size ratio, median / 95th percentile (matches)",
            MedianAnd95(run.size_ratio[on], "%.2f"), "(diagnostic)", -1);
  }
  finding(
      "ratio matches elsewhere, by the ground truth's name where they land (matches; per "
      "million of its pixels)",
      ElsewhereByName(run), "(diagnostic)", -1);
  // Which objects the operating point finds: recall per object at the threshold of eq. 5.4's
  // matches that keeps FPR ≤ 0.3 %, and the false positives each object adds there.
  const double threshold = roc.ThresholdAtFpr(0.003);
  for (int k = 0; k < db.objects(); ++k) {
    int shown = 0, found = 0, false_positives = 0;
    for (const RecognitionRow& r : run.rows)
      if (r.object == k) {
        const bool is_visible = r.visible_pixels >= a.min_visible,
                   passes = r.scores[0] >= threshold;
        shown += is_visible;
        found += is_visible && passes;
        false_positives += !is_visible && passes;
      }
    finding(
        "TPR of " + learning.names[std::size_t(k)] + " at FPR <= 0.3 % (" +
            (std::isinf(threshold) ? std::string("no threshold")
                                   : ">= " + Num(threshold, "%.0f") + " matches") +
            ")",
        (shown ? eval::PercentText(double(found) / shown) + " of " + std::to_string(shown) : "-") +
            " (" + std::to_string(false_positives) + " false positives)",
        "(reported)", -1);
  }
  // Where the misses come from: the same matching among only the object's own keypoints.
  for (int k = 0; k < db.objects(); ++k) {
    int shown = 0, in_frame = 0, on_own = 0, distances = 0;
    double distance = 0.0;
    for (const RecognitionRow& r : run.rows)
      if (r.object == k && r.visible_pixels >= a.min_visible) {
        ++shown;
        in_frame += r.scores[0] >= 1;
        on_own += r.on_object.matches >= 1;
        if (std::isfinite(r.on_object.mean_nearest_distance))
          distance += r.on_object.mean_nearest_distance, ++distances;
      }
    if (shown == 0) continue;
    finding(learning.names[std::size_t(k)] +
                ": visible decisions with a match among its own keypoints (ground truth; in "
                "the whole frame)",
            eval::PercentText(double(on_own) / shown) + " (" +
                eval::PercentText(double(in_frame) / shown) + ")",
            "(diagnostic)", -1);
    finding(learning.names[std::size_t(k)] +
                ": mean distance of a learnt feature to its nearest keypoint on the object",
            distances ? Num(distance / distances) : "-", "(diagnostic)", -1);
  }
  if (baseline) {
    const eval::Roc& b = baseline_run->rocs[0];
    finding("baseline: features in the database", std::to_string(baseline->db.features()),
            "5531 (thesis)", -1);
    finding("baseline: segmentation IoU with the object, mean over " +
                std::to_string(baseline->frames) + " frames",
            Num(baseline->mean_iou), "(reported)", -1);
    finding("baseline: TPR at FPR <= 0.3 %", eval::PercentText(b.TprAtFpr(0.003)), "(reported)",
            -1);
    finding("baseline: TPR at FPR <= 1 %", eval::PercentText(b.TprAtFpr(0.01)), "(reported)", -1);
    finding("baseline: TPR at FPR <= 5 %", eval::PercentText(b.TprAtFpr(0.05)),
            "(thesis: 81.5 % at 7.2 %)", -1);
    finding("baseline: AUC", Num(b.auc), "(reported)", -1);
    finding("baseline: TPR at FPR <= 0.3 %, " + std::string(kScoreNames[kScores - 1]),
            eval::PercentText(baseline_run->rocs[kScores - 1].TprAtFpr(0.003)), "(reported)", -1);
    // The thesis's claim: the surprise-driven database ahead at every FPR up to 5 % — with the
    // thesis's score, and with both databases' matches checked against their learnt keypoints.
    for (int i : {0, kScores - 1}) {
      const eval::Roc& ours = rocs[std::size_t(i)];
      const eval::Roc& theirs = baseline_run->rocs[std::size_t(i)];
      bool never_behind = true, ever_ahead = false;
      for (int step = 1; step <= 50; ++step) {
        const double fpr = 0.001 * step;
        never_behind = never_behind && ours.TprAtFpr(fpr) >= theirs.TprAtFpr(fpr);
        ever_ahead = ever_ahead || ours.TprAtFpr(fpr) > theirs.TprAtFpr(fpr);
      }
      const bool ahead = never_behind && ever_ahead;
      finding(
          std::string("surprise-driven TPR never below the baseline's at FPR <= 5 % (0.1 % steps), "
                      "above somewhere") +
              (i == 0 ? "" : ", " + std::string(kScoreNames[i])),
          ahead ? "yes" : "no", i == 0 ? "yes (thesis)" : "(reported)", i == 0 ? ahead : -1);
    }
  }
  findings.WriteCsv(out + "/findings.csv");

  report.Heading("Findings");
  findings.AddTo(report);
  report.Paragraph("Learnt objects: " + [&] {
    std::string s;
    for (int k = 0; k < db.objects(); ++k) {
      int count = 0;
      for (int h = 0; h < db.features(); ++h) count += db.MostProbableObject(h) == k;
      s += (k ? ", " : "") + learning.names[std::size_t(k)] + " (" + std::to_string(count) +
           " features)";
    }
    return s;
  }());
  report.Heading("Learning: focus of attention (fig. 5.3)");
  report.Raw(eval::SvgLinePlot("Focus box centre x", "frame", "x (px)", learning.plots_x));
  report.Raw(eval::SvgLinePlot("Focus box centre y", "frame", "y (px)", learning.plots_y));
  report.Raw(eval::SvgLinePlot("Features selected in the box", "frame", "features",
                               learning.plots_features));
  report.Heading("Recognition in another room (fig. 5.5)");
  std::vector<eval::PlotSeries> per_object, shown;
  const char* colours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9"};
  for (int k = 0; k < db.objects(); ++k) {
    eval::PlotSeries m{learning.names[std::size_t(k)], colours[k % 6], {}, 1};
    eval::PlotSeries v{learning.names[std::size_t(k)], colours[k % 6], {}, 1};
    for (const RecognitionRow& r : rows)
      if (r.object == k) {
        m.points.emplace_back(r.frame, r.scores[0]);
        v.points.emplace_back(r.frame, r.visible_pixels >= a.min_visible ? k + 1 : NAN);
      }
    per_object.push_back(m);
    shown.push_back(v);
  }
  report.Raw(eval::SvgLinePlot("Matches per frame per object", "frame", "matches", per_object));
  report.Raw(
      eval::SvgLinePlot("Visible (ground truth), one line per object", "frame", "object", shown));
  std::vector<eval::PlotSeries> curves, zoom;
  const auto add_curve = [&](const eval::Roc& curve, const std::string& name,
                             const std::string& colour) {
    curves.push_back(eval::RocPlotSeries(curve, name, colour));
    zoom.push_back(eval::RocPlotSeries(curve, name, colour, {0.05}));
  };
  for (int i = 0; i < kScores; ++i)
    add_curve(rocs[std::size_t(i)], kScoreNames[i], kScoreColours[i]);
  if (baseline_run) add_curve(baseline_run->rocs[0], "baseline (eigenbackground)", "#000000");
  report.Raw(eval::SvgLinePlot("ROC over (frame, object) decisions, sweeping the matches required",
                               "FPR (%)", "TPR (%)", curves));
  report.Raw(eval::SvgLinePlot("ROC up to FPR 5 %", "FPR (%)", "TPR (%)", zoom));
  if (a.panels_every > 0) {
    report.Heading("Panels (matches in cyan, as fig. 5.4)");
    for (int f : run.panels)
      report.Image("panels/" + core::FrameStem(f) + ".png", "frame " + std::to_string(f));
  }
  report.Save(out + "/report.html");
  ObjectExperimentResult result;
  result.findings = findings;
  result.objects = db.objects();
  result.features = db.features();
  result.recognition_frames = run.frames;
  result.skipped = run.skipped;
  return result;
}

}  // namespace novelty::experiments
