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
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/input_error.h"
#include "io/output_journal.h"
#include "io/output_stream.h"

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

// A signal held back during Commit(): one a handler deferred, or one still
// pending in this thread (blocked here, and in every other thread); 0 if none.
int HeldSignal() {
  if (const int sig = deferred_signal.exchange(0)) return sig;
  sigset_t pending;
  sigpending(&pending);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) {
    if (sigismember(&pending, s)) return s;
  }
  return 0;
}

// Ends the process by `sig` from Commit() (signals blocked there).
[[noreturn]] void TerminateFromCommit(int sig) {
  RemoveRegistered();
  signal(sig, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, sig);
  raise(sig);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  _exit(128 + sig);  // not reached: the default action ends the process
}

// ARCHGEO_TEST_PAUSE_AFTER_RENAME=k: Commit() stops itself (SIGSTOP) once k
// renames are done (k = 0: journal and backups written, nothing renamed), for
// the tests that SIGKILL a commit half way. -1 when unset.
int PauseAfterRename() {
  const char* value = std::getenv("ARCHGEO_TEST_PAUSE_AFTER_RENAME");
  return value != nullptr && *value != '\0' ? std::atoi(value) : -1;
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

std::string Errno() { return std::strerror(errno); }

void SyncFolder(const fs::path& folder) {
  const int fd = open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  fsync(fd);  // best effort: durability of the renames, not their atomicity
  close(fd);
}

std::string KindOfFile(mode_t mode) {
  return S_ISLNK(mode)    ? "a symbolic link"
         : S_ISDIR(mode)  ? "a folder"
         : S_ISCHR(mode)  ? "a character device"
         : S_ISBLK(mode)  ? "a block device"
         : S_ISFIFO(mode) ? "a FIFO"
         : S_ISSOCK(mode) ? "a socket"
                          : "a special file";
}

// Refuses a target that exists and is not a regular file, a symbolic link
// included (never followed, never replaced).
void CheckTarget(const std::string& target, const std::string& key) {
  struct stat info;
  if (lstat(target.c_str(), &info) != 0 || S_ISREG(info.st_mode)) return;
  std::string what = KindOfFile(info.st_mode);
  if (S_ISLNK(info.st_mode)) {
    std::error_code error;
    const fs::path to = fs::read_symlink(target, error);
    if (!error) what += " to '" + to.string() + "'";
  }
  throw InputError(target, 0, key,
                   "the output path exists and is not a regular file (" + what +
                       "); outputs are written as regular files only, and a link is neither "
                       "followed nor replaced");
}

std::string Absolute(const std::string& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  return error ? path : absolute.lexically_normal().string();
}

}  // namespace

StagedOutputs::StagedOutputs(std::vector<std::string> protected_paths)
    : protected_paths_(std::move(protected_paths)) {}

StagedOutputs::~StagedOutputs() {
  for (const Staged& s : staged_) close(s.fd);
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
  CheckTarget(target, key);
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
  RecoverOutputs(folder.string());  // what a killed run left here
  CheckTarget(target, key);         // as the recovery left it
  staged_.push_back(CreateTemporary(target, key));
  slots_.push_back(Register(staged_.back().temporary, false));
  return staged_.back().temporary;
}

