// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the lexical layer of the mesh readers (see text_scan.h).
#include "io/text_scan.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "core/input_error.h"

namespace archgeo {

[[noreturn]] void FailInput(const std::string& path, int line, const std::string& message) {
  throw InputError(path, line, "", message);
}

std::string QuoteToken(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string quoted = "'";
  for (std::size_t i = 0; i < token.size() && i < kShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      quoted.push_back(static_cast<char>(c));
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      quoted += hex;
    }
  }
  if (token.size() > kShown) quoted += "...";
  return quoted + "'";
}

std::string NoFacesMessage(std::size_t vertices) {
  return "empty mesh: the file has " + std::to_string(vertices) + " vertices but no faces";
}

std::string OutOfRangeMessage(std::size_t face, std::size_t vertices) {
  return "face " + std::to_string(face) + " refers to a vertex index out of range (the file has " +
         std::to_string(vertices) + " vertices)";
}

std::string LimitMessage(const std::string& what, std::uint64_t limit, const std::string& key) {
  return what + ", more than the limit of " + std::to_string(limit) + " (" + key +
         "; raise it in the spec if the mesh is really that large)";
}

bool LineReader::Next() {
  while (pos_ < text_.size()) {
    const std::size_t newline = text_.find('\n', pos_);
    const std::size_t end = newline == std::string_view::npos ? text_.size() : newline;
    std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = newline == std::string_view::npos ? text_.size() : end + 1;
    ++line_;
    if (hash_comments_) line = line.substr(0, line.find('#'));
    tokens_.clear();
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      const std::size_t start = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i > start) tokens_.push_back(line.substr(start, i - start));
    }
    if (!tokens_.empty()) return true;
  }
  return false;
}

std::optional<long long> ParseInteger(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  long long value = 0;
  const char* end = token.data() + token.size();
  const auto [ptr, error] = std::from_chars(token.data(), end, value);
  if (error != std::errc() || ptr != end) return std::nullopt;
  return value;
}

NumberParse ParseDouble(std::string_view token, double* value) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, error] = std::from_chars(token.data(), end, *value);
  if (ptr != end || token.empty()) return NumberParse::kNotANumber;
  if (error == std::errc::result_out_of_range) {
    // Overflow or underflow: strtod tells them apart (±HUGE_VAL or a tiny value).
    const std::string copy(token);
    *value = std::strtod(copy.c_str(), nullptr);
  } else if (error != std::errc()) {
    return NumberParse::kNotANumber;
  }
  return std::isfinite(*value) ? NumberParse::kOk : NumberParse::kNonFinite;
}

void ParseVertexTokens(const std::string& path, int line, std::size_t index,
                       const std::vector<std::string_view>& tokens, std::size_t first,
                       std::size_t needed, double* values) {
  const std::string vertex = "vertex " + std::to_string(index);
  if (tokens.size() < first + needed) {
    FailInput(path, line,
              vertex + " has " + std::to_string(tokens.size() - first) + " coordinates; expected " +
                  std::to_string(needed));
  }
  for (std::size_t k = first; k < tokens.size(); ++k) {
    double value = 0;
    switch (ParseDouble(tokens[k], &value)) {
      case NumberParse::kNotANumber:
        FailInput(path, line, "cannot parse " + QuoteToken(tokens[k]) + " as a number in " + vertex);
      case NumberParse::kNonFinite:
        FailInput(path, line, "non-finite coordinate " + QuoteToken(tokens[k]) + " in " + vertex);
      case NumberParse::kOk:
        break;
    }
    if (k < first + needed) values[k - first] = value;
  }
}

std::uint64_t SaturatingMul(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) {
    return std::numeric_limits<std::uint64_t>::max();
  }
  return a * b;
}

std::uint64_t SaturatingAdd(std::uint64_t a, std::uint64_t b) {
  return b > std::numeric_limits<std::uint64_t>::max() - a
             ? std::numeric_limits<std::uint64_t>::max()
             : a + b;
}

}  // namespace archgeo
