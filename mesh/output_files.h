// archgeo — atomic, all-or-nothing output files.
#pragma once

#include <string>
#include <vector>

namespace archgeo {

// Stages output files: Stage(target) returns a temporary path beside the
// target (creating the target's directory if needed); Commit() renames every
// staged file into place. If Commit() is never reached (an error, an
// exception) the destructor removes the temporaries and the directories
// Stage() created (if still empty), so a failed run leaves no partial output. Stage() throws InputError if the target is one of the
// `protected_paths` (inputs are never overwritten) or its directory cannot
// be created.
class StagedOutputs {
 public:
  explicit StagedOutputs(std::vector<std::string> protected_paths = {});
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  std::string Stage(const std::string& target);
  void Commit();

 private:
  std::vector<std::string> protected_paths_;
  std::vector<std::pair<std::string, std::string>> staged_;  // (temporary, target)
  std::vector<std::string> created_;  // directories created by Stage(), outermost first
  bool committed_ = false;
};

}  // namespace archgeo
