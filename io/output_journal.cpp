// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the commit journal and the recovery of killed commits (see
// io/output_journal.h).
#include "io/output_journal.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <set>
#include <system_error>

namespace archgeo {
namespace {

namespace fs = std::filesystem;

constexpr size_t kTokenLength = 12;
constexpr char kJournalPrefix[] = ".archgeo-commit-";
constexpr char kJournalMagic[] = "archgeo-commit 1";

bool IsTokenChar(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); }

// Parses "<pid>-<token>" at `at`: the position after it, or npos.
size_t ParsePidToken(const std::string& s, size_t at, pid_t* pid, std::string* token) {
  size_t digits = at;
  while (digits < s.size() && digits - at < 9 && s[digits] >= '0' && s[digits] <= '9') ++digits;
  if (digits == at || digits >= s.size() || s[digits] != '-') return std::string::npos;
  const size_t start = digits + 1;
  if (start + kTokenLength > s.size()) return std::string::npos;
  for (size_t i = start; i < start + kTokenLength; ++i) {
    if (!IsTokenChar(s[i])) return std::string::npos;
  }
  *pid = pid_t(std::stol(s.substr(at, digits - at)));
  *token = s.substr(start, kTokenLength);
  return start + kTokenLength;
}

bool ProcessAlive(pid_t pid) {
  return pid == getpid() || kill(pid, 0) == 0 || errno == EPERM;
}

bool OwnRegularFile(const std::string& path) {
  struct stat info;
  return lstat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && info.st_uid == geteuid();
}

void SyncJournalFolder(const std::string& path) {
  const std::string folder = fs::path(path).parent_path().string();
  const int fd = open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  fsync(fd);
  close(fd);
}

// Fields separated by NUL (paths may hold any other byte).
std::string Serialize(const std::vector<std::string>& copies,
                      const std::vector<JournalEntry>& entries) {
  std::string out;
  const auto put = [&out](const std::string& field) { out += field + '\0'; };
  put(kJournalMagic);
  put(std::to_string(copies.size()));
  for (const std::string& c : copies) put(c);
  put(std::to_string(entries.size()));
  for (const JournalEntry& e : entries) {
    put(e.target), put(e.temporary), put(e.backup);
    put(std::to_string(e.device)), put(std::to_string(e.inode));
  }
  put("end");
  return out;
}

// False for a journal that is not complete (its writer died while writing
// it: before any backup or rename).
bool ReadJournal(const std::string& path, std::vector<std::string>* copies,
                 std::vector<JournalEntry>* entries) {
  const int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return false;
  std::string text;
  char buffer[4096];
  ssize_t n;
  while ((n = read(fd, buffer, sizeof buffer)) > 0) text.append(buffer, size_t(n));
  close(fd);
  std::vector<std::string> fields;
  for (size_t at = 0, end; (end = text.find('\0', at)) != std::string::npos; at = end + 1) {
    fields.push_back(text.substr(at, end - at));
  }
  if (fields.size() < 4 || fields.front() != kJournalMagic || fields.back() != "end") return false;
  try {
    size_t at = 1;
    const size_t n_copies = std::stoul(fields.at(at++));
    for (size_t i = 0; i < n_copies; ++i) copies->push_back(fields.at(at++));
    const size_t n_entries = std::stoul(fields.at(at++));
    for (size_t i = 0; i < n_entries; ++i) {
      JournalEntry e;
      e.target = fields.at(at++), e.temporary = fields.at(at++), e.backup = fields.at(at++);
      e.device = std::stoull(fields.at(at++)), e.inode = std::stoull(fields.at(at++));
      entries->push_back(e);
    }
    return !copies->empty() && at + 1 == fields.size();
  } catch (const std::exception&) {
    return false;
  }
}

bool SameInode(const struct stat& info, std::uint64_t device, std::uint64_t inode) {
  return std::uint64_t(info.st_dev) == device && std::uint64_t(info.st_ino) == inode;
}

void RecoverJournal(const std::string& path) {
  std::vector<std::string> copies;
  std::vector<JournalEntry> entries;
  if (!ReadJournal(path, &copies, &entries)) {
    unlink(path.c_str());
    return;
  }
  struct stat info;
  if (lstat(copies.back().c_str(), &info) == 0) {
    RollBackOutputs(entries);  // the commit did not reach its commit point
  } else {
    for (const JournalEntry& e : entries) {
      if (!e.backup.empty() && OwnRegularFile(e.backup)) unlink(e.backup.c_str());
    }
  }
  for (const std::string& c : copies) {
    unlink(c.c_str());
    SyncJournalFolder(c);
  }
  unlink(path.c_str());
}

// The names in `folder` (none if it cannot be read).
std::vector<std::string> NamesIn(const std::string& folder) {
  std::vector<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(folder.empty() ? "." : folder, error), end; !error && it != end;
       it.increment(error)) {
    names.push_back(it->path().filename().string());
  }
  return names;
}

