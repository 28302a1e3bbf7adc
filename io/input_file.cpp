// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — opening user input files: regular files only (see input_file.h).
#include "io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/input_error.h"

namespace archgeo {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& key,
                       const std::string& message) {
  throw InputError(path, 0, key, message);
}

// What the file type in `mode` is, for "not a regular file" messages.
const char* KindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  return "not a regular file";
}

void RequireRegular(const std::string& path, const std::string& key, const struct stat& info) {
  if (!S_ISREG(info.st_mode)) {
    Fail(path, key,
         std::string("cannot read it: it is ") + KindOf(info.st_mode) +
             "; archgeo reads regular files only");
  }
}

// Closes the descriptor when it goes out of scope.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Opens `path` read-only without blocking (a FIFO without a writer, a
// terminal) and checks that what was opened is a regular file.
int OpenRegular(const std::string& path, const std::string& key, struct stat* info) {
  struct stat before;
  if (::stat(path.c_str(), &before) != 0) {
    Fail(path, key, std::string("cannot open: ") + std::strerror(errno));
  }
  RequireRegular(path, key, before);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) Fail(path, key, std::string("cannot open: ") + std::strerror(errno));
  if (::fstat(fd, info) != 0) {
    const int error = errno;
    ::close(fd);
    Fail(path, key, std::string("cannot open: ") + std::strerror(error));
  }
  if (!S_ISREG(info->st_mode)) {
    ::close(fd);
    RequireRegular(path, key, *info);
  }
  return fd;
}

}  // namespace

void CheckRegularInputFile(const std::string& path, const std::string& key) {
  struct stat info;
  Descriptor fd(OpenRegular(path, key, &info));
}

std::string ReadInputFile(const std::string& path, const std::string& key,
                          std::uint64_t max_bytes, const std::string& limit_key) {
  struct stat info;
  Descriptor fd(OpenRegular(path, key, &info));
  const auto too_large = [&](const std::string& size) {
    Fail(path, key,
         "the file has " + size + " bytes, more than the limit of " + std::to_string(max_bytes) +
             (limit_key.empty() ? std::string() : " (" + limit_key + "; raise it if the file is "
                                                      "really that large)"));
  };
  const std::uint64_t size = info.st_size > 0 ? static_cast<std::uint64_t>(info.st_size) : 0;
  if (size > max_bytes) too_large(std::to_string(size));
  // Regular files do not block; clear O_NONBLOCK anyway so reads are plain.
  const int flags = ::fcntl(fd.get(), F_GETFL);
  if (flags >= 0) ::fcntl(fd.get(), F_SETFL, flags & ~O_NONBLOCK);

  std::string content;
  content.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      Fail(path, key, std::string("cannot read the file: ") + std::strerror(errno));
    }
    if (n == 0) break;
    // The file may grow while it is read (or report no size, as in /proc).
    if (content.size() + static_cast<std::uint64_t>(n) > max_bytes) {
      too_large("more than " + std::to_string(max_bytes));
    }
    content.append(buffer, static_cast<std::size_t>(n));
  }
  return content;
}

}  // namespace archgeo
