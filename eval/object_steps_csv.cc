#include "eval/object_steps_csv.h"

#include <stdexcept>

namespace novelty::eval {

const char* ChangeKindName(objects::ChangeKind kind) {
  switch (kind) {
    case objects::ChangeKind::kAdded:
      return "added";
    case objects::ChangeKind::kRemoved:
      return "removed";
    case objects::ChangeKind::kUnchanged:
      return "unchanged";
    case objects::ChangeKind::kUnknown:
      break;
  }
  return "unknown";
}

const char* RecognisedName(objects::LearnerStep::Recognised r) {
  using R = objects::LearnerStep::Recognised;
  switch (r) {
    case R::kByDatabase:
      return "database";
    case R::kByActiveFeatures:
      return "active";
    case R::kNewObject:
      return "new";
    case R::kNothing:
      break;
  }
  return "nothing";
}

ObjectStepsCsv::ObjectStepsCsv(const std::string& path) : path_(path), out_(path) {
  out_ << "frame,box_x,box_y,box_width,box_height,change,observed_depth,expected_depth,extracted,"
          "not_nearer,reconstructed,static,learnt,recognised,object,database_features,matches\n";
  if (!out_) throw std::runtime_error(path + ": cannot write");
}

void ObjectStepsCsv::Add(int frame, const objects::AcquisitionStep& s, int database_features) {
  out_ << frame << ",";
  if (s.focus.box.empty())
    out_ << ",,,,";
  else
    out_ << s.focus.box.x << "," << s.focus.box.y << "," << s.focus.box.width << ","
         << s.focus.box.height << ",";
  out_ << ChangeKindName(s.change.kind) << ",";
  if (s.change.known_share > 0.0)
    out_ << s.change.observed_depth << "," << s.change.predicted_depth << ",";
  else
    out_ << ",,";
  out_ << s.extracted << "," << s.not_nearer << "," << s.reconstructed << ","
       << s.learner.static_features << "," << s.learner.learnt << ","
       << RecognisedName(s.learner.recognised) << "," << s.learner.object << ","
       << database_features << ",";
  for (std::size_t k = 0; k < s.learner.matches_per_object.size(); ++k)
    out_ << (k ? ";" : "") << s.learner.matches_per_object[k];
  out_ << "\n";
  if (!out_) throw std::runtime_error(path_ + ": cannot write");
}

}  // namespace novelty::eval