// A temporary `<stem>.tmp-<pid>-<token><extension>` or a backup
// `<target>.bak-<pid>-<token>` of a process that is not alive.
bool DeadProcessFile(const std::string& name, std::string* token, bool* backup) {
  pid_t pid = 0;
  for (size_t at = name.find(".tmp-"); at != std::string::npos; at = name.find(".tmp-", at + 1)) {
    if (ParsePidToken(name, at + 5, &pid, token) != std::string::npos) {
      *backup = false;
      return !ProcessAlive(pid);
    }
  }
  const size_t at = name.rfind(".bak-");
  if (at != std::string::npos && ParsePidToken(name, at + 5, &pid, token) == name.size()) {
    *backup = true;
    return !ProcessAlive(pid);
  }
  return false;
}

}  // namespace

std::string RandomToken() {
  unsigned char bytes[kTokenLength];
  size_t got = 0;
  while (got < sizeof bytes) {
    const ssize_t n = getrandom(bytes + got, sizeof bytes - got, 0);
    if (n > 0) got += size_t(n);
  }
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::string token;
  for (unsigned char b : bytes) token += kAlphabet[b % 36];
  return token;
}

std::string TemporaryMark(const std::string& token) {
  return ".tmp-" + std::to_string(getpid()) + "-" + token;
}

std::string BackupMark(const std::string& token) {
  return ".bak-" + std::to_string(getpid()) + "-" + token;
}

bool CommitJournal::Write(const std::vector<JournalEntry>& entries, const std::string& token) {
  std::vector<std::string> folders;
  for (const JournalEntry& e : entries) {
    const std::string folder = fs::path(e.target).parent_path().string();
    if (std::find(folders.begin(), folders.end(), folder) == folders.end()) {
      folders.push_back(folder);
    }
  }
  if (folders.empty()) return true;
  std::rotate(folders.begin(), folders.begin() + 1, folders.end());  // the primary last
  std::vector<std::string> copies;
  const std::string name = kJournalPrefix + std::to_string(getpid()) + "-" + token;
  for (const std::string& f : folders) copies.push_back((fs::path(f) / name).string());
  const std::string text = Serialize(copies, entries);
  for (const std::string& c : copies) {
    const int fd = open(c.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) break;
    copies_.push_back(c);
    const bool written = ::write(fd, text.data(), text.size()) == ssize_t(text.size()) &&
                         fsync(fd) == 0;
    const int saved = errno;
    if (close(fd) != 0 || !written) {
      errno = written ? errno : saved;
      break;
    }
    SyncJournalFolder(c);
  }
  if (copies_.size() == copies.size()) return true;
  const int saved = errno;
  Remove();
  errno = saved;
  return false;
}

void CommitJournal::Committed() {
  if (copies_.empty()) return;
  unlink(copies_.back().c_str());
  SyncJournalFolder(copies_.back());
  copies_.pop_back();
}

void CommitJournal::Remove() {
  for (const std::string& c : copies_) unlink(c.c_str());
  copies_.clear();
}

void RollBackOutputs(const std::vector<JournalEntry>& entries) {
  for (const JournalEntry& e : entries) {
    struct stat target, backup, temporary;
    const bool has_target = lstat(e.target.c_str(), &target) == 0;
    if (!e.backup.empty()) {
      if (lstat(e.backup.c_str(), &backup) == 0) {
        if (has_target && SameInode(target, backup.st_dev, backup.st_ino)) {
          unlink(e.backup.c_str());  // never replaced
        } else {
          rename(e.backup.c_str(), e.target.c_str());
        }
      }
    } else if (has_target && SameInode(target, e.device, e.inode)) {
      unlink(e.target.c_str());  // new, had no old version
    }
    if (lstat(e.temporary.c_str(), &temporary) == 0 && SameInode(temporary, e.device, e.inode)) {
      unlink(e.temporary.c_str());
    }
    SyncJournalFolder(e.target);
  }
}

void RecoverOutputs(const std::string& folder) {
  const fs::path dir(folder.empty() ? "." : folder);
  for (const std::string& name : NamesIn(folder)) {
    pid_t pid = 0;
    std::string token;
    const size_t prefix = sizeof kJournalPrefix - 1;
    if (name.compare(0, prefix, kJournalPrefix) != 0 ||
        ParsePidToken(name, prefix, &pid, &token) != name.size() || ProcessAlive(pid)) {
      continue;
    }
    const std::string path = (dir / name).string();
    if (OwnRegularFile(path)) RecoverJournal(path);
  }
  std::set<std::string> journals;  // tokens of the journals still here
  const std::vector<std::string> names = NamesIn(folder);
  for (const std::string& name : names) {
    if (name.compare(0, sizeof kJournalPrefix - 1, kJournalPrefix) == 0 &&
        name.size() >= kTokenLength) {
      journals.insert(name.substr(name.size() - kTokenLength));
    }
  }
  for (const std::string& name : names) {
    std::string token;
    bool backup = false;
    if (!DeadProcessFile(name, &token, &backup) || (backup && journals.count(token))) continue;
    const std::string path = (dir / name).string();
    if (OwnRegularFile(path)) unlink(path.c_str());
  }
}

}  // namespace archgeo
