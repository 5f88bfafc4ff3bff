#include "apps/shell/output_folder.h"

#include "apps/shell/program.h"

#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace novelty::apps {
namespace {

namespace fs = std::filesystem;

// The program named in `dir`'s marker ("" if there is none) and the entries it wrote there.
struct Marker {
  std::string program;
  std::vector<std::string> entries;
};

Marker ReadMarker(const fs::path& dir) {
  std::ifstream in(dir / OutputFolder::kMarker);
  Marker m;
  std::getline(in, m.program);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) m.entries.push_back(line);
  return m;
}

bool Empty(const fs::path& dir) {
  return fs::is_empty(dir);
}

// The path's parts, made absolute and normal (symbolic links resolved where it exists).
std::vector<std::string> Components(const fs::path& p) {
  std::error_code ec;
  fs::path full = fs::weakly_canonical(fs::absolute(p), ec);
  if (ec) full = fs::absolute(p).lexically_normal();
  std::vector<std::string> parts;
  for (const fs::path& part : full)
    if (!part.empty()) parts.push_back(part.string());
  return parts;
}

// True if `inner` is `outer` or lies inside it.
bool Within(const fs::path& inner, const fs::path& outer) {
  const std::vector<std::string> a = Components(inner), b = Components(outer);
  return a.size() >= b.size() && std::equal(b.begin(), b.end(), a.begin());
}

// May `dir` be replaced by `program`'s results?
// `whole`: the folder must hold only what the marker lists (an OUT.partial a killed run left
// holds more, and is removed).
void CheckReplaceable(const fs::path& dir, const std::string& program, const std::string& out,
                      bool whole) {
  if (!fs::exists(fs::symlink_status(dir))) return;
  if (!fs::is_directory(fs::symlink_status(dir)))
    throw std::runtime_error(dir.string() + ": exists and is not a folder; choose another --out");
  if (Empty(dir)) return;
  const Marker by = ReadMarker(dir);
  const std::string in = dir.string() == out ? "" : " (in " + dir.string() + ")";
  if (by.program != program)
    throw std::runtime_error(out + ": " +
                             (by.program.empty() ? "holds files that are not " + program +
                                                       "'s results"
                                                 : "holds " + by.program + "'s results") +
                             in + "; choose another --out");
  // Its own earlier results, but nothing the user (or another program) put there since.
  if (!whole) return;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name == OutputFolder::kMarker) continue;
    if (std::find(by.entries.begin(), by.entries.end(), name) == by.entries.end())
      throw std::runtime_error(out + ": holds '" + name + "', which " + program +
                               " did not write" + in + "; move it or choose another --out");
  }
}

}  // namespace

OutputFolder::OutputFolder(const std::string& program, const std::string& out,
                           const std::vector<std::string>& inputs)
    : program_(program), out_(out) {
  if (out.empty()) throw UsageError("no output folder given (an empty --out)");
  while (out_.size() > 1 && out_.back() == '/') out_.pop_back();
  partial_ = out_ + ".partial";
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    if (Within(input, out_))
      throw std::runtime_error(out_ + ": holds an input of the run (" + input +
                               "); choose another --out");
  }
  CheckReplaceable(out_, program_, out_, true);
  CheckReplaceable(partial_, program_, out_, false);
  fs::remove_all(partial_);
  std::error_code ec;
  fs::create_directories(partial_, ec);
  if (ec)
    throw std::runtime_error(partial_ + ": cannot create the output folder (" + ec.message() + ")");
  // Marked at once: a partial folder left by a killed run is this program's to remove.
  std::ofstream(fs::path(partial_) / kMarker) << program_ << "\n";
}

OutputFolder::~OutputFolder() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(partial_, ignored);
}

std::string OutputFolder::File(const std::string& name) const {
  return (fs::path(partial_) / name).string();
}

void OutputFolder::Commit() {
  if (committed_) return;
  {  // The marker lists what was written, so that a later run replaces only that.
    std::ofstream marker(fs::path(partial_) / kMarker);
    marker << program_ << "\n";
    for (const auto& entry : fs::directory_iterator(partial_))
      if (entry.path().filename() != kMarker) marker << entry.path().filename().string() << "\n";
    if (!marker) throw std::runtime_error(partial_ + ": cannot write " + kMarker);
  }
  std::error_code ec;
  std::string old;  // the earlier output moves to a new, unique name, then goes
  if (fs::exists(fs::symlink_status(out_))) {
    std::string name = out_ + ".old.XXXXXX";
    if (!mkdtemp(name.data()))
      throw std::runtime_error(out_ + ": cannot replace the earlier output (no folder beside it)");
    old = name;
    fs::rename(out_, old, ec);  // onto the empty folder mkdtemp made
    if (ec) {
      fs::remove(old);
      throw std::runtime_error(out_ + ": cannot replace the earlier output (" + ec.message() + ")");
    }
  }
  fs::rename(partial_, out_, ec);
  if (ec) {
    if (!old.empty()) fs::rename(old, out_);
    throw std::runtime_error(out_ + ": cannot publish the results from " + partial_ + " (" +
                             ec.message() + ")");
  }
  committed_ = true;
  if (!old.empty()) fs::remove_all(old, ec);
}

void CheckOutputFile(const std::string& flag, const std::string& path,
                     const std::vector<std::string>& inputs,
                     const std::function<bool(const std::string&)>& replaceable) {
  if (path.empty()) throw UsageError("no output file given (an empty " + flag + ")");
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    if (Within(path, input))
      throw std::runtime_error(
          flag + " " + path +
          (Components(path) == Components(input) ? " is the input " : " lies inside the input ") +
          input + ": it would be overwritten");
  }
  const fs::file_status status = fs::symlink_status(path);
  if (!fs::exists(status)) return;
  if (fs::is_directory(status)) throw std::runtime_error(flag + " " + path + ": is a folder");
  if (!replaceable(path))
    throw std::runtime_error(flag + " " + path +
                             ": exists and is not what this program writes; not replacing it");
}

std::function<bool(const std::string&)> HasExtension(const std::string& extension) {
  return [extension](const std::string& path) {
    return fs::path(path).extension().string() == extension;
  };
}

}  // namespace novelty::apps
