// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench/child.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "core/input_error.h"

extern char** environ;

namespace archgeo {
namespace {

// What the handler stops and removes (fixed storage: no allocation in it).
std::atomic<pid_t> running_child{0};
char scratch_path[PATH_MAX];
std::atomic<bool> scratch_live{false};

constexpr int kForwarded[3] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction handlers_before[3];
std::atomic<bool> bench_handlers_installed{false};

// A forwarded signal that arrived in another thread while this one was
// between spawning a child (or creating the scratch folder) and recording it:
// the handler there leaves it here, and the end of the section raises it again
// in this thread, where the handler then sees the child and the folder.
std::atomic<bool> recording{false};
std::atomic<int> deferred_signal{0};

// While alive: the forwarded signals are blocked in this thread, and a
// handler running in another thread defers them (see above). One at a time.
class RecordingSection {
 public:
  RecordingSection() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : kForwarded) sigaddset(&set, s);
    pthread_sigmask(SIG_BLOCK, &set, &before_);
    recording.store(true);
  }
  ~RecordingSection() {
    recording.store(false);
    pthread_sigmask(SIG_SETMASK, &before_, nullptr);
    if (const int sig = deferred_signal.exchange(0)) raise(sig);
  }
  const sigset_t& before() const { return before_; }

 private:
  sigset_t before_;
};

// Async-signal-safe: `sig` to the child, then up to 5 s for it to end
// (solve's own cleanup), then SIGKILL; the child is reaped.
void StopChild(pid_t child, int sig) {
  kill(child, sig);
  const timespec tick = {0, 10 * 1000 * 1000};
  for (int i = 0; i < 500; ++i) {
    int status = 0;
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child || (done < 0 && errno != EINTR)) return;
    nanosleep(&tick, nullptr);
  }
  kill(child, SIGKILL);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
}

// The kernel's record of a folder entry (getdents64).
struct FolderEntry {
  std::uint64_t inode;
  std::int64_t offset;
  unsigned short length;
  unsigned char type;
  char name[1];
};

// Async-signal-safe: removes every file of `folder` (it holds no folders),
// then the folder.
void EmptyScratchFolder(const char* folder) {
  const int fd = open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    alignas(8) char buffer[4096];
    for (int pass = 0; pass < 8; ++pass) {  // removing while listing may skip entries
      bool removed = false;
      lseek(fd, 0, SEEK_SET);
      for (long n; (n = syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0;) {
        for (long at = 0; at < n;) {
          const auto* entry = reinterpret_cast<const FolderEntry*>(buffer + at);
          at += entry->length;
          const char* name = entry->name;
          if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
          removed = unlinkat(fd, name, 0) == 0 || removed;
        }
      }
      if (!removed) break;
    }
    close(fd);
  }
  rmdir(folder);
}

void OnBenchSignal(int sig, siginfo_t* info, void* context) {
  const int saved_errno = errno;
  if (recording.load()) {
    // Another thread is recording a child or the folder: it raises `sig`
    // again when done, unless it finished first and left the signal here.
    deferred_signal.store(sig);
    if (recording.load() || deferred_signal.exchange(0) == 0) {
      errno = saved_errno;
      return;
    }
  }
  const pid_t child = running_child.exchange(0);
  if (child > 0) StopChild(child, sig);
  if (scratch_live.exchange(false)) EmptyScratchFolder(scratch_path);
  int i = 0;
  while (kForwarded[i] != sig) ++i;
  const struct sigaction& before = handlers_before[i];
  if (before.sa_flags & SA_SIGINFO) {
    before.sa_sigaction(sig, info, context);
  } else if (before.sa_handler != SIG_DFL && before.sa_handler != SIG_IGN) {
    before.sa_handler(sig);
  } else {
    signal(sig, SIG_DFL);
    raise(sig);  // delivered when this handler returns
  }
  errno = saved_errno;
}

}  // namespace

ScratchFolder::ScratchFolder() {
  std::error_code error;
  std::filesystem::path base = std::filesystem::temp_directory_path(error);
  if (error) base = "/tmp";
  std::string pattern = (base / "archgeo_bench.XXXXXX").string();
  if (pattern.size() >= sizeof scratch_path) {
    throw InputError(base.string(), 0, "TMPDIR", "the temporary folder's path is too long");
  }
  RecordingSection blocked;  // the folder is registered before a signal can see it
  if (scratch_live.load()) throw std::logic_error("one bench scratch folder at a time");
  if (!mkdtemp(pattern.data())) {
    throw InputError(base.string(), 0, "TMPDIR",
                     std::string("cannot create a scratch folder: ") + std::strerror(errno));
  }
  std::memcpy(scratch_path, pattern.c_str(), pattern.size() + 1);
  scratch_live.store(true);
  path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
  scratch_live.store(false);
}

ChildOutcome RunChild(const std::vector<std::string>& argv, const std::string& stdout_path,
                      const std::string& stderr_path) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;  // the child handles them itself, even if ignored here
  sigemptyset(&defaults);
  for (int s : kForwarded) sigaddset(&defaults, s);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  int spawned = 0;
  {
    // A signal before running_child is set would miss the child.
    RecordingSection blocked;
    posix_spawnattr_setsigmask(&attributes, &blocked.before());
    spawned = posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, args.data(), environ);
    if (spawned == 0) running_child.store(pid);
  }
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) {
    throw InputError(argv[0], 0, "", std::string("cannot run the archgeo binary: ") +
                                         std::strerror(spawned));
  }
  // Waits without reaping: until running_child is cleared the pid stays the
  // child's (a zombie), so a forwarded signal cannot reach another process.
  siginfo_t info;
  while (waitid(P_PID, id_t(pid), &info, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
  }
  ChildOutcome outcome;
  outcome.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int status = 0;
  rusage usage{};
  {
    RecordingSection blocked;
    running_child.store(0);
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
  }
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  outcome.peak_memory_mb = double(usage.ru_maxrss) / 1024.0;
  return outcome;
}

void InstallBenchSignalHandling() {
  if (bench_handlers_installed.exchange(true)) return;
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_sigaction = &OnBenchSignal;
  action.sa_flags = SA_SIGINFO;
  sigemptyset(&action.sa_mask);
  for (int s : kForwarded) sigaddset(&action.sa_mask, s);
  for (int i = 0; i < 3; ++i) sigaction(kForwarded[i], &action, &handlers_before[i]);
}

}  // namespace archgeo
