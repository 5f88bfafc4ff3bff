#include "mrpt_plugins/object_database_map_options.h"

#include "core/range_check.h"
#include "maps/objects/feature_extractor.h"

namespace novelty::mrpt_plugins {

ObjectDatabaseMapConfig::ObjectDatabaseMapConfig() {
  map.extractor = objects::FeatureExtractor::kSift;
  map.focus.morphology_size = 12;
  map.learn_unchanged_change = true;
  map.learn_only_nearer_features = true;
  map.nearer_is_surprising = true;
  map.learner.static_features_recognise = true;
  map.learner.verify_pose = true;
}

const OptionTable<ObjectDatabaseMapConfig>& ObjectDatabaseMapConfig::Table() {
  using C = ObjectDatabaseMapConfig;
  static const OptionTable<C> table = [] {
    OptionTable<C> t;
    t.AddChoice(
         "extractor", [](C & c) -> auto& { return c.map.extractor; },
         objects::FeatureExtractorNames(),
         "features: msurf (the thesis's SURF), sift or akaze (OpenCV, float KAZE descriptor)")
        .Add(
            "xi", [](C & c) -> auto& { return c.map.focus.xi; },
            "flood fill down to mean + xi * std of the surprise map (thesis 5.1: 2)")
        .Add(
            "morphology_size", [](C & c) -> auto& { return c.map.focus.morphology_size; },
            "px, side of the closing and opening element (not in the thesis; 0 = none)")
        .Add(
            "static_distance_px", [](C & c) -> auto& { return c.map.learner.static_distance_px; },
            "px, delta of eq. 5.1 (thesis: 2)")
        .Add(
            "match_ratio", [](C & c) -> auto& { return c.map.learner.match_ratio; },
            "nearest / second-nearest distance ratio for a match (thesis 5.1: 0.65)")
        .Add(
            "min_surprising_share",
            [](C & c) -> auto& { return c.map.learner.min_surprising_share; },
            "T of eq. 5.5: share of a descriptor's window on surprise to learn it (thesis: 0.8)")
        .Add(
            "forget_after_frames",
            [](C & c) -> auto& { return c.map.learner.forget_after_frames; },
            "frames without selected features that drop the active features (thesis: 10)")
        .Add(
            "relative_descriptor_change",
            [](C & c) -> auto& { return c.map.relative_descriptor_change; },
            "eq. 5.2's bound without a second camera, share of the descriptor's norm (chosen)")
        .Add(
            "extraction_margin", [](C & c) -> auto& { return c.map.extraction_margin; },
            "px, SIFT and AKAZE extract features from the focus box grown by this much, not "
            "the whole frame, without keypoints whose windows leave it (M-SURF: always the whole "
            "frame; -1: the whole frame with the box as mask, as maps saved before it)",
            1.0, -1.0)
        .Add(
            "min_relative_depth_change",
            [](C & c) -> auto& { return c.map.change.min_relative_difference; },
            "added/removed: a pixel's observed and expected depth differ by this share (chosen: 5 %)")
        .Add(
            "min_known_depth_share",
            [](C & c) -> auto& { return c.map.change.min_known_share; },
            "added/removed: share of the region with both depths needed to tell (chosen)")
        .Add(
            "min_changed_depth_share",
            [](C & c) -> auto& { return c.map.change.min_changed_share; },
            "added/removed: share of those pixels nearer/farther than expected (chosen: a quarter)")
        .Add(
            "learn_unknown_change", [](C & c) -> auto& { return c.map.learn_unknown_change; },
            "learn where depth cannot tell added from removed (true = the thesis, which always "
            "learnt)")
        .Add(
            "learn_unchanged_change",
            [](C & c) -> auto& { return c.map.learn_unchanged_change; },
            "learn where the region's depth is the expected one (true = the thesis, which had no "
            "depth test; false: light and noise teach nothing, and an object whose shape the "
            "appearance map took in already is learnt for forget_after_frames after it was added)")
        .Add(
            "nearer_is_surprising",
            [](C & c) -> auto& { return c.map.nearer_is_surprising; },
            "in an added region, pixels nearer than the farthest surface the map saw count as "
            "surprising in rho_S of eq. 5.5 (false = the thesis: surprise alone)")
        .Add(
            "learn_only_nearer_features",
            [](C & c) -> auto& { return c.map.learn_only_nearer_features; },
            "select only features nearer than the farthest surface the map saw at their pixel "
            "(false = the thesis; true: the shadow and the table beside a new object are not "
            "learnt; pair it with a larger morphology_size, and not for a standing camera: "
            "object_acquisition.h)")
        .Add(
            "grow_focus_over_nearer",
            [](C & c) -> auto& { return c.map.grow_focus_over_nearer; },
            "in an added region, the focus grows over the touching pixels nearer than the "
            "farthest surface the map saw as well as over surprise (false = the thesis: "
            "surprise alone; pair it with learn_only_nearer_features and nearer_is_surprising)")
        .Add(
            "depth_of_room_at_start", [](C & c) -> auto& { return c.depth_of_room_at_start; },
            "added/removed and nearer also compare with the depth the appearance map's views "
            "held at this map's first frame, so an object stays added after they take in its "
            "depth (false: the views now; let the map learn the room first, --objects-from)")
        .Add(
            "distinct_second_match",
            [](C & c) -> auto& { return c.map.learner.distinct_second_match; },
            "ratio test against the second candidate of another place, not a duplicate of the "
            "nearest's blob (false = the thesis)")
        .Add(
            "static_features_recognise",
            [](C & c) -> auto& { return c.map.learner.static_features_recognise; },
            "the object being learnt is recognised where the frame has static features, not "
            "only where the ratio test against its active features passes (false = the ratio "
            "test alone)")
        .Add(
            "verify_pose", [](C & c) -> auto& { return c.map.learner.verify_pose; },
            "recognise only if the matches' 3-D places agree on a pose (OpenGV RANSAC; false = "
            "the thesis)")
        .Add(
            "verify_reprojection_px",
            [](C & c) -> auto& { return c.map.learner.verification.reprojection_px; },
            "px, a match agrees with the pose within this (chosen: eq. 5.1's 2 px)")
        .Add(
            "verify_min_inliers",
            [](C & c) -> auto& { return c.map.learner.verification.min_inliers; },
            "matches that must agree (chosen: P3P's 3, one to choose, two against chance)")
        .Check([](const C& c) {
          const objects::ObjectAcquisitionOptions& o = c.map;
          CheckInRange(o.learner.verification.reprojection_px, 1e-3, 100, "verify_reprojection_px");
          CheckInRange(o.learner.verification.min_inliers, 4, 100000, "verify_min_inliers");
          CheckInRange(o.focus.xi, 0, 10, "xi");
          CheckInRange(o.focus.morphology_size, 0, 101, "morphology_size");
          CheckInRange(o.learner.static_distance_px, 1e-3, 100, "static_distance_px");
          CheckInRange(o.learner.match_ratio, 1e-3, 1, "match_ratio");
          CheckInRange(o.learner.min_surprising_share, 0, 1, "min_surprising_share");
          CheckInRange(o.learner.forget_after_frames, 1, 100000, "forget_after_frames");
          CheckInRange(o.relative_descriptor_change, 1e-6, 10, "relative_descriptor_change");
          CheckInRange(o.extraction_margin, -1, 100000, "extraction_margin");
          CheckInRange(o.change.min_relative_difference, 1e-3, 10, "min_relative_depth_change");
          CheckInRange(o.change.min_known_share, 0, 1, "min_known_depth_share");
          CheckInRange(o.change.min_changed_share, 1e-3, 1, "min_changed_depth_share");
        });
    return t;
  }();
  return table;
}

}  // namespace novelty::mrpt_plugins
