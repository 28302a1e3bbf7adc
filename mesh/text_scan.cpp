// archgeo — plain-text pre-scan of ASCII OBJ/OFF/PLY mesh files (see text_scan.h).
#include "mesh/text_scan.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include "mesh/input_error.h"

namespace archgeo {

[[noreturn]] void FailInput(const std::string& path, int line, const std::string& message) {
  throw InputError(path, line, "", message);
}

std::string QuoteToken(std::string_view token) { return "'" + std::string(token) + "'"; }

std::string NoFacesMessage(std::size_t vertices) {
  return "empty mesh: the file has " + std::to_string(vertices) + " vertices but no faces";
}

std::string OutOfRangeMessage(std::size_t face, std::size_t vertices) {
  return "face " + std::to_string(face) + " refers to a vertex index out of range (the file has " +
         std::to_string(vertices) + " vertices)";
}

namespace {

// Walks a text line by line (lines numbered from 1), dropping '#' comments
// and splitting the rest into whitespace-separated tokens ('\r' included).
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  // Advances to the next line with at least one token; false at the end.
  bool Next() {
    while (pos_ < text_.size()) {
      std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      line = line.substr(0, line.find('#'));
      tokens_.clear();
      for (std::size_t i = 0; i < line.size();) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) tokens_.push_back(line.substr(start, i - start));
      }
      if (!tokens_.empty()) return true;
    }
    return false;
  }
  int line() const { return line_; }
  const std::vector<std::string_view>& tokens() const { return tokens_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::vector<std::string_view> tokens_;
};

// The whole token as a decimal integer, or nothing.
std::optional<long long> ParseInteger(std::string_view token) {
  long long value = 0;
  const char* end = token.data() + token.size();
  auto [ptr, error] = std::from_chars(token.data(), end, value);
  if (error != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// Checks the values tokens[first..] of vertex `index` (at `line`): at least
// three, each a finite number.
void CheckVertexTokens(const std::string& path, int line, std::size_t index,
                       const std::vector<std::string_view>& tokens, std::size_t first) {
  const std::string vertex = "vertex " + std::to_string(index);
  if (tokens.size() < first + 3) {
    FailInput(
        path, line,
        vertex + " has " + std::to_string(tokens.size() - first) + " coordinates; expected 3");
  }
  for (std::size_t k = first; k < tokens.size(); ++k) {
    const std::string token(tokens[k]);
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') {
      FailInput(path, line, "cannot parse " + QuoteToken(token) + " as a number in " + vertex);
    }
    if (!std::isfinite(value))
      FailInput(path, line, "non-finite coordinate " + QuoteToken(token) + " in " + vertex);
  }
}

void FailIndex(const std::string& path, int line, std::string_view token, std::size_t face) {
  FailInput(
      path, line,
      "cannot parse " + QuoteToken(token) + " as a vertex index in face " + std::to_string(face));
}

void AppendLine(const std::vector<std::string_view>& tokens, std::string* out) {
  for (std::string_view token : tokens) {
    out->append(token);
    out->push_back(' ');
  }
  out->back() = '\n';
}

}  // namespace

// OBJ: `v` and `f` records. Tabs become spaces in `text`: CGAL's OBJ reader
// skips from one face index to the next by looking for a space.
LineMap ScanObj(const std::string& path, std::string* text) {
  LineMap lines;
  for (LineReader reader(*text); reader.Next();) {
    const auto& tokens = reader.tokens();
    if (tokens[0] == "v") {
      CheckVertexTokens(path, reader.line(), lines.vertex.size(), tokens, 1);
      lines.vertex.push_back(reader.line());
    } else if (tokens[0] == "f") {
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view index = tokens[k].substr(0, tokens[k].find('/'));
        const auto value = ParseInteger(index);
        if (!value || *value == 0) FailIndex(path, reader.line(), tokens[k], lines.face.size());
      }
      lines.face.push_back(reader.line());
    }
  }
  if (lines.face.empty()) FailInput(path, 0, NoFacesMessage(lines.vertex.size()));
  std::replace(text->begin(), text->end(), '\t', ' ');
  return lines;
}

