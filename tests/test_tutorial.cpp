// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// docs/tutorial.md runs as written: every ```sh block, in order, from the
// repository root (build/archgeo replaced by the binary under test), after
// out/tutorial/ is removed, so a step that needs a file no earlier step
// wrote fails. Each step must exit 0 (a solve may exit 4: a valid result
// written with a tolerance missed, which the tutorial says for step 4) and
// every out/tutorial/ file it names must exist afterwards.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/shell.h"

namespace ARCHGEO_UNITY_ID {

using archgeo::Outcome;
using archgeo::Shell;

namespace fs = std::filesystem;


std::vector<std::string> Steps(const std::string& markdown) {
  std::vector<std::string> steps;
  std::istringstream in(markdown);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line == "```sh") {
      inside = true;
    } else if (line == "```") {
      inside = false;
    } else if (inside && !line.empty()) {
      steps.push_back(line);
    }
  }
  return steps;
}

TEST(Tutorial, EveryStepRunsAsWritten) {
  const fs::path root = ARCHGEO_SOURCE_DIR;
  std::ifstream file(root / "docs/tutorial.md");
  std::stringstream text;
  text << file.rdbuf();
  const std::vector<std::string> steps = Steps(text.str());
  ASSERT_GE(steps.size(), 10u);
  fs::remove_all(root / "out/tutorial");
  const std::string prefix = "build/archgeo ";
  for (const std::string& step : steps) {
    ASSERT_EQ(step.rfind(prefix, 0), 0u) << "a step is one archgeo command: " << step;
    const std::string command =
        "cd '" + root.string() + "' && '" + ARCHGEO_BINARY + "' " + step.substr(prefix.size());
    const Outcome o = Shell(command);
    const bool solve = step.rfind(prefix + "solve ", 0) == 0;
    EXPECT_TRUE(o.code == 0 || (solve && o.code == 4))
        << step << "\nexit " << o.code << "\n" << o.output;
    // Every out/tutorial/ file the step names exists now.
    std::istringstream words(step);
    std::string word;
    while (words >> word) {
      const size_t at = word.find("out/tutorial/");
      if (at == std::string::npos) continue;
      EXPECT_TRUE(fs::exists(root / word.substr(at))) << step << ": no " << word.substr(at);
    }
  }
}

}  // namespace
