// objects.csv: per frame what the object database did (maps/objects/object_acquisition.h) —
// where it looked, added or removed, how many features it extracted, found static and learnt,
// and what it recognised with how many matches per object: the data of figs. 5.3 c and 5.5 a–c.
#pragma once

#include <fstream>
#include <string>

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

/// "added", "removed", "unchanged", "unknown".
const char* ChangeKindName(objects::ChangeKind kind);
/// "nothing", "database", "active", "new".
const char* RecognisedName(objects::LearnerStep::Recognised r);

}  // namespace novelty::eval