// The temporary, created here (exclusively, never through a link) with an
// unpredictable name that keeps the extension: writers choose the format from it.
StagedOutputs::Staged StagedOutputs::CreateTemporary(const std::string& target,
                                                     const std::string& key) {
  const fs::path path(target);
  for (int attempt = 0; attempt < 100; ++attempt) {
    Staged s{(path.parent_path() / path.stem()).string() + TemporaryMark(RandomToken()) +
                 path.extension().string(),
             target, key};
    const int fd = open(s.temporary.c_str(),
                        O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, 0666);
    if (fd < 0 && errno == EEXIST) continue;
    if (fd < 0) throw InputError(target, 0, key, "cannot create a file beside it: " + Errno());
    // Kept open until the end: the inode cannot be freed and its number
    // given to a file put in the temporary's place.
    s.fd = fd;
    struct stat info;
    fstat(fd, &info);
    s.device = std::uint64_t(info.st_dev);
    s.inode = std::uint64_t(info.st_ino);
    return s;
  }
  throw InputError(target, 0, key, "cannot create a temporary beside it: every name taken");
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

// Every temporary still the file Stage() created (not swapped for a link or
// another file), written and flushed to disk; every target still one Stage()
// accepts.
void StagedOutputs::CheckAndSync() const {
  for (const Staged& s : staged_) {
    struct stat info;
    if (lstat(s.temporary.c_str(), &info) != 0 || !S_ISREG(info.st_mode) ||
        std::uint64_t(info.st_dev) != s.device || std::uint64_t(info.st_ino) != s.inode) {
      throw InputError(s.target, 0, s.key,
                       "its temporary '" + s.temporary +
                           "' was removed or replaced by another file before the commit; "
                           "nothing was replaced");
    }
    CheckTarget(s.target, s.key);
    if (fsync(s.fd) != 0) {
      throw InputError(s.target, 0, s.key, "cannot write the output to disk: " + Errno());
    }
  }
}

void StagedOutputs::Commit() {
  CHECK(!committed_) << "Commit() called twice";
  // 1. Every output complete and on disk before anything is replaced.
  CheckAndSync();
  // 2. No signal handler runs its cleanup from here to the end of the commit.
  int idle = 0;
  while (!state.compare_exchange_weak(idle, 1)) {
    if (idle == 2) pause();  // a handler is ending the process
    idle = 0;
  }
  BlockSignals block;
  // 3. The journal, then a hard-linked backup of every existing target.
  const std::string token = RandomToken();
  std::vector<JournalEntry> entries;
  for (const Staged& s : staged_) {
    struct stat info;
    const bool exists = lstat(s.target.c_str(), &info) == 0;
    entries.push_back({Absolute(s.target), Absolute(s.temporary),
                       exists ? Absolute(s.target) + BackupMark(token) : std::string(), s.device,
                       s.inode});
  }
  std::string failure;
  size_t failed = 0;
  CommitJournal journal;
  if (!journal.Write(entries, token)) {
    failure = "cannot write the commit journal beside it: " + Errno();
  }
  for (size_t i = 0; i < staged_.size() && failure.empty(); ++i) {
    if (!entries[i].backup.empty() &&
        link(staged_[i].target.c_str(), entries[i].backup.c_str()) != 0) {
      failure = "cannot keep a backup of the old output while replacing it: " + Errno();
      failed = i;
    }
  }
  // 4. The renames, each atomic.
  const int pause_after = PauseAfterRename();
  if (failure.empty() && pause_after == 0) raise(SIGSTOP);
  size_t renamed = 0;
  for (size_t i = 0; i < staged_.size() && failure.empty(); ++i) {
    if (rename(staged_[i].temporary.c_str(), staged_[i].target.c_str()) != 0) {
      failure = "cannot move the output into place: " + Errno();
      failed = i;
      break;
    }
    ++renamed;
    if (rename_hook_) rename_hook_(int(i), staged_[i].target);
    if (pause_after == int(i) + 1) raise(SIGSTOP);
  }
  // 5. A failure or a signal held back so far: every output returns to its
  // old content. Else the commit point (the primary journal goes), then the
  // backups.
  const int sig = HeldSignal();
  if (!failure.empty() || sig != 0) {
    RollBackOutputs({entries.begin(), entries.begin() + long(renamed)});
    for (size_t i = renamed; i < entries.size(); ++i) {
      if (!entries[i].backup.empty()) unlink(entries[i].backup.c_str());  // never replaced
    }
    journal.Remove();
  } else {
    journal.Committed();
    for (const JournalEntry& e : entries) {
      if (!e.backup.empty()) unlink(e.backup.c_str());
    }
    journal.Remove();
  }
  for (const Staged& s : staged_) SyncFolder(fs::path(s.target).parent_path());
  if (sig != 0) {
    state.store(2);
    TerminateFromCommit(sig);
  }
  if (failure.empty()) {
    committed_ = true;
    for (int slot : slots_) Unregister(slot);
    slots_.clear();
  }
  state.store(0);
  // A handler in another thread may have deferred a signal after
  // HeldSignal() looked (it took the signal a moment before running): the
  // commit is complete (or rolled back), so that signal ends the run now
  // rather than being lost.
  if (const int late = deferred_signal.exchange(0)) TerminateFromCommit(late);
  if (!failure.empty()) {
    const Staged& s = staged_[failed];
    throw InputError(s.target, 0, s.key, failure + " (every output keeps its old content)");
  }
}

void WriteTextFile(const std::string& path, const std::string& text, const std::string& key) {
  std::FILE* file = FopenNoFollow(path);
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
