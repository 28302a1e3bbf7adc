// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Progress as a user sees it (tools/progress_line.h): on a terminal (a
// pseudo-terminal from util-linux's `script`) one line rewritten in place
// with the round, the iteration and the goal against its target; the log
// with --log; `archgeo bench` says which run of how many it is on.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

std::string Output(const std::string& command, int* code) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  *code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class ProgressTest : public ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    int code = 0;
    Output(std::string(ARCHGEO_BINARY) + " generate " + Path("grid.obj") +
               " --nu 16 --nv 12 --noise 0.03", &code);
    ASSERT_EQ(code, 0);
    spec_ = WriteFile("spec.yaml", "mesh: grid.obj\nproblem: planar_quads\n"
                                   "output: {mesh: out.ply, report: out.json}\n");
  }
  // What a terminal shows of `archgeo ARGS` (the typescript without
  // script's own first and last lines).
  std::string OnATerminal(const std::string& args) const {
    int code = 0;
    const std::string typescript = Path("typescript");
    Output("script -qec '" + std::string(ARCHGEO_BINARY) + " " + args + "' " + typescript, &code);
    EXPECT_EQ(code, 0);
    std::string text = ReadFile(typescript);
    text = text.substr(text.find('\n') + 1);                // "Script started ..."
    return text.substr(0, text.rfind("Script done"));
  }
  std::string spec_;
};

TEST_F(ProgressTest, OnATerminalTheProgressIsOneLineRewrittenInPlace) {
  const std::string screen = OnATerminal("solve " + spec_);
  // Everything before the summary is one line: carriage returns, no newline.
  const size_t summary = screen.find("planar_quads: ");
  ASSERT_NE(summary, std::string::npos) << screen;
  const std::string progress = screen.substr(0, summary);
  EXPECT_EQ(progress.find('\n'), std::string::npos) << progress;
  EXPECT_GE(Count(progress, "\r\033[K"), 4) << progress;
  EXPECT_NE(progress.find("round 1/12  iter "), std::string::npos) << progress;  // 12: the default
  EXPECT_NE(progress.find("pq_normalized_max "), std::string::npos) << progress;
  EXPECT_NE(progress.find("(goal 1e-03)"), std::string::npos) << progress;
  EXPECT_NE(progress.find(" done "), std::string::npos) << progress;
  // The line is erased before the summary, which then reads as usual.
  EXPECT_EQ(progress.substr(progress.size() - 4), "\r\033[K");
  EXPECT_NE(screen.find("stop: tolerances met"), std::string::npos) << screen;
}

TEST_F(ProgressTest, WithLogEveryIterationIsALineOfItsOwn) {
  const std::string screen = OnATerminal("solve " + spec_ + " --log");
  EXPECT_EQ(screen.find("\033[K"), std::string::npos) << screen;
  EXPECT_GE(Count(screen, "  iter "), 4) << screen;
  EXPECT_GE(Count(screen, "\n"), Count(screen, "  iter ")) << screen;
  const std::string quiet = OnATerminal("solve " + spec_ + " --quiet");
  EXPECT_EQ(quiet.find("  iter "), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find("round 1"), std::string::npos) << quiet;
}

TEST_F(ProgressTest, BenchSaysWhichRunOfHowManyItIsOn) {
  int code = 0;
  const std::string out =
      Output(std::string(ARCHGEO_BINARY) + " bench " + spec_ + " --mesh " + Path("grid.obj") +
                 " --vary 'solver.num_threads=[1,2]'", &code);
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("run 1 of 2: grid.obj, solver.num_threads=1\n"), std::string::npos) << out;
  EXPECT_NE(out.find("run 2 of 2: grid.obj done: exit code 0, "), std::string::npos) << out;
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
