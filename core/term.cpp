// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/term.h"

#include "core/batch.h"

namespace archgeo {

double TermContext::Option(const std::string& option, bool boolean) const {
  for (const auto& [name, value] : options_) {
    if (name == option) return value;
  }
  const std::string key = "terms." + term_name() + "." + option;
  const double value = boolean ? double(settings().Bool(key)) : settings().Number(key);
  options_.emplace_back(option, value);
  return value;
}

double TermContext::Number(const std::string& option) const { return Option(option, false); }

long long TermContext::Integer(const std::string& option) const {
  return settings().Integer("terms." + term_name() + "." + option);
}

bool TermContext::Bool(const std::string& option) const { return Option(option, true) != 0.0; }

const std::string& TermContext::String(const std::string& option) const {
  return settings().String("terms." + term_name() + "." + option);
}

Batch* TermContext::FindBatch(const void* key, double band) const {
  for (const Kept& k : batches_) {
    if (k.key == key && k.band == band) return k.batch;
  }
  return nullptr;
}

Batch* TermContext::KeepBatch(const void* key, double band, std::unique_ptr<Batch> batch) {
  Batch* kept = Keep(std::move(batch));
  batches_.push_back({key, band, kept});
  return kept;
}

}  // namespace archgeo
