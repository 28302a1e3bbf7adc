// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — opening user input files: regular files only.
//
// Every file archgeo reads on the user's behalf (the mesh, the reference, the
// YAML spec, the principal-edges file) goes through one of these two
// functions, so a path that names something other than a regular file is
// refused at once with an InputError instead of blocking or reading forever:
// a FIFO (named pipe: opening it waits for a writer), a character device
// (/dev/zero never ends, /dev/tty waits for input), a block device, a socket,
// a directory. Symbolic links are followed; what they point to is checked.
#pragma once

#include <cstdint>
#include <string>

namespace archgeo {

// Throws InputError(path, 0, key, ...) unless `path` names an existing
// regular file that this process can open for reading. It does not block:
// it stats the path (refusing FIFOs, devices, sockets, directories and
// missing paths by name) and then opens and closes it with O_NONBLOCK. Use it
// before handing a path to a reader that opens the file itself (std::ifstream,
// YAML::LoadFile); `key` is the spec key or option that named the file
// ("" for the spec file itself).
void CheckRegularInputFile(const std::string& path, const std::string& key = "");

// The whole content of the regular file at `path`. Opens with O_NONBLOCK and
// checks the open descriptor (fstat), so a FIFO or device swapped in after an
// earlier check cannot block it either, then reads to the end. Throws
// InputError(path, 0, key, ...) for everything CheckRegularInputFile refuses,
// for a read error, and for a file larger than `max_bytes` (the message names
// `limit_key`, the spec key that raises the bound, if not empty).
std::string ReadInputFile(const std::string& path, const std::string& key = "",
                          std::uint64_t max_bytes = std::uint64_t{8} << 30,
                          const std::string& limit_key = "limits.max_file_bytes");

}  // namespace archgeo
