// objects.csv: per frame what the object database did (maps/objects/object_acquisition.h) —
// where it looked, added or removed, how many features it extracted, found static and learnt,
// and what it recognised with how many matches per object: the data of figs. 5.3 c and 5.5 a–c.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "maps/objects/object_acquisition.h"

namespace novelty::eval {

class ObjectStepsCsv {
 public:
  /// Creates `path` with its header line; throws std::runtime_error naming it if it cannot.
  explicit ObjectStepsCsv(const std::string& path);
  /// One row: frame, focus box (x, y, width, height; empty when none), change (added, removed,
  /// unchanged, unknown) with the observed and expected mean depth (m), features extracted, of
  /// them left out as not nearer (learn_only_nearer_features), of the rest reconstructed, static
  /// and learnt, what recognised (nothing, database, active, new) which object (−1 none),
  /// the database's size after the frame, and the matches per object ("3;0;12").
  void Add(int frame, const objects::AcquisitionStep& step, int database_features);

 private:
  std::string path_;
  std::ofstream out_;
};

/// What novelty-objects reads back of a row of objects.csv.
struct ObjectStepRow {
  int frame = 0;
  bool has_box = false;
  cv::Rect box;        ///< the focus box, if has_box
  std::string change;  ///< "added", "removed", "unchanged", "unknown"
  int extracted = 0, learnt = 0, object = -1;
  int database_features = 0;  ///< after the step
};

/// Reads an objects.csv that ObjectStepsCsv wrote, its cells by the header's names: a file of an
/// older version without the later columns (not_nearer) reads the same. Throws
/// std::runtime_error naming the file, and the line of a row that does not fit (other number of
/// cells than the header, a number that is not one, a box with some cells empty).
std::vector<ObjectStepRow> ReadObjectStepsCsv(const std::string& path);

/// "added", "removed", "unchanged", "unknown".
const char* ChangeKindName(objects::ChangeKind kind);
/// "nothing", "database", "active", "new".
const char* RecognisedName(objects::LearnerStep::Recognised r);

}  // namespace novelty::eval
