// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The kill semantics of README's "Atomic outputs", through the built
// `archgeo`: a run stopped at each rename of its commit
// (ARCHGEO_TEST_PAUSE_AFTER_RENAME=k) and then SIGKILLed leaves outputs
// that the next run into the folder restores (all old, nothing `.bak-`,
// `.tmp-` or journal left); a SIGTERM there rolls the commit back and exits
// 143; an output that is a symbolic link (also /dev/stdout) is refused.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/scratch_dir.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

class CliKillTest : public ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    // A tolerance the input meets: no iteration, the run is its outputs.
    spec_ = WriteFile("spec.yaml", "mesh: " + std::string(ARCHGEO_SOURCE_DIR) +
                                       "/examples/roof_grid.obj\nproblem: planar_quads\n"
                                       "tolerance:\n  pq_normalized_max: 0.05\nsolver:\n  num_threads: 1\n"
                                       "output:\n  mesh: out/m.ply\n  report: out/r.json\n"
                                       "  image: out/i.png\n");
    fs::create_directories(Path("out"));
  }

  // The three outputs with old contents.
  void WriteOld() const {
    for (const std::string& name : names_) WriteFile("out/" + name, "old " + name);
  }
  // How many outputs are old (-1 if one is missing).
  int OldCount() const {
    int old = 0;
    for (const std::string& name : names_) {
      if (!fs::exists(Path("out/" + name))) return -1;
      old += ReadFile(Path("out/" + name)) == "old " + name;
    }
    return old;
  }
  void ExpectNoLeftovers() const {
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      EXPECT_EQ(name.find(".tmp-"), std::string::npos) << entry.path();
      EXPECT_EQ(name.find(".bak-"), std::string::npos) << entry.path();
      EXPECT_EQ(name.find(".archgeo-commit-"), std::string::npos) << entry.path();
    }
  }

  // Starts `archgeo solve` with ARCHGEO_TEST_PAUSE_AFTER_RENAME=k and waits
  // until it has stopped itself there; its pid.
  pid_t StartPaused(int k) const {
    const std::string binary = ARCHGEO_BINARY;
    const std::string pause = "ARCHGEO_TEST_PAUSE_AFTER_RENAME=" + std::to_string(k);
    std::vector<char*> env;
    for (char** e = environ; *e != nullptr; ++e) {
      const std::string entry = *e;
      if (entry.rfind("OMP_NUM_THREADS=", 0) != 0 && entry.rfind("OPENBLAS_NUM_THREADS=", 0) != 0) {
        env.push_back(*e);
      }
    }
    env.push_back(const_cast<char*>(pause.c_str()));
    // One thread: a SIGTERM sent while the commit is stopped can then only be
    // pending for the committing thread, which blocks it, so the commit sees
    // it. (With helper threads alive one of them may take it and run the
    // handler a moment after the commit looked; the run then ends by the
    // signal after the commit point: io/output_files.cpp.)
    static char omp[] = "OMP_NUM_THREADS=1", blas[] = "OPENBLAS_NUM_THREADS=1";
    env.push_back(omp);
    env.push_back(blas);
    env.push_back(nullptr);
    const char* argv[] = {binary.c_str(), "solve", spec_.c_str(), "--quiet", nullptr};
    const pid_t pid = fork();
    if (pid == 0) {
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 1);
      dup2(null, 2);
      execve(binary.c_str(), const_cast<char**>(argv), env.data());
      _exit(127);
    }
    int status = 0;
    EXPECT_EQ(waitpid(pid, &status, WUNTRACED), pid);
    EXPECT_TRUE(WIFSTOPPED(status)) << "k=" << k << " status " << status;
    return pid;
  }
  // The exit status of `pid` after it is continued (128 + signal if killed).
  static int Finish(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

  std::string spec_;
  const std::vector<std::string> names_ = {"m.ply", "r.json", "i.png"};
};

// SIGKILL once k renames are done (k = 0..3), then the next run: stopped
// before its own first rename, it has restored every old output (its
// recovery); let go, it ends with every output new, exit 0, nothing left.
TEST_F(CliKillTest, ASigkillAtEachRenameIsUndoneByTheNextRun) {
  for (int k = 0; k <= 3; ++k) {
    WriteOld();
    const pid_t killed = StartPaused(k);
    EXPECT_EQ(OldCount(), 3 - k) << "k=" << k;  // k outputs already replaced
    kill(killed, SIGKILL);
    EXPECT_EQ(Finish(killed), 128 + SIGKILL);

    const pid_t next = StartPaused(0);
    EXPECT_EQ(OldCount(), 3) << "k=" << k;  // all old again
    kill(next, SIGCONT);
    EXPECT_EQ(Finish(next), 0) << "k=" << k;
    EXPECT_EQ(OldCount(), 0) << "k=" << k;  // all new
    ExpectNoLeftovers();
  }
}

// A SIGTERM during the commit (after the first rename) rolls it back: exit
// 143, every output old, nothing left.
TEST_F(CliKillTest, ASigtermDuringTheCommitRollsItBackAndExits143) {
  WriteOld();
  const pid_t pid = StartPaused(1);
  EXPECT_EQ(OldCount(), 2);
  kill(pid, SIGTERM);
  kill(pid, SIGCONT);
  EXPECT_EQ(Finish(pid), 128 + SIGTERM);
  EXPECT_EQ(OldCount(), 3);
  ExpectNoLeftovers();
}

// An output that is a symbolic link is refused (exit 2, the path and key
// named); the link and the file it points to stay as they were. So is
// /dev/stdout with the output redirected to a file.
TEST_F(CliKillTest, ASymbolicLinkOutputIsRefusedAndKept) {
  const std::string victim = WriteFile("victim.json", "victim");
  fs::create_symlink(victim, Path("out/r.json"));
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " solve " + spec_ + " --quiet");
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find(Path("out/r.json") + ": key 'output.report'"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("a symbolic link"), std::string::npos) << o.output;
  EXPECT_TRUE(fs::is_symlink(Path("out/r.json")));
  EXPECT_EQ(ReadFile(victim), "victim");
  EXPECT_FALSE(fs::exists(Path("out/m.ply")));  // nothing written

  struct stat info;
  ASSERT_EQ(lstat("/dev/stdout", &info), 0);
  ASSERT_TRUE(S_ISLNK(info.st_mode)) << "/dev/stdout is a symbolic link on Debian (to /proc/self/fd/1)";
  const std::string spec =
      WriteFile("stdout.yaml", "mesh: " + std::string(ARCHGEO_SOURCE_DIR) +
                                   "/examples/roof_grid.obj\nproblem: planar_quads\n"
                                   "output:\n  report: /dev/stdout\n");
  const Outcome s = Shell("{ " + std::string(ARCHGEO_BINARY) + " solve " + spec + " --quiet > " +
                          Path("redirected.txt") + "; }");
  EXPECT_EQ(s.code, 2) << s.output;
  EXPECT_NE(s.output.find("/dev/stdout: key 'output.report'"), std::string::npos) << s.output;
  ASSERT_EQ(lstat("/dev/stdout", &info), 0);
  EXPECT_TRUE(S_ISLNK(info.st_mode));
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
