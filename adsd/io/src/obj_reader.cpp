// Wavefront OBJ, read line by line into double.
//
// Why not a library: of the candidates, tinyobjloader (Debian builds it with double) parses
// numbers with its own routine, which is not correctly rounded (17-digit coordinates came
// back a few ulps off), and CGAL's OBJ reader refuses files with line
// elements ("l"), reads only the first corner of a face whose corners are separated by tabs, and
// says nothing but "false" on a bad file. Here every number goes through std::from_chars, which
// rounds correctly, and a bad line is reported with its number.
//
// What is read: "v x y z" (up to four numbers after the third, w or a colour, ignored) and "f" with
// corners written i, i/t, i/t/n or i//n (t and n not used, but each a whole number or empty),
// indices from 1, negative ones counting back from the last vertex read. "l" (lines) and "p"
// (points) are counted, not surfaces; every other statement (vt, vn, o, g, s, usemtl, mtllib, ...)
// is ignored, as are comments from '#'. A line ending in a backslash continues on the next, as the
// format allows (exporters wrap long faces so); errors name the line the statement starts on. An
// index may refer to a vertex defined later in the file; one beyond the last vertex is an error
// naming its line.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "adsd/error.h"
#include "adsd/tolerances.h"
#include "file_checks.h"
#include "text_scan.h"

namespace adsd::io::detail {

namespace {

std::string shortest(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

class ObjReader {
 public:
  ObjReader(const std::string& path, std::string_view text) : path_(path), lines_(text) {}

  PolygonSoup run() {
    std::string_view line;
    std::string continued;  // a statement's lines so far, while each ends in a backslash
    while (lines_.next(line)) {
      if (continued.empty()) statementLine_ = lines_.lineNumber();
      const std::size_t hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
      const std::size_t last = line.find_last_not_of(" \t\r\v\f");
      if (last != std::string_view::npos && line[last] == '\\') {
        continued.append(line.substr(0, last)).push_back(' ');
        requireShortLine(continued.size());
        continue;
      }
      if (!continued.empty()) line = continued.append(line);
      readStatement(line);
      continued.clear();
    }
    if (!continued.empty()) readStatement(continued);  // the file's last line ends in a backslash
    if (maxIndex_ >= static_cast<long long>(soup_.points.size())) {
      throw InputError(path_ + ":" + std::to_string(maxIndexLine_) + ": face refers to vertex " +
                       std::to_string(maxIndex_ + 1) + " but the file has " + std::to_string(soup_.points.size()) +
                       " vertices (indices start at 1)");
    }
    if (soup_.polygonCount() == 0) {
      throw InputError(path_ + ": the file holds no triangles (no 'f' lines" +
                       (lineElements_ + pointElements_ > 0 ? ", only " + std::to_string(lineElements_) +
                                                                  " lines and " + std::to_string(pointElements_) +
                                                                  " points, which are not surfaces)"
                                                            : ")"));
    }
    return std::move(soup_);
  }

 private:
  std::string at() const { return path_ + ":" + std::to_string(statementLine_) + ": "; }

  void requireShortLine(std::size_t bytes) const {
    if (bytes > kMaxWordLineBytes) {
      throw InputError(at() + "line longer than " + std::to_string(kMaxWordLineBytes) +
                       " bytes (a face of millions of corners?)");
    }
  }

  void readStatement(std::string_view line) {
    requireShortLine(line.size());
    const std::vector<std::string_view> tokens = splitWhitespace(line);
    if (tokens.empty()) return;
    const std::string_view keyword = tokens[0];
    if (keyword == "v") {
      readVertex(tokens);
    } else if (keyword == "f" || keyword == "l" || keyword == "p") {
      readElement(tokens);
    }
  }

  void readVertex(const std::vector<std::string_view>& tokens) {
    const std::size_t v = soup_.points.size();
    Vec3 p;
    if (tokens.size() < 4) {
      throw InputError(at() + "vertex " + std::to_string(v + 1) + ": expected 3 coordinates after 'v', got " +
                       std::to_string(tokens.size() - 1));
    }
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view word = tokens[static_cast<std::size_t>(axis) + 1];
      if (!parseDouble(word, p(axis))) {
        throw InputError(at() + "vertex " + std::to_string(v + 1) + ": coordinate " + quoteToken(word) +
                         " is not a decimal number");
      }
    }
    // After x y z a file may give w, or a colour (r g b, some exporters r g b a): numbers, read
    // and not used. Anything else is a mistake: a lone carriage return in a file of LF line ends
    // joined two vertex lines into one, and the second vertex was dropped without a word (the
    // faces after it then named the wrong corners; an adversarial review).
    if (tokens.size() > 8) {
      throw InputError(at() + "vertex " + std::to_string(v + 1) + ": expected 3 coordinates after 'v' (then w or a " +
                       "colour), got " + std::to_string(tokens.size() - 1) + " values");
    }
    for (std::size_t k = 4; k < tokens.size(); ++k) {
      double ignored = 0.0;
      if (!parseDouble(tokens[k], ignored)) {
        throw InputError(at() + "vertex " + std::to_string(v + 1) + ": " + quoteToken(tokens[k]) +
                         " after its coordinates is not a number (w or a colour)");
      }
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(p(axis))) {
        throw InputError(at() + "vertex " + std::to_string(v + 1) + " has a non-finite coordinate " + shortest(p(axis)));
      }
      if (std::abs(p(axis)) > tolerance::kMaxCoordinate) {
        throw InputError(at() + "vertex " + std::to_string(v + 1) + ": coordinate " + shortest(p(axis)) +
                         " is beyond +-1e75, where the distance computation's squared lengths would overflow");
      }
    }
    if (v >= UINT32_MAX) throw InputError(at() + "more than 2^32 - 1 vertices");
    soup_.points.push_back(p);
  }

