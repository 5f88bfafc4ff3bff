// The one output-folder policy of every program that writes a folder of results (panels, CSVs,
// report.html): the results are written into OUT.partial and renamed to OUT at the end, so a run
// that fails or is stopped leaves the earlier OUT whole and never a half-written one. OUT is
// refused if it holds one of the run's inputs (the rawlog, the ground truth, a learnt folder),
// or files that are not this program's earlier output (another program's results, a user's
// folder, a file put into an earlier output since): a marker file `.novelty-output` names the
// program that wrote a folder and what it wrote there.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace novelty::apps {

class OutputFolder {
 public:
  /// Checks OUT against `inputs` (files or folders; empty strings are ignored) and creates
  /// OUT.partial, removing one an earlier run of `program` left. Throws std::runtime_error
  /// naming OUT and the reason (UsageError for an empty OUT).
  OutputFolder(const std::string& program, const std::string& out,
               const std::vector<std::string>& inputs);
  /// Removes OUT.partial unless Commit() has published it.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// Where to write now (OUT.partial).
  const std::string& path() const { return partial_; }
  /// path()/name.
  std::string File(const std::string& name) const;
  /// Where the results will be once committed (OUT), for messages.
  const std::string& final_path() const { return out_; }

  /// Marks the folder as `program`'s and renames it to OUT, replacing an earlier output.
  void Commit();

  /// The marker's name.
  static constexpr const char* kMarker = ".novelty-output";

 private:
  std::string program_, out_, partial_;
  bool committed_ = false;
};

/// The same policy for a program's one output file (a rawlog, a map): refused when it is one of
/// `inputs` or lies inside an input's folder (the ground truth), or when it exists and
/// `replaceable` says it is not what the program writes (a user's file, another program's). The
/// file itself is written through core::TemporaryFile. Throws std::runtime_error naming `flag`.
void CheckOutputFile(const std::string& flag, const std::string& path,
                     const std::vector<std::string>& inputs,
                     const std::function<bool(const std::string&)>& replaceable);

/// For CheckOutputFile: a file whose name ends in `extension` (".rawlog").
std::function<bool(const std::string&)> HasExtension(const std::string& extension);

}  // namespace novelty::apps
