// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — files opened for writing that are never reached through a
// symbolic link.
//
// Every writer (meshes, reports, pictures, pages) opens its file through
// these, never by std::ofstream or fopen: the last component of the path is
// opened with O_NOFOLLOW, so a staged temporary that someone swapped for a
// symbolic link after Stage() created it (io/output_files.h) is an error
// (ELOOP), not a write into the link's target. Header-only: render/ uses it
// without linking io/.
#pragma once

#include <ext/stdio_filebuf.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <ios>
#include <ostream>
#include <string>

namespace archgeo {

// open(2) of `path` for writing, created if missing and truncated, without
// following a symbolic link in its last component: a file descriptor, or -1
// with errno set (ELOOP for a symbolic link).
inline int OpenNoFollow(const std::string& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY,
                0666);
}

// OpenNoFollow() as a stdio stream ("wb"); nullptr with errno set.
inline std::FILE* FopenNoFollow(const std::string& path) {
  const int fd = OpenNoFollow(path);
  if (fd < 0) return nullptr;
  std::FILE* file = ::fdopen(fd, "wb");
  if (file == nullptr) ::close(fd);
  return file;
}

// An std::ofstream in binary mode opened by OpenNoFollow(): `!stream` after
// construction when the open failed (errno set), and close() sets failbit
// when the last write-back fails.
class NoFollowOfstream : public std::ostream {
 public:
  explicit NoFollowOfstream(const std::string& path)
      : std::ostream(nullptr), fd_(OpenNoFollow(path)), error_(fd_ < 0 ? errno : 0),
        buffer_(fd_, std::ios::out | std::ios::binary) {
    if (fd_ < 0) {
      errno = error_;  // the open's, not the buffer's
      setstate(std::ios::failbit);
    } else {
      rdbuf(&buffer_);
    }
  }
  void close() {
    if (fd_ >= 0 && buffer_.close() == nullptr) setstate(std::ios::failbit);
    fd_ = -1;
  }

 private:
  int fd_;
  int error_;
  __gnu_cxx::stdio_filebuf<char> buffer_;
};

}  // namespace archgeo