// OFF: the header, then one vertex per line, then faces "n i1 ... in [colour]"
// whose indices may wrap onto following lines. ASCII `text` is rewritten with
// one record per line and no comments; binary OFF is left to CGAL.
LineMap ScanOff(const std::string& path, std::string* text) {
  LineMap lines;
  LineReader reader(*text);
  if (!reader.Next()) FailInput(path, 0, "not an OFF file: no header");
  const std::string keyword(reader.tokens()[0]);
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) {
    FailInput(path, reader.line(),
              "not an OFF file: expected the keyword 'OFF', found " + QuoteToken(keyword));
  }
  if (reader.tokens().size() > 1 && reader.tokens()[1] == "BINARY") return lines;
  if (keyword.find('n') != std::string::npos) {
    FailInput(path, reader.line(), "n-dimensional OFF (" + keyword + ") is not supported");
  }
  std::vector<std::string_view> counts(reader.tokens().begin() + 1, reader.tokens().end());
  if (counts.empty() && reader.Next()) counts = reader.tokens();
  const auto num_vertices = counts.size() >= 2 ? ParseInteger(counts[0]) : std::nullopt;
  const auto num_faces = counts.size() >= 2 ? ParseInteger(counts[1]) : std::nullopt;
  if (!num_vertices || !num_faces || *num_vertices < 0 || *num_faces < 0) {
    FailInput(path, reader.line(), "cannot read the vertex and face counts of the OFF header");
  }
  std::string normalized =
      keyword + "\n" + std::to_string(*num_vertices) + " " + std::to_string(*num_faces) + " 0\n";
  for (long long i = 0; i < *num_vertices; ++i) {
    if (!reader.Next()) {
      FailInput(path, 0,
                "the header declares " + std::to_string(*num_vertices) +
                    " vertices, but the file has only " + std::to_string(i));
    }
    CheckVertexTokens(path, reader.line(), lines.vertex.size(), reader.tokens(), 0);
    lines.vertex.push_back(reader.line());
    AppendLine(reader.tokens(), &normalized);
  }
  for (long long j = 0; j < *num_faces; ++j) {
    if (!reader.Next()) {
      FailInput(path, 0,
                "the header declares " + std::to_string(*num_faces) +
                    " faces, but the file has only " + std::to_string(j));
    }
    const int line = reader.line();
    std::vector<std::string_view> tokens = reader.tokens();
    const auto size = ParseInteger(tokens[0]);
    if (!size || *size < 0) {
      FailInput(path, line,
                "cannot parse " + QuoteToken(tokens[0]) + " as the vertex count of face " +
                    std::to_string(j));
    }
    while (tokens.size() < static_cast<std::size_t>(*size) + 1) {
      if (!reader.Next()) {
        FailInput(path, line,
                  "face " + std::to_string(j) + " declares " + std::to_string(*size) +
                      " vertices, but the file ends first");
      }
      tokens.insert(tokens.end(), reader.tokens().begin(), reader.tokens().end());
    }
    for (long long k = 1; k <= *size; ++k) {
      const auto index = ParseInteger(tokens[k]);
      if (!index || *index < 0) FailIndex(path, line, tokens[k], lines.face.size());
      if (*index >= *num_vertices) {
        FailInput(path, line, OutOfRangeMessage(lines.face.size(), *num_vertices));
      }
    }
    lines.face.push_back(line);
    AppendLine(tokens, &normalized);
  }
  *text = std::move(normalized);
  return lines;
}

// PLY: a header up to "end_header"; in ASCII PLY each element is one line, in
// the header's element order. Binary PLY is left to CGAL.
LineMap ScanPly(const std::string& path, const std::string& text) {
  LineReader reader(text);
  if (!reader.Next() || reader.tokens()[0] != "ply") {
    FailInput(path, 1, "not a PLY file: the first line must be 'ply'");
  }
  std::string format;
  std::vector<std::pair<std::string, long long>> elements;
  while (true) {
    if (!reader.Next()) FailInput(path, 0, "the PLY header has no 'end_header' line");
    const auto& tokens = reader.tokens();
    if (tokens[0] == "end_header") break;
    if (tokens[0] == "format" && tokens.size() > 1) format = tokens[1];
    if (tokens[0] == "element") {
      const auto count = tokens.size() > 2 ? ParseInteger(tokens[2]) : std::nullopt;
      if (!count || *count < 0) FailInput(path, reader.line(), "cannot read the PLY element count");
      elements.emplace_back(tokens[1], *count);
    }
  }
  LineMap lines;
  if (format != "ascii") return lines;
  for (const auto& [name, count] : elements) {
    const bool is_vertex = name == "vertex" || name == "vertices";
    const bool is_face = name == "face" || name == "faces";
    for (long long k = 0; k < count; ++k) {
      if (!reader.Next()) {
        FailInput(path, 0,
                  "the header declares " + std::to_string(count) + " " + name +
                      " elements, but the file has only " + std::to_string(k));
      }
      if (is_vertex) {
        CheckVertexTokens(path, reader.line(), lines.vertex.size(), reader.tokens(), 0);
        lines.vertex.push_back(reader.line());
      }
      if (is_face) lines.face.push_back(reader.line());
    }
  }
  return lines;
}

std::string ReadFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    FailInput(path, 0, "cannot open: it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) FailInput(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) FailInput(path, 0, "cannot read the file");
  return buffer.str();
}

}  // namespace archgeo
