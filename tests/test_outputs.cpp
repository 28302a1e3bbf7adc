// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The output protocol of io/output_files.h: regular files only, nothing
// replaced before everything is written, all old or all new when a rename
// fails or a signal arrives, checked writes on a full disk — as a unit and
// end to end through the `archgeo` binary.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/input_error.h"
#include "io/io.h"
#include "io/output_files.h"
#include "io/output_stream.h"
#include "tests/make_mesh.h"
#include "tests/scratch_dir.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

class OutputsTest : public ScratchDirTest {
 protected:
  // No temporaries, backups or journals anywhere under the scratch folder.
  void ExpectNoLeftovers() const {
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      EXPECT_EQ(name.find(".tmp-"), std::string::npos) << entry.path();
      EXPECT_EQ(name.find(".bak-"), std::string::npos) << entry.path();
      EXPECT_EQ(name.find(".archgeo-commit-"), std::string::npos) << entry.path();
    }
  }
  // A file that must stay as it is: what a link planted by someone else
  // points to.
  std::string Victim() const { return WriteFile("victim.txt", "victim"); }
};

// `<stem>.tmp-<pid>-<12 of [a-z0-9]><extension>`
bool IsTemporaryName(const std::string& name, const std::string& stem, const std::string& ext) {
  const std::string head = stem + ".tmp-" + std::to_string(getpid()) + "-";
  if (name.size() != head.size() + 12 + ext.size() || name.compare(0, head.size(), head) != 0 ||
      name.compare(name.size() - ext.size(), ext.size(), ext) != 0) {
    return false;
  }
  for (size_t i = head.size(); i < head.size() + 12; ++i) {
    if (!std::islower(static_cast<unsigned char>(name[i])) && !std::isdigit(name[i])) return false;
  }
  return true;
}

TEST_F(OutputsTest, StageCreatesTheTemporaryWithAnUnpredictableNameAndTheExtension) {
  StagedOutputs first, second;
  const std::string a = first.Stage(Path("mesh.ply"));
  const std::string b = second.Stage(Path("mesh.ply"));  // the same target: another name
  EXPECT_NE(a, b);
  for (const std::string& t : {a, b}) {
    EXPECT_TRUE(IsTemporaryName(fs::path(t).filename().string(), "mesh", ".ply")) << t;
    struct stat info;
    ASSERT_EQ(lstat(t.c_str(), &info), 0) << t;  // created by Stage(), empty
    EXPECT_TRUE(S_ISREG(info.st_mode));
    EXPECT_EQ(info.st_size, 0);
  }
}

// A temporary swapped for a link after Stage(): the writers refuse to write
// through it (O_NOFOLLOW), the error names the user's path.
TEST_F(OutputsTest, AWriterNeverFollowsALinkSwappedForItsTemporary) {
  const std::string victim = Victim();
  StagedOutputs outputs;
  try {
    outputs.Write(Path("o.json"), "output.report", [&](const std::string& temporary) {
      fs::remove(temporary);
      fs::create_symlink(victim, temporary);
      WriteTextFile(temporary, "attack", "output.report");
    });
    ADD_FAILURE() << "written through the link";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), Path("o.json"));
    EXPECT_NE(e.message().find("cannot open"), std::string::npos) << e.what();
  }
  const std::string mesh = outputs.Stage(Path("m.obj"));
  fs::remove(mesh);
  fs::create_symlink(victim, mesh);
  EXPECT_THROW(WriteMesh(mesh, MakeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}})),
               InputError);
  NoFollowOfstream stream(mesh);
  EXPECT_FALSE(stream);
  EXPECT_EQ(ReadFile(victim), "victim");
}

// A temporary replaced (by a link or another file) after it was written:
// Commit() refuses, names the output and replaces nothing.
TEST_F(OutputsTest, ATemporaryReplacedBeforeTheCommitIsAnErrorAndNothingIsReplaced) {
  const std::string victim = Victim();
  const std::string a = WriteFile("a.json", "old a");
  const std::string b = WriteFile("b.json", "old b");
  for (const bool link : {true, false}) {
    StagedOutputs outputs;
    WriteTextFile(outputs.Stage(a), "new a");
    const std::string temporary = outputs.Stage(b, "output.report");
    WriteTextFile(temporary, "new b");
    fs::remove(temporary);
    if (link) {
      fs::create_symlink(victim, temporary);
    } else {
      WriteTextFile(temporary, "planted");  // a new file at the same name
    }
    try {
      outputs.Commit();
      ADD_FAILURE() << "committed";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), b);
      EXPECT_EQ(e.key(), "output.report");
      EXPECT_NE(e.message().find("replaced"), std::string::npos) << e.what();
    }
    fs::remove(temporary);
  }
  EXPECT_EQ(ReadFile(a), "old a");
  EXPECT_EQ(ReadFile(b), "old b");
  EXPECT_EQ(ReadFile(victim), "victim");
  ExpectNoLeftovers();
}

