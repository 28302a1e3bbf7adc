// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — all-or-nothing output files (protocol in io/output_files.h).
#include "io/output_files.h"

#include <fcntl.h>
#include <glog/logging.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/input_error.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

// --- what a signal handler may clean up ---------------------------------------
// Fixed storage (no allocation in the handler). A slot holds a staged
// temporary or a folder created by Stage(); `used` is set last when a slot is
// filled and cleared first when it is freed, with the signals blocked in the
// thread that changes it.
constexpr int kSlots = 512;
struct Slot {
  char path[PATH_MAX];
  bool folder;
  std::atomic<bool> used;
};
Slot slots[kSlots];

// 0: idle; 1: a Commit() is renaming (a signal is deferred); 2: terminating.
std::atomic<int> state{0};
std::atomic<int> deferred_signal{0};

// Blocks SIGINT, SIGTERM and SIGHUP in this thread while alive.
class BlockSignals {
 public:
  BlockSignals() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
    pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~BlockSignals() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

int Register(const std::string& path, bool folder) {
  CHECK_LT(path.size(), size_t(PATH_MAX)) << "path too long: " << path;
  BlockSignals block;
  for (int i = 0; i < kSlots; ++i) {
    if (!slots[i].used.load()) {
      std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
      slots[i].folder = folder;
      slots[i].used.store(true);
      return i;
    }
  }
  LOG(FATAL) << "more than " << kSlots << " staged outputs at once";
  return -1;
}

void Unregister(int slot) {
  if (slot < 0) return;
  BlockSignals block;
  slots[slot].used.store(false);
}

// Async-signal-safe: unlink and rmdir only.
void RemoveRegistered() {
  for (Slot& s : slots) {
    if (s.used.load() && !s.folder) unlink(s.path);
  }
  // Folders: several passes so that nesting order does not matter.
  for (int pass = 0; pass < 8; ++pass) {
    for (int i = kSlots - 1; i >= 0; --i) {
      if (slots[i].used.load() && slots[i].folder) rmdir(slots[i].path);
    }
  }
}

void Terminate(int sig) {
  RemoveRegistered();
  signal(sig, SIG_DFL);
  raise(sig);  // delivered when the handler returns (the signal is blocked in it)
}

void OnSignal(int sig) {
  int idle = 0;
  if (state.compare_exchange_strong(idle, 2)) {
    Terminate(sig);
  } else if (state.load() == 1) {
    deferred_signal.store(sig);  // Commit() raises it when the renames are done
  }
}

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

std::string Errno() { return std::strerror(errno); }

// Flushes a written file to disk; false with errno set on failure.
bool SyncFile(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = fsync(fd) == 0;
  const int saved = errno;
  close(fd);
  errno = saved;
  return ok;
}

void SyncFolder(const fs::path& folder) {
  const int fd = open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  fsync(fd);  // best effort: durability of the renames, not their atomicity
  close(fd);
}

std::string BackupOf(const std::string& target) {
  return target + ".bak-" + std::to_string(getpid());
}

}  // namespace

StagedOutputs::StagedOutputs(std::vector<std::string> protected_paths)
    : protected_paths_(std::move(protected_paths)) {}

StagedOutputs::~StagedOutputs() {
  if (committed_) return;
  for (const Staged& s : staged_) {
    std::error_code ignored;  // a temporary never written does not exist
    fs::remove(s.temporary, ignored);
  }
  // Folders Stage() created, deepest first; fs::remove leaves a folder that
  // is not empty (another process wrote there) in place.
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) {
    std::error_code ignored;
    fs::remove(*it, ignored);
  }
  for (int slot : slots_) Unregister(slot);
}

