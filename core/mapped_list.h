// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — MappedList<T>: a list of trivially copyable values in its own
// memory mapping, for the loop's lists of hundreds of MB (core/residuals.h:
// ~30 residual blocks and ~100 parameter entries per quad). It grows by
// mremap, which moves the pages instead of copying them (a growing
// std::vector copies and faults in every page again at each growth step).
// The mapping uses normal pages: the serial trial cost streams these lists,
// and it is slower over transparent huge pages.
//
// Clear keeps the pages (the next round writes the same amount again); Fit
// returns the pages past the end to the system without moving anything.
#pragma once

#include <cstddef>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace archgeo {

namespace mapped_list {
// The mapping of `bytes` (a multiple of the page size; 0: none) that holds
// the `old_bytes` at `old` (nullptr: none yet), moved or grown in place;
// throws std::bad_alloc when the system has no memory for it.
void* Resize(void* old, size_t old_bytes, size_t bytes);
void Unmap(void* data, size_t bytes);
size_t PageRound(size_t bytes);
}  // namespace mapped_list

template <class T>
class MappedList {
  static_assert(std::is_trivially_copyable_v<T>, "MappedList moves its pages, not its values");

 public:
  MappedList() = default;
  ~MappedList() { mapped_list::Unmap(data_, bytes_); }
  MappedList(const MappedList&) = delete;
  MappedList& operator=(const MappedList&) = delete;
  MappedList(MappedList&& other) noexcept { Swap(other); }
  MappedList& operator=(MappedList&& other) noexcept {
    MappedList gone;
    gone.Swap(other);  // `other` is left empty, this list's mapping goes with `gone`
    Swap(gone);
    return *this;
  }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T* data() const { return data_; }
  T* data() { return data_; }
  const T& operator[](size_t i) const { return data_[i]; }
  T& operator[](size_t i) { return data_[i]; }
  const T& back() const { return data_[size_ - 1]; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }

  void push_back(const T& value) {
    if (size_ == capacity_) Reserve(size_ + 1);
    std::memcpy(static_cast<void*>(data_ + size_), &value, sizeof(T));
    ++size_;
  }
  void clear() { size_ = 0; }
  // `n` values; the new ones are unspecified (zero on pages never written).
  void Resize(size_t n) {
    if (n > capacity_) Map(n);
    size_ = n;
  }
  // Returns the pages past the end.
  void Fit() { Map(size_); }

 private:
  void Swap(MappedList& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
    std::swap(bytes_, other.bytes_);
  }
  // Room for at least `n` values: twice as much as now at least.
  void Reserve(size_t n) { Map(n > 2 * capacity_ ? n : 2 * capacity_ + 1); }
  void Map(size_t n) {
    const size_t bytes = mapped_list::PageRound(n * sizeof(T));
    if (bytes == bytes_) return;
    data_ = static_cast<T*>(mapped_list::Resize(data_, bytes_, bytes));
    bytes_ = bytes;
    capacity_ = bytes / sizeof(T);
  }

  T* data_ = nullptr;
  size_t size_ = 0, capacity_ = 0, bytes_ = 0;
};

}  // namespace archgeo