// An output path that is a symbolic link is refused; the link stays a link
// and its target keeps its content (also /dev/stdout, a link on Linux).
TEST_F(OutputsTest, ASymbolicLinkIsRefusedAsAnOutputAndKept) {
  const std::string victim = Victim();
  fs::create_symlink(victim, Path("link.json"));
  fs::create_symlink(Path("nowhere.json"), Path("dangling.json"));
  StagedOutputs outputs;
  for (const std::string& target : {Path("link.json"), Path("dangling.json")}) {
    try {
      outputs.Stage(target, "output.report");
      ADD_FAILURE() << target << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), target);
      EXPECT_NE(e.message().find("a symbolic link to '"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_symlink(target));
  }
  struct stat info;
  if (lstat("/dev/stdout", &info) == 0 && S_ISLNK(info.st_mode)) {
    EXPECT_THROW(outputs.Stage("/dev/stdout", "output.report"), InputError);
    EXPECT_TRUE(fs::is_symlink("/dev/stdout"));
  }
  EXPECT_EQ(ReadFile(victim), "victim");
  EXPECT_FALSE(fs::exists(Path("nowhere.json")));
  ExpectNoLeftovers();
}

TEST_F(OutputsTest, SpecialFilesAreRefusedAsOutputs) {
  ASSERT_EQ(mkfifo(Path("pipe").c_str(), 0600), 0);
  fs::create_directories(Path("folder"));
  StagedOutputs outputs;
  for (const std::string& target : {std::string("/dev/null"), Path("pipe"), Path("folder")}) {
    try {
      outputs.Stage(target, "output.report");
      ADD_FAILURE() << target << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), target);
      EXPECT_EQ(e.key(), "output.report");
      EXPECT_NE(e.message().find("not a regular file"), std::string::npos) << e.what();
    }
  }
  struct stat info;
  ASSERT_EQ(stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));  // the device node is still a device
}

TEST_F(OutputsTest, WriterErrorsNameTheUsersPath) {
  StagedOutputs outputs;
  try {
    outputs.Write(Path("mesh.ply"), "output.mesh", [](const std::string& temporary) {
      throw InputError(temporary, 0, "", "cannot write the mesh file");
    });
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), Path("mesh.ply"));
    EXPECT_EQ(e.key(), "output.mesh");
  }
}

