// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Every documented solver key value works or is refused (core/solver_options.h):
// `archgeo solve` with examples/planar_quads.yaml on a small roof, for every
// pair of linear_solver_type and preconditioner_type, and for every value of
// every other enumerated solver key (choices and flags) beside each
// linear_solver_type and each preconditioner_type, ends with a result or
// bad input (exit 0, 2, 3, 4 or 5) — never by a signal (Ceres aborts on
// combinations its IsValid accepts, e.g. mixed precision without a
// single-precision Cholesky, cgnr with a Schur preconditioner) or exit 1.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/solver_options.h"
#include "problems/commands/generate.h"
#include "tests/scratch_dir.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

class SolverKeys : public ScratchDirTest {};

std::vector<std::string> Values(const Key& k) {
  if (k.type == Type::kBool) return {"true", "false"};
  return k.choices;
}

TEST_F(SolverKeys, EveryEnumeratedValueWorksOrIsRefused) {
  GenerateOptions roof;
  roof.nu = 5;
  roof.nv = 4;
  GenerateSurface(Path("roof.obj"), roof);
  const Key *linear = nullptr, *preconditioner = nullptr;
  std::vector<const Key*> others;
  const std::vector<Key> keys = archgeo::SolverKeys();
  for (const Key& k : keys) {
    if (k.name == "solver.linear_solver_type") linear = &k;
    else if (k.name == "solver.preconditioner_type") preconditioner = &k;
    else if (k.type == Type::kChoice || k.type == Type::kBool) others.push_back(&k);
  }
  ASSERT_TRUE(linear && preconditioner);
  ASSERT_GE(others.size(), 10u);
  std::vector<std::string> cases;  // "--set a=x --set b=y"
  for (const std::string& l : linear->choices) {
    for (const std::string& p : preconditioner->choices) {
      cases.push_back("--set " + linear->name + "=" + l + " --set " + preconditioner->name + "=" + p);
    }
  }
  for (const Key* k : others) {
    for (const std::string& v : Values(*k)) {
      for (const Key* pair : {linear, preconditioner}) {
        for (const std::string& w : pair->choices) {
          cases.push_back("--set " + k->name + "=" + v + " --set " + pair->name + "=" + w);
        }
      }
    }
  }
  // One shell line per case printing "<exit> <case>", two at a time; one
  // round of three iterations is enough to reach each linear solve.
  std::ofstream jobs(Path("jobs.txt"));
  const std::string solve = std::string(ARCHGEO_BINARY) + " solve " + ARCHGEO_SOURCE_DIR +
                            "/examples/planar_quads.yaml --quiet --set mesh=" + Path("roof.obj") +
                            " --set output.mesh= --set output.image= --set output.report=" +
                            " --set solver.subset_preconditioner_parts=pq_diagonal" +
                            " --set schedule.outer_iterations=1 --set solver.max_num_iterations=3 ";
  for (const std::string& c : cases) {
    jobs << solve << c << " >/dev/null 2>&1; echo \"$? " << c << "\"\n";
  }
  jobs.close();
  const Outcome o = Shell("xargs -P 2 -d '\\n' -n 1 sh -c < " + Path("jobs.txt"));
  int lines = 0;
  std::istringstream out(o.output);
  for (std::string line; std::getline(out, line);) {
    if (line.empty()) continue;
    ++lines;
    const int code = std::stoi(line.substr(0, line.find(' ')));
    EXPECT_TRUE(code == 0 || code == 2 || code == 3 || code == 4 || code == 5) << line;
  }
  EXPECT_EQ(lines, int(cases.size())) << o.output;
}

}  // namespace
}  // namespace archgeo
