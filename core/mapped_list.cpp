// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — MappedList's mappings (see mapped_list.h).
#include "core/mapped_list.h"

#include <sys/mman.h>
#include <unistd.h>

namespace archgeo::mapped_list {

size_t PageRound(size_t bytes) {
  static const size_t page = size_t(sysconf(_SC_PAGESIZE));
  return (bytes + page - 1) / page * page;
}

void Unmap(void* data, size_t bytes) {
  if (data) munmap(data, bytes);
}

void* Resize(void* old, size_t old_bytes, size_t bytes) {
  if (bytes == 0) {
    Unmap(old, old_bytes);
    return nullptr;
  }
  void* data = old ? mremap(old, old_bytes, bytes, MREMAP_MAYMOVE)
                   : mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                          -1, 0);
  if (data == MAP_FAILED) throw std::bad_alloc();
  return data;
}

}  // namespace archgeo::mapped_list