TEST_F(OutputsTest, AFailedRenameRestoresEveryOldOutput) {
  const std::string a = WriteFile("a.json", "old a");
  const std::string b = WriteFile("b.json", "old b");
  {
    StagedOutputs outputs;
    WriteTextFile(outputs.Stage(a), "new a");
    WriteTextFile(outputs.Stage(b), "new b");
    // After the first rename, b becomes a folder that is not empty: the
    // second rename fails.
    outputs.SetRenameHookForTesting([&](int k, const std::string&) {
      if (k != 0) return;
      fs::remove(b);
      fs::create_directories(b + "/x");
    });
    try {
      outputs.Commit();
      ADD_FAILURE() << "the commit succeeded";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), b);
      EXPECT_NE(e.message().find("old content"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(ReadFile(a), "old a");  // restored from its backup
  fs::remove_all(b);
  ExpectNoLeftovers();
}

TEST_F(OutputsTest, AFailedRenameRemovesNewOutputsThatHadNoOldVersion) {
  const std::string a = Path("new.json");
  const std::string b = WriteFile("b.json", "old b");
  {
    StagedOutputs outputs;
    WriteTextFile(outputs.Stage(a), "new a");
    WriteTextFile(outputs.Stage(b), "new b");
    outputs.SetRenameHookForTesting([&](int k, const std::string&) {
      if (k != 0) return;
      fs::remove(b);
      fs::create_directories(b + "/x");
    });
    EXPECT_THROW(outputs.Commit(), InputError);
  }
  EXPECT_FALSE(fs::exists(a));
  fs::remove_all(b);
  ExpectNoLeftovers();
}

// A SIGTERM during the renames is held back, then rolls the commit back:
// every output old, the process ended by the signal.
TEST_F(OutputsTest, ASignalDuringTheCommitRollsItBackAndEndsTheProcess) {
  const std::string a = WriteFile("a.json", "old a");
  const std::string b = WriteFile("b.json", "old b");
  const std::string c = Path("new/c.json");  // no old version, in a new folder
  EXPECT_EXIT(
      {
        InstallOutputSignalCleanup();
        StagedOutputs outputs;
        WriteTextFile(outputs.Stage(a), "new a");
        WriteTextFile(outputs.Stage(c), "new c");
        WriteTextFile(outputs.Stage(b), "new b");
        outputs.SetRenameHookForTesting([](int k, const std::string&) {
          if (k == 1) kill(getpid(), SIGTERM);
        });
        outputs.Commit();
        std::_Exit(0);  // not reached: the held signal ends the process
      },
      ::testing::KilledBySignal(SIGTERM), "");
  EXPECT_EQ(ReadFile(a), "old a");
  EXPECT_EQ(ReadFile(b), "old b");
  EXPECT_FALSE(fs::exists(Path("new")));
  ExpectNoLeftovers();
}

// A SIGKILL after each rename of a commit into two folders: the next Stage()
// into either folder rolls every output back (all old, in both folders) and
// leaves no backup, temporary or journal.
TEST_F(OutputsTest, AKilledCommitIsRolledBackByTheNextStageIntoEitherFolder) {
  const std::vector<std::string> targets = {Path("one/a.json"), Path("two/b.json"),
                                            Path("one/c.json")};
  for (int kill_after = 0; kill_after < 3; ++kill_after) {
    for (const std::string& next : {Path("one/x.json"), Path("two/x.json")}) {
      fs::remove_all(Path("one"));
      fs::remove_all(Path("two"));
      fs::create_directories(Path("one"));
      fs::create_directories(Path("two"));
      WriteFile("one/a.json", "old a");
      WriteFile("two/b.json", "old b");  // one/c.json is new
      EXPECT_EXIT(
          {
            StagedOutputs outputs;
            for (const std::string& t : targets) WriteTextFile(outputs.Stage(t), "new");
            outputs.SetRenameHookForTesting([&](int k, const std::string&) {
              if (k == kill_after) raise(SIGKILL);
            });
            outputs.Commit();
            std::_Exit(0);
          },
          ::testing::KilledBySignal(SIGKILL), "");
      EXPECT_EQ(ReadFile(targets[0]), "new");  // the first rename done: all old no more
      EXPECT_EQ(ReadFile(targets[1]), kill_after >= 1 ? "new" : "old b");
      {
        StagedOutputs recovering;
        recovering.Stage(next);
      }
      EXPECT_EQ(ReadFile(targets[0]), "old a") << kill_after << " " << next;
      EXPECT_EQ(ReadFile(targets[1]), "old b") << kill_after << " " << next;
      EXPECT_FALSE(fs::exists(targets[2])) << kill_after << " " << next;
      ExpectNoLeftovers();
    }
  }
}

// What a dead process left outside a journal goes (its temporaries, backups
// of a commit past its commit point); what a live one or a user left stays.
TEST_F(OutputsTest, TheNextStageRemovesOnlyWhatDeadProcessesLeft) {
  const pid_t dead = fork();
  if (dead == 0) std::_Exit(0);
  waitpid(dead, nullptr, 0);
  const std::string d = std::to_string(dead), live = std::to_string(getpid());
  WriteFile("mesh.ply", "new mesh");
  const std::string gone[] = {WriteFile("mesh.tmp-" + d + "-abcdefghij12.ply", "partial"),
                              WriteFile("mesh.ply.bak-" + d + "-abcdefghij12", "old mesh")};
  const std::string kept[] = {WriteFile("mesh.tmp-" + live + "-abcdefghij12.ply", "in use"),
                              WriteFile("notes.tmp-" + d + "-short.txt", "a user's file"),
                              WriteFile("mesh.ply.bak-" + d, "a user's backup")};
  {
    StagedOutputs outputs;
    outputs.Stage(Path("report.json"));
  }
  for (const std::string& p : gone) EXPECT_FALSE(fs::exists(p)) << p;
  for (const std::string& p : kept) EXPECT_TRUE(fs::exists(p)) << p;
  EXPECT_EQ(ReadFile(Path("mesh.ply")), "new mesh");
}

// A SIGINT while the outputs are being written removes the temporaries and
// the folders made for them; the old outputs stay.
TEST_F(OutputsTest, ASignalBeforeTheCommitLeavesTheOldOutputs) {
  const std::string a = WriteFile("a.json", "old a");
  EXPECT_EXIT(
      {
        InstallOutputSignalCleanup();
        StagedOutputs outputs;
        WriteTextFile(outputs.Stage(a), "new a");
        WriteTextFile(outputs.Stage(Path("made/for/b.json")), "new b");
        kill(getpid(), SIGINT);
        std::_Exit(0);  // not reached
      },
      ::testing::KilledBySignal(SIGINT), "");
  EXPECT_EQ(ReadFile(a), "old a");
  EXPECT_FALSE(fs::exists(Path("made")));
  ExpectNoLeftovers();
}

// A full disk (here: a file-size limit, EFBIG) is an error, not an empty file.
// Exits 7 when WriteTextFile throws the right error.
void WriteBeyondAFileSizeLimit(const std::string& path) {
  signal(SIGXFSZ, SIG_IGN);
  rlimit limit;
  limit.rlim_cur = limit.rlim_max = 4096;
  setrlimit(RLIMIT_FSIZE, &limit);
  try {
    WriteTextFile(path, std::string(100000, 'x'), "output.report");
  } catch (const InputError& e) {
    std::_Exit(e.file() == path && e.key() == "output.report" ? 7 : 8);
  }
  std::_Exit(9);
}

TEST_F(OutputsTest, AFullDiskIsAnErrorNamingTheFile) {
  const std::string path = Path("big.json");
  EXPECT_EXIT(WriteBeyondAFileSizeLimit(path), ::testing::ExitedWithCode(7), "");
}

// --- end to end -----------------------------------------------------------------


std::string Archgeo() { return std::string(ARCHGEO_BINARY); }
std::string Example(const std::string& name) {
  return std::string(ARCHGEO_SOURCE_DIR) + "/examples/" + name;
}

class OutputsCliTest : public OutputsTest {
 protected:
  std::string Spec(const std::string& outputs) const {
    return WriteFile("spec.yaml", "mesh: " + Example("roof_grid.obj") +
                                      "\nproblem: planar_quads\noutput:\n" + outputs);
  }
};

TEST_F(OutputsCliTest, AReportThatDoesNotFitIsAnErrorAndTheOldOutputsStay) {
  const std::string old_report = WriteFile("o.json", "old report");
  const std::string spec = Spec("  report: o.json\n");
  // 4 KiB: too little for the report (~6 KB), the last file written.
  const Outcome o = Shell("bash -c \"trap '' XFSZ; ulimit -f 4; exec " + Archgeo() + " solve " +
                        spec + " --quiet\"");
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find(Path("o.json") + ": key 'output.report'"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("wrote"), std::string::npos) << o.output;
  EXPECT_EQ(ReadFile(old_report), "old report");
  ExpectNoLeftovers();
}

TEST_F(OutputsCliTest, ADeviceIsRefusedAsAnOutput) {
  const std::string spec = Spec("  report: /dev/null\n");
  const Outcome o = Shell(Archgeo() + " solve " + spec + " --quiet");
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("/dev/null: key 'output.report'"), std::string::npos) << o.output;
  struct stat info;
  ASSERT_EQ(stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
}

TEST_F(OutputsCliTest, ThePrincipalEdgesInputIsNeverOverwritten) {
  fs::copy_file(Example("principal_torus.obj"), Path("torus.obj"));
  fs::copy_file(Example("principal_torus_edges.txt"), Path("edges.txt"));
  const std::string edges = ReadFile(Path("edges.txt"));
  const std::string spec =
      WriteFile("spec.yaml",
                "mesh: torus.obj\nproblem: principal_symmetric\nprincipal_edges: edges.txt\n"
                "output:\n  principal_edges: edges.txt\n");
  const Outcome o = Shell(Archgeo() + " solve " + spec + " --quiet");
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("refusing to overwrite the input file"), std::string::npos) << o.output;
  EXPECT_EQ(ReadFile(Path("edges.txt")), edges);
}

// SIGINT stops a long solve within a second; the old outputs stay and no
// temporary or new folder is left.
TEST_F(OutputsCliTest, SigintStopsASolveAndLeavesTheOldOutputs) {
  const std::string old_report = WriteFile("o.json", "old report");
  const std::string spec =
      WriteFile("spec.yaml", "mesh: " + std::string(ARCHGEO_DATA_DIR) +
                                 "/directional_Concerthall.off\nproblem: smooth_mesh\n"
                                 "output:\n  mesh: new/o.ply\n  report: o.json\n");
  const std::string pid_file = Path("pid");
  const std::string command =
      Archgeo() + " solve " + spec + " --quiet > /dev/null 2>&1 & echo $! > " + pid_file +
      "; wait $!; echo $? > " + Path("status");
  std::thread runner([&] { Shell("bash -c '" + command + "'"); });
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));  // the solve is running
  const pid_t pid = std::stoi(ReadFile(pid_file));
  const auto sent = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  runner.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  EXPECT_LT(seconds, 1.0);
  EXPECT_EQ(std::stoi(ReadFile(Path("status"))), 128 + SIGINT);
  EXPECT_EQ(ReadFile(old_report), "old report");
  EXPECT_FALSE(fs::exists(Path("new")));
  ExpectNoLeftovers();
}

}  // namespace
}  // namespace archgeo
