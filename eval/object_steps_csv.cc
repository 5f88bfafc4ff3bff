#include "eval/object_steps_csv.h"

#include <algorithm>
#include <sstream>
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

namespace {

// The columns every version of the file has had, in this order, from the start of its header.
constexpr const char* kHeaderStart = "frame,box_x,box_y,box_width,box_height,change";

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// The whole cell as an integer (std::stoi would take "12abc" as 12).
int Integer(const std::string& cell, const std::string& column) {
  std::size_t end = 0;
  int v = 0;
  try {
    v = std::stoi(cell, &end);
  } catch (const std::exception&) {  // no digits, or out of range: the message below says so
    end = 0;
  }
  if (cell.empty() || end != cell.size())
    throw std::invalid_argument(column + " \"" + cell + "\" is not an integer");
  return v;
}

}  // namespace

std::vector<ObjectStepRow> ReadObjectStepsCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(
        path +
        ": cannot open (novelty-run writes it when its --config declares a CObjectDatabaseMap)");
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.rfind(kHeaderStart, 0) != 0)
    throw std::runtime_error(path + ": not novelty-run's objects.csv (header " + line + ")");
  // Cells by the header's names, so that a column added to the file does not shift the others.
  const std::vector<std::string> header = SplitCsv(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
      throw std::runtime_error(path + ": no column " + name + " (header " + line + ")");
    return std::size_t(it - header.begin());
  };
  const std::size_t frame = column("frame"), x = column("box_x"), y = column("box_y"),
                    width = column("box_width"), height = column("box_height"),
                    change = column("change"), extracted = column("extracted"),
                    learnt = column("learnt"), object = column("object"),
                    database_features = column("database_features");
  std::vector<ObjectStepRow> rows;
  for (int n = 2; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a file saved with CRLF
    if (line.empty()) continue;
    const std::vector<std::string> c = SplitCsv(line);
    try {
      if (c.size() != header.size()) throw std::invalid_argument("not as many cells as the header");
      const auto integer = [&](std::size_t i) { return Integer(c[i], header[i]); };
      ObjectStepRow r;
      r.frame = integer(frame);
      const int box_cells = !c[x].empty() + !c[y].empty() + !c[width].empty() + !c[height].empty();
      if (box_cells != 0 && box_cells != 4) throw std::invalid_argument("a box with empty cells");
      r.has_box = box_cells == 4;
      if (r.has_box) r.box = cv::Rect(integer(x), integer(y), integer(width), integer(height));
      r.change = c[change];
      r.extracted = integer(extracted);
      r.learnt = integer(learnt);
      r.object = integer(object);
      r.database_features = integer(database_features);
      rows.push_back(r);
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ":" + std::to_string(n) + ": malformed row (" + e.what() +
                               ")");
    }
  }
  return rows;
}

ObjectStepsCsv::ObjectStepsCsv(const std::string& path) : path_(path), out_(path) {
  out_ << kHeaderStart
       << ",observed_depth,expected_depth,extracted,not_nearer,reconstructed,static,learnt,"
          "recognised,object,database_features,matches\n";
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
