// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the lexical layer of the mesh readers (no CGAL): lines, tokens,
// numbers and the messages the readers share.
//
// Used by the OBJ, OFF and PLY parsers (io/soup_readers.h). Messages number
// vertices and faces from 0, in file order; lines from 1 (0 = unknown).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace archgeo {

// 1-based lines of the vertex and face records of an ASCII file (empty for
// binary files); used only to point messages at the file.
struct LineMap {
  std::vector<int> vertex, face;
  int Vertex(std::size_t i) const { return i < vertex.size() ? vertex[i] : 0; }
  int Face(std::size_t i) const { return i < face.size() ? face[i] : 0; }
};

// Throws InputError for `path` at 1-based `line` (0 = unknown), no key.
[[noreturn]] void FailInput(const std::string& path, int line, const std::string& message);

// `token` in single quotes, for messages: at most 40 characters (longer ones
// are cut, marked "..."), bytes outside printable ASCII written as \xNN.
std::string QuoteToken(std::string_view token);

// "empty mesh" message for a file with `vertices` vertices and no faces.
std::string NoFacesMessage(std::size_t vertices);

// Message for face `face` (0-based) referring to a vertex index outside a
// file with `vertices` vertices.
std::string OutOfRangeMessage(std::size_t face, std::size_t vertices);

// Message for a count beyond a ReadLimits bound: "<what> <count>, more than
// the limit of <limit> (<key>; ...)", e.g. what = "the header declares
// 200000000 vertices".
std::string LimitMessage(const std::string& what, std::uint64_t limit, const std::string& key);

// Walks a text line by line (lines numbered from 1), splitting each line into
// tokens separated by whitespace ('\r' included). With `hash_comments`, '#'
// starts a comment that runs to the end of the line (OBJ, OFF).
class LineReader {
 public:
  explicit LineReader(std::string_view text, bool hash_comments = true)
      : text_(text), hash_comments_(hash_comments) {}

  // Advances to the next line with at least one token; false at the end.
  bool Next();
  int line() const { return line_; }
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  // Offset of the first byte after the current line (after its '\n').
  std::size_t end_offset() const { return pos_; }

 private:
  std::string_view text_;
  bool hash_comments_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::vector<std::string_view> tokens_;
};

// Reads fixed-size numbers (integers, IEEE floats) from binary data in the
// given byte order, never past its end.
class ByteReader {
 public:
  ByteReader(std::string_view data, std::size_t offset, bool big_endian)
      : data_(data), offset_(std::min(offset, data.size())), big_endian_(big_endian) {}

  std::size_t offset() const { return offset_; }
  std::size_t remaining() const { return data_.size() - offset_; }

  // Reads one T; false (nothing read) if fewer than sizeof(T) bytes remain.
  template <typename T>
  bool Read(T* value) {
    if (remaining() < sizeof(T)) return false;
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, data_.data() + offset_, sizeof(T));
    const bool host_big_endian = IsHostBigEndian();
    if (big_endian_ != host_big_endian) std::reverse(bytes, bytes + sizeof(T));
    std::memcpy(value, bytes, sizeof(T));
    offset_ += sizeof(T);
    return true;
  }

  // Skips `bytes` bytes; false (nothing skipped) if fewer remain.
  bool Skip(std::uint64_t bytes) {
    if (remaining() < bytes) return false;
    offset_ += static_cast<std::size_t>(bytes);
    return true;
  }

 private:
  static bool IsHostBigEndian() {
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    return first == 0;
  }
  std::string_view data_;
  std::size_t offset_;
  bool big_endian_;
};

// The whole token as a decimal integer (an optional leading '+' or '-'), or
// nothing (not an integer, or beyond the range of long long).
std::optional<long long> ParseInteger(std::string_view token);

enum class NumberParse { kOk, kNotANumber, kNonFinite };

// The whole token as a decimal floating-point number (C locale, optional
// sign, exponent; no hexadecimal), correctly rounded. kNonFinite for "nan",
// "inf" and numbers beyond the double range; a number below it reads as 0 or
// a denormal.
NumberParse ParseDouble(std::string_view token, double* value);

// Parses tokens[first..] as the coordinates of vertex `index` (at `line`):
// at least `needed` (3 or 4) tokens, each a finite number; the first
// `needed` are stored in `values`. Throws InputError naming `path` and `line`.
void ParseVertexTokens(const std::string& path, int line, std::size_t index,
                       const std::vector<std::string_view>& tokens, std::size_t first,
                       std::size_t needed, double* values);

// a * b and a + b, saturating at UINT64_MAX (for comparing declared counts
// with file sizes without overflow).
std::uint64_t SaturatingMul(std::uint64_t a, std::uint64_t b);
std::uint64_t SaturatingAdd(std::uint64_t a, std::uint64_t b);

}  // namespace archgeo
