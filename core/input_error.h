// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — user-input errors.
//
// Every problem with a user's input (a mesh file, a YAML spec, a command-line
// value) is reported as an InputError naming the file, and where known the line
// and the key. tools/ turns it into exit code 2. Programmer invariants use
// glog's CHECK instead.
#pragma once

#include <stdexcept>
#include <string>

namespace archgeo {

class InputError : public std::runtime_error {
 public:
  // `file` is the path as the user gave it; `line` is 1-based (0 = unknown);
  // `key` is a dotted YAML path or a command-line option ("" = none).
  InputError(std::string file, int line, std::string key, const std::string& message)
      : std::runtime_error(Format(file, line, key, message)),
        file_(std::move(file)), line_(line), key_(std::move(key)), message_(message) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }  // without file, line and key

 private:
  static std::string Format(const std::string& file, int line, const std::string& key,
                            const std::string& message) {
    std::string s = file.empty() ? std::string("input") : file;
    if (line > 0) s += ":" + std::to_string(line);
    if (!key.empty()) s += ": key '" + key + "'";
    return s + ": " + message;
  }
  std::string file_;
  int line_;
  std::string key_;
  std::string message_;
};

}  // namespace archgeo
