// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The documentation against the code:
//  - the key tables of docs/keys.md come from the settings schema: each block
//    between `<!-- keys: PROBLEM -->` and `<!-- /keys -->` must equal
//    `archgeo spec PROBLEM --keys` (`common`: the keys every problem has), and
//    every problem but `custom` (whose keys are its terms') must have one
//    (`bash tools/update_keys.sh` regenerates them);
//  - README.md's problem table (the table headed `| problem |`) has a row
//    `| \`NAME\` |` for every problem of the registry, and names every
//    examples/*.yaml of the tree;
//  - every `examples/...` path named in README.md or docs/**/*.md exists.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "problems/declarations/registry.h"
#include "problems/spec/schema.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

const fs::path kSource = ARCHGEO_SOURCE_DIR;

std::string Read(const fs::path& path) {
  std::ifstream in(path);
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

// The lines of README.md's problem table after its header: the first
// Markdown table whose header line starts with "| problem |".
std::vector<std::string> ProblemTable(const std::string& readme) {
  std::istringstream in(readme);
  std::vector<std::string> rows;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside) {
      inside = line.rfind("| problem |", 0) == 0;
      continue;
    }
    if (line.empty() || line[0] != '|') break;
    rows.push_back(line);
  }
  return rows;
}

// Every `examples/...` path in `text` (not part of a longer path), without a
// sentence's full stop.
std::vector<std::string> ExamplePaths(const std::string& text) {
  static const std::regex kPath(R"((^|[^A-Za-z0-9_./-])(examples/[A-Za-z0-9_./-]*))");
  std::vector<std::string> paths;
  for (std::sregex_iterator it(text.begin(), text.end(), kPath), end; it != end; ++it) {
    std::string path = (*it)[2];
    while (path.back() == '.') path.pop_back();
    paths.push_back(path);
  }
  return paths;
}

TEST(Readme, KeyTablesAreTheSchemas) {
  const std::string keys = Read(kSource / "docs/keys.md");
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

TEST(Readme, EveryProblemHasARowInTheProblemTable) {
  const std::vector<std::string> rows = ProblemTable(Read(kSource / "README.md"));
  ASSERT_FALSE(rows.empty()) << "README.md has no table headed '| problem |'";
  const std::vector<std::string> names = ProblemNames();
  ASSERT_GE(names.size(), 10u);
  for (const std::string& name : names) {
    const std::string start = "| `" + name + "` |";
    const bool found = std::any_of(rows.begin(), rows.end(), [&](const std::string& row) {
      return row.rfind(start, 0) == 0;
    });
    EXPECT_TRUE(found) << "README.md's problem table has no row starting with " << start;
  }
}

TEST(Readme, EveryExampleSpecIsInTheProblemTable) {
  const std::vector<std::string> rows = ProblemTable(Read(kSource / "README.md"));
  ASSERT_FALSE(rows.empty()) << "README.md has no table headed '| problem |'";
  std::string table;
  for (const std::string& row : rows) table += row + "\n";
  int specs = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(kSource / "examples")) {
    if (entry.path().extension() != ".yaml") continue;
    ++specs;
    const std::string name = "examples/" + entry.path().filename().string();
    EXPECT_NE(table.find("`" + name + "`"), std::string::npos)
        << "README.md's problem table does not name " << name;
  }
  EXPECT_GE(specs, 10);
}

TEST(Readme, EveryExamplePathNamedInTheDocsExists) {
  std::vector<fs::path> pages = {kSource / "README.md"};
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kSource / "docs")) {
    if (entry.is_regular_file() && entry.path().extension() == ".md") pages.push_back(entry.path());
  }
  std::sort(pages.begin(), pages.end());
  std::set<std::string> named;
  for (const fs::path& page : pages) {
    const std::string text = Read(page);
    ASSERT_FALSE(text.empty()) << page;
    for (const std::string& path : ExamplePaths(text)) {
      named.insert(path);
      EXPECT_TRUE(fs::exists(kSource / path))
          << fs::relative(page, kSource).string() << " names " << path
          << ", which does not exist";
    }
  }
  EXPECT_GE(named.size(), 20u);  // the problem table alone names every spec
}

}  // namespace
}  // namespace archgeo
