// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The key tables of docs/keys.md come from the settings schema: each block
// between `<!-- keys: PROBLEM -->` and `<!-- /keys -->` must equal `archgeo
// spec PROBLEM --keys` (`common`: the keys every problem has), and every
// problem but `custom` (whose keys are its terms') must have one.
// `bash tools/update_keys.sh` regenerates them.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "problems/registry.h"
#include "problems/schema.h"

namespace archgeo {
namespace {

std::string Keys() {
  std::ifstream in(ARCHGEO_SOURCE_DIR "/docs/keys.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text between the markers of `name`, or "<missing>".
std::string Block(const std::string& text, const std::string& name) {
  const std::string open = "<!-- keys: " + name + " -->\n";
  const size_t start = text.find(open);
  if (start == std::string::npos) return "<missing>";
  const size_t end = text.find("<!-- /keys -->", start);
  if (end == std::string::npos) return "<missing>";
  return text.substr(start + open.size(), end - start - open.size());
}

TEST(Readme, KeyTablesAreTheSchemas) {
  const std::string keys = Keys();
  ASSERT_FALSE(keys.empty());
  const ProblemDecl* planar = FindProblem("planar_quads");
  ASSERT_NE(planar, nullptr);
  EXPECT_EQ(Block(keys, "common"), KeyTable(*planar, true))
      << "docs/keys.md is out of date: bash tools/update_keys.sh";
  for (const std::string& name : ProblemNames()) {
    if (name == "custom") continue;
    const ProblemDecl* problem = FindProblem(name);
    ASSERT_NE(problem, nullptr) << name;
    EXPECT_EQ(Block(keys, name), KeyTable(*problem, false))
        << "docs/keys.md: the keys of " << name << " are out of date or missing: "
        << "bash tools/update_keys.sh";
  }
}

}  // namespace
}  // namespace archgeo
