// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/custom_value.h"

namespace archgeo {

const CustomValue* CustomValue::Find(const std::string& key) const {
  for (const Entry& e : entries) {
    if (e.key.IsScalar() && e.key.text == key) return &e.value;
  }
  return nullptr;
}

std::string CustomValue::Describe() const {
  switch (kind) {
    case Kind::kScalar:
      return "'" + text + "'";
    case Kind::kList:
      return "a list";
    case Kind::kMap:
      return "a mapping";
    case Kind::kNull:
      break;
  }
  return "nothing";
}

}  // namespace archgeo
