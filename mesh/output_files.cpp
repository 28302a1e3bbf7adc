// archgeo — atomic output files: each output is written to a temporary file
// beside its target (same directory, so same file system), named
// <stem>.tmp-<pid>-<n><extension>, and renamed into place by Commit();
// std::filesystem::rename replaces the target atomically.
#include "mesh/output_files.h"

#include <glog/logging.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <system_error>
#include <utility>

#include "mesh/input_error.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

// Whether `a` and `b` name the same file: equal once made absolute with
// symbolic links, "." and ".." resolved, or (both existing) the same inode.
bool SameFile(const std::string& a, const std::string& b) {
  std::error_code error_a, error_b, error;
  const fs::path canonical_a = fs::weakly_canonical(fs::absolute(a), error_a);
  const fs::path canonical_b = fs::weakly_canonical(fs::absolute(b), error_b);
  if (!error_a && !error_b && canonical_a == canonical_b) return true;
  return fs::equivalent(a, b, error);  // false (with `error` set) if either is missing
}

// Distinguishes the temporaries of all StagedOutputs in this process.
std::atomic<unsigned> next_temporary{0};

}  // namespace

StagedOutputs::StagedOutputs(std::vector<std::string> protected_paths)
    : protected_paths_(std::move(protected_paths)) {}

StagedOutputs::~StagedOutputs() {
  if (committed_) return;
  for (const auto& staged : staged_) {
    std::error_code ignored;  // a temporary never written does not exist
    fs::remove(staged.first, ignored);
  }
  // Directories Stage() created, deepest first; fs::remove leaves a
  // directory that is not empty (another process wrote there) in place.
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) {
    std::error_code ignored;
    fs::remove(*it, ignored);
  }
}

std::string StagedOutputs::Stage(const std::string& target) {
  CHECK(!committed_) << "Stage() after Commit()";
  for (const std::string& input : protected_paths_) {
    if (SameFile(target, input)) {
      throw InputError(target, 0, "", "refusing to overwrite the input file '" + input + "'");
    }
  }
  for (const auto& staged : staged_) {
    if (SameFile(target, staged.second)) {
      throw InputError(target, 0, "", "the same output file is given twice");
    }
  }
  std::error_code error;
  if (fs::is_directory(target, error))
    throw InputError(target, 0, "", "the output path is a directory");
  const fs::path directory = fs::path(target).parent_path();
  if (!directory.empty()) {
    std::vector<fs::path> missing;  // from the directory up to the first existing ancestor
    for (fs::path d = directory; !d.empty() && !fs::exists(d, error); d = d.parent_path()) {
      missing.push_back(d);
      if (d == d.parent_path()) break;
    }
    created_.insert(created_.end(), missing.rbegin(), missing.rend());
    fs::create_directories(directory, error);
    if (error) {
      throw InputError(
          target, 0, "",
          "cannot create the directory '" + directory.string() + "': " + error.message());
    }
  }
  // Keeps the extension: writers choose the format from it.
  const fs::path path(target);
  std::string temporary = (directory / path.stem()).string() + ".tmp-" + std::to_string(getpid()) +
                          "-" + std::to_string(next_temporary++) + path.extension().string();
  staged_.emplace_back(temporary, target);
  return temporary;
}

void StagedOutputs::Commit() {
  CHECK(!committed_) << "Commit() called twice";
  for (const auto& staged : staged_) {
    CHECK(fs::exists(staged.first)) << "staged output " << staged.second << " was never written";
  }
  for (const auto& [temporary, target] : staged_) {
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error)
      throw InputError(target, 0, "", "cannot move the output into place: " + error.message());
  }
  committed_ = true;
}

}  // namespace archgeo