  /// The texture and normal indices after a corner's vertex index (from \p start): not used, but
  /// a word or a fourth index there is a mistake in the file, not something to pass over.
  void requireTextureAndNormalIndices(std::string_view corner, std::size_t start) const {
    std::size_t parts = 0;
    bool whole = true;
    for (std::size_t slash = start; slash < corner.size() && whole; ++parts) {
      const std::size_t end = std::min(corner.find('/', slash + 1), corner.size());
      const std::string_view index = corner.substr(slash + 1, end - slash - 1);  // empty in "i//n" and "i/"
      long long value = 0;
      whole = index.empty() || parseInteger(index, value);
      slash = end;
    }
    if (!whole || parts > 2) {
      throw InputError(at() + "face corner " + quoteToken(corner) +
                       ": expected i, i/t, i/t/n or i//n, each a whole number");
    }
  }

  /// A face, line or point element: corners "i", "i/t", "i/t/n" or "i//n".
  void readElement(const std::vector<std::string_view>& tokens) {
    if (tokens.size() < 2) throw InputError(at() + "'" + std::string(tokens[0]) + "' without vertex indices");
    if (tokens[0] != "f") {
      ++(tokens[0] == "l" ? lineElements_ : pointElements_);
      return;
    }
    const long long defined = static_cast<long long>(soup_.points.size());
    for (std::size_t k = 1; k < tokens.size(); ++k) {
      const std::string_view corner = tokens[k].substr(0, tokens[k].find('/'));
      long long index = 0;
      if (!parseInteger(corner, index) || index == 0) {
        throw InputError(at() + "face corner " + quoteToken(tokens[k]) +
                         " does not start with a vertex index (from 1, or negative counting back)");
      }
      requireTextureAndNormalIndices(tokens[k], corner.size());
      if (index < 0) {
        // Compared as index < -defined: negating index itself overflows for the most negative
        // long long, which a file may well hold.
        if (index < -defined) {
          throw InputError(at() + "face corner " + quoteToken(tokens[k]) + " counts back past the first vertex (" +
                           std::to_string(defined) + " defined so far)");
        }
        index = defined + index;
      } else {
        index -= 1;
        if (index > maxIndex_) {
          maxIndex_ = index;
          maxIndexLine_ = statementLine_;
        }
      }
      if (index >= UINT32_MAX) throw InputError(at() + "vertex index " + quoteToken(corner) + " beyond 2^32 - 1");
      soup_.addCorner(static_cast<std::uint32_t>(index));
    }
    soup_.closePolygon();
  }

  const std::string& path_;
  LineScanner lines_;
  PolygonSoup soup_;
  long long maxIndex_ = -1;
  int maxIndexLine_ = 0;
  int statementLine_ = 0;  // where the statement being read starts
  std::uint64_t lineElements_ = 0, pointElements_ = 0;
};

}  // namespace

PolygonSoup readObj(const std::string& path, std::string_view text) { return ObjReader(path, text).run(); }

}  // namespace adsd::io::detail