std::string StagedOutputs::Stage(const std::string& target, const std::string& key) {
  CHECK(!committed_) << "Stage() after Commit()";
  for (const std::string& input : protected_paths_) {
    if (SameFile(target, input)) {
      throw InputError(target, 0, key, "refusing to overwrite the input file '" + input + "'");
    }
  }
  for (const Staged& s : staged_) {
    if (SameFile(target, s.target)) {
      throw InputError(target, 0, key, "the same output file is given twice");
    }
  }
  struct stat info;
  if (stat(target.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
    throw InputError(target, 0, key,
                     std::string("the output path exists and is not a regular file (") +
                         (S_ISDIR(info.st_mode)    ? "a folder"
                          : S_ISCHR(info.st_mode)  ? "a character device"
                          : S_ISBLK(info.st_mode)  ? "a block device"
                          : S_ISFIFO(info.st_mode) ? "a FIFO"
                          : S_ISSOCK(info.st_mode) ? "a socket"
                                                   : "a special file") +
                         "); outputs are written as regular files only");
  }
  std::error_code error;
  const fs::path folder = fs::path(target).parent_path();
  if (!folder.empty()) {
    std::vector<fs::path> missing;  // from the folder up to the first existing ancestor
    for (fs::path d = folder; !d.empty() && !fs::exists(d, error); d = d.parent_path()) {
      missing.push_back(d);
      if (d == d.parent_path()) break;
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      created_.push_back(it->string());
      slots_.push_back(Register(it->string(), true));
    }
    fs::create_directories(folder, error);
    if (error) {
      throw InputError(target, 0, key,
                       "cannot create the folder '" + folder.string() + "': " + error.message());
    }
  }
  // Keeps the extension: writers choose the format from it.
  const fs::path path(target);
  const std::string temporary = (folder / path.stem()).string() + ".tmp-" +
                                std::to_string(getpid()) + "-" +
                                std::to_string(next_temporary++) + path.extension().string();
  staged_.push_back({temporary, target, key});
  slots_.push_back(Register(temporary, false));
  return temporary;
}

void StagedOutputs::Write(const std::string& target, const std::string& key,
                          const std::function<void(const std::string&)>& writer) {
  const std::string temporary = Stage(target, key);
  try {
    writer(temporary);
  } catch (const InputError& e) {
    if (e.file() == temporary) throw InputError(target, e.line(), key, e.message());
    throw;
  }
}

void StagedOutputs::Commit() {
  CHECK(!committed_) << "Commit() called twice";
  // 1. Every output complete and on disk before anything is replaced.
  for (const Staged& s : staged_) {
    CHECK(fs::exists(s.temporary)) << "staged output " << s.target << " was never written";
    if (!SyncFile(s.temporary)) {
      throw InputError(s.target, 0, s.key, "cannot write the output to disk: " + Errno());
    }
  }
  // 2. No signal handler runs its cleanup from here to the end of the renames.
  int idle = 0;
  while (!state.compare_exchange_weak(idle, 1)) {
    if (idle == 2) pause();  // a handler is ending the process
    idle = 0;
  }
  BlockSignals block;
  std::vector<std::string> backups(staged_.size());
  std::string failure;
  size_t failed = staged_.size();
  for (size_t i = 0; i < staged_.size() && failure.empty(); ++i) {
    struct stat info;
    if (stat(staged_[i].target.c_str(), &info) != 0) continue;  // a new output
    backups[i] = BackupOf(staged_[i].target);
    unlink(backups[i].c_str());  // a stale backup of an earlier run with our pid
    if (link(staged_[i].target.c_str(), backups[i].c_str()) != 0) {
      failure = "cannot keep a backup of the old output while replacing it: " + Errno();
      failed = i;
      backups[i].clear();
    }
  }
  size_t renamed = 0;
  for (size_t i = 0; i < staged_.size() && failure.empty(); ++i) {
    if (rename(staged_[i].temporary.c_str(), staged_[i].target.c_str()) != 0) {
      failure = "cannot move the output into place: " + Errno();
      failed = i;
      break;
    }
    ++renamed;
    if (rename_hook_) rename_hook_(int(i), staged_[i].target);
  }
  if (!failure.empty()) {
    // Roll back: the old outputs return, the new ones that had none go.
    for (size_t i = 0; i < renamed; ++i) {
      if (!backups[i].empty()) {
        rename(backups[i].c_str(), staged_[i].target.c_str());
        backups[i].clear();
      } else {
        unlink(staged_[i].target.c_str());
      }
    }
  }
  for (const std::string& b : backups) {
    if (!b.empty()) unlink(b.c_str());
  }
  for (const Staged& s : staged_) SyncFolder(fs::path(s.target).parent_path());
  if (failure.empty()) {
    committed_ = true;
    for (int slot : slots_) Unregister(slot);
    slots_.clear();
  }
  state.store(0);
  if (const int sig = deferred_signal.exchange(0)) {
    idle = 0;
    if (state.compare_exchange_strong(idle, 2)) Terminate(sig);
  }
  if (!failure.empty()) {
    const Staged& s = staged_[failed];
    throw InputError(s.target, 0, s.key, failure + " (every output keeps its old content)");
  }
}

void WriteTextFile(const std::string& path, const std::string& text, const std::string& key) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw InputError(path, 0, key, "cannot open for writing: " + Errno());
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size() &&
                       std::fflush(file) == 0 && fsync(fileno(file)) == 0;
  const int saved = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    errno = written ? errno : saved;
    throw InputError(path, 0, key, "cannot write the file (" + Errno() + ")");
  }
}

void InstallOutputSignalCleanup() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = &OnSignal;
  sigemptyset(&action.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, s);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &action, nullptr);
}

}  // namespace archgeo
