#include "problems/analysis.h"

#include <cstdio>

namespace archgeo {
namespace {

// Pads to `width` characters as displayed (UTF-8 code points, not bytes).
std::string Pad(const std::string& text, size_t width) {
  size_t shown = 0;
  for (unsigned char c : text) shown += (c & 0xC0) != 0x80;
  return text + std::string(width > shown ? width - shown : 0, ' ');
}

std::string Cell(const AnalysisRow& row, double scale) {
  char buf[64];
  switch (row.kind) {
    case AnalysisRow::Kind::kLength:
      std::snprintf(buf, sizeof buf, "%.4e (%.3e)", row.value, row.value / scale);
      break;
    case AnalysisRow::Kind::kDegrees:
      std::snprintf(buf, sizeof buf, "%.4g°", row.value);
      break;
    case AnalysisRow::Kind::kCount:
      std::snprintf(buf, sizeof buf, "%.0f", row.value);
      break;
    case AnalysisRow::Kind::kRatio:
      std::snprintf(buf, sizeof buf, "%.4e", row.value);
      break;
  }
  return buf;
}

}  // namespace

std::set<std::string> ApplicableAnalyses(const Mesh& mesh) {
  std::set<std::string> names;
  return names;
}

AnalysisRows Analyse(const Mesh& mesh, const std::set<std::string>& names) {
  AnalysisRows rows;
  return rows;
}

void AnalysisToJson(const AnalysisRows& rows, double scale, nlohmann::json& json) {
  for (const AnalysisRow& row : rows) {
    json[row.key] = row.value;
    if (row.kind == AnalysisRow::Kind::kLength) json[row.key + "_relative"] = row.value / scale;
  }
}

std::string FormatAnalysis(const AnalysisRows& before, const AnalysisRows* after, double scale) {
  std::string out;
  for (const AnalysisRow& row : before) {
    std::string a;
    if (after) {
      for (const AnalysisRow& r : *after) {
        if (r.key == row.key) a = Cell(r, scale);
      }
    }
    out += Pad(row.label, 32) + Pad(Cell(row, scale), 26) + a + "\n";
  }
  if (after) {  // rows only after (e.g. a quantity undefined before)
    for (const AnalysisRow& r : *after) {
      bool seen = false;
      for (const AnalysisRow& b : before) seen |= b.key == r.key;
      if (!seen) out += Pad(r.label, 32) + Pad("-", 26) + Cell(r, scale) + "\n";
    }
  }
  return out;
}

}  // namespace archgeo
