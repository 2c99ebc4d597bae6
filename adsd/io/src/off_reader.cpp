// OFF, read line by line into double.
//
// Why not a library: CGAL's OFF scanner (the one exact candidate; OpenMesh rounds to float) is
// exact but slower than assimp on the largest real model, bunny00.off (docs/numerics.md), and
// says nothing but "false" on a bad file, while a malformed file must be reported with its line. The
// format is a header and two lists of numbers, and every number goes through std::from_chars,
// which rounds correctly: a coordinate written with 17 significant digits comes back bit for bit.
//
// What is read: the optional keyword (OFF, COFF, NOFF, CNOFF, STOFF, ...: extra values after a
// vertex's three coordinates, such as colours or normals, are ignored), the counts (vertices,
// faces, edges), then one vertex per line and one face per line ("n i1 ... in", extra values
// after the indices ignored). '#' starts a comment anywhere; blank and comment lines are skipped.
// Refused, with the line: homogeneous (4OFF) and n-dimensional (nOFF) variants and binary OFF,
// fewer lines than the counts promise or data after the last face, a vertex without three
// numbers, a non-finite coordinate or one beyond +-1e75 (tolerances.h), a face without its
// indices, an index out of range.

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

constexpr long long kMaxCount = UINT32_MAX;

// The shortest lines the data can have: a vertex "0 0 0" and a face "1 0", each with its line end.
// Reservations are capped by how many such lines the rest of the file could hold, so that a header
// promising 2^32 - 2 vertices in a 40-byte file is reported as the truncation it is (when the
// reading reaches the end) instead of reserving 100 GB first.
constexpr std::size_t kShortestVertexLineBytes = 6;
constexpr std::size_t kShortestFaceLineBytes = 4;

std::string_view withoutComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// "OFF" with the optional prefixes ST, C, N, 4, n in that order. Sets \p plain false for the
/// 4 (homogeneous) and n (dimension) variants.
bool isOffKeyword(std::string_view token, bool& plain) {
  if (token.size() < 3 || token.substr(token.size() - 3) != "OFF") return false;
  std::string_view prefix = token.substr(0, token.size() - 3);
  plain = true;
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  for (const char letter : {'C', 'N', '4', 'n'}) {
    if (!prefix.empty() && prefix.front() == letter) {
      if (letter == '4' || letter == 'n') plain = false;
      prefix.remove_prefix(1);
    }
  }
  return prefix.empty();
}

std::string shortest(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

class OffReader {
 public:
  OffReader(const std::string& path, std::string_view text) : path_(path), text_(text), lines_(text) {}

  PolygonSoup run() {
    std::vector<long long> counts;
    readHeader(counts);
    const long long vertices = counts[0];
    const long long faces = counts[1];
    if (vertices == 0) throw InputError(path_ + ": the OFF header promises 0 vertices");
    if (faces == 0) throw InputError(path_ + ": the file holds no triangles (the OFF header promises 0 faces)");

    PolygonSoup soup;
    soup.points.reserve(std::min(static_cast<std::size_t>(vertices), linesThatFit(kShortestVertexLineBytes)));
    for (long long v = 0; v < vertices; ++v) {
      const std::vector<std::string_view> tokens = nextDataLine("vertex", "vertices", v, vertices);
      Vec3 p;
      if (tokens.size() < 3 || !parseDouble(tokens[0], p.x()) || !parseDouble(tokens[1], p.y()) ||
          !parseDouble(tokens[2], p.z())) {
        throw InputError(at() + "vertex " + std::to_string(v) + ": expected 3 coordinates, got " +
                         quoteToken(withoutComment(current_)));
      }
      requireRepresentable(p, v);
      soup.points.push_back(p);
    }
    const std::size_t facesThatFit = std::min(static_cast<std::size_t>(faces), linesThatFit(kShortestFaceLineBytes));
    soup.corners.reserve(3 * facesThatFit);
    soup.starts.reserve(facesThatFit + 1);
    for (long long f = 0; f < faces; ++f) {
      // A vertex count too high reads the first faces as vertices (a line of numbers either way),
      // and then the faces seem missing: said, where "ends after 0 faces" alone pointed away from
      // the count at fault (an adversarial review).
      const std::string hint = f == 0 ? " (is the header's vertex count, " + std::to_string(vertices) +
                                            ", more than the file holds? Face lines were then read as vertices)"
                                      : std::string();
      const std::vector<std::string_view> tokens = nextDataLine("face", "faces", f, faces, hint);
      long long corners = 0;
      if (!parseInteger(tokens[0], corners) || corners < 1) {
        throw InputError(at() + "face " + std::to_string(f) + ": expected a corner count of at least 1, got " +
                         quoteToken(tokens[0]));
      }
      if (static_cast<long long>(tokens.size()) < corners + 1) {
        throw InputError(at() + "face " + std::to_string(f) + ": expected " + std::to_string(corners) +
                         " vertex indices, got " + std::to_string(tokens.size() - 1));
      }
      for (long long k = 1; k <= corners; ++k) {
        long long index = -1;
        if (!parseInteger(tokens[k], index) || index < 0) {
          throw InputError(at() + "face " + std::to_string(f) + ": vertex index " + quoteToken(tokens[k]) +
                           " is not a non-negative integer");
        }
        if (index >= vertices) {
          throw InputError(at() + "face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                           " but the file has " + std::to_string(vertices) + " vertices (indices start at 0)");
        }
        soup.addCorner(static_cast<std::uint32_t>(index));
      }
      soup.closePolygon();
    }
    requireNothingAfterTheFaces(faces);
    return soup;
  }

 private:
  std::string at() const { return path_ + ":" + std::to_string(lines_.lineNumber()) + ": "; }

  /// How many lines of at least \p bytesEach bytes (line end included; the last may lack it) the
  /// rest of the file could hold.
  std::size_t linesThatFit(std::size_t bytesEach) const {
    return (text_.size() - lines_.offset() + 1) / bytesEach;
  }

  void requireRepresentable(const Vec3& p, long long v) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(p(axis))) {
        throw InputError(at() + "vertex " + std::to_string(v) + " has a non-finite coordinate " + shortest(p(axis)));
      }
      if (std::abs(p(axis)) > tolerance::kMaxCoordinate) {
        throw InputError(at() + "vertex " + std::to_string(v) + ": coordinate " + shortest(p(axis)) +
                         " is beyond +-1e75, where the distance computation's squared lengths would overflow");
      }
    }
  }

  /// Reads the keyword (optional) and the three counts, which may span lines and carry comments.
  void readHeader(std::vector<long long>& counts) {
    bool first = true;
    int firstCountLine = 0;
    std::string_view line;
    while (counts.size() < 3) {
      if (!lines_.next(line)) {
        throw InputError(path_ + ": the OFF header ends before its three counts (vertices faces edges)");
      }
      std::vector<std::string_view> tokens = splitWhitespace(withoutComment(line));
      if (tokens.empty()) continue;
      std::size_t t = 0;
      if (first) {
        first = false;
        bool plain = true;
        if (isOffKeyword(tokens[0], plain)) {
          if (!plain) throw InputError(at() + "homogeneous (4OFF) and n-dimensional (nOFF) OFF files are not read");
          ++t;
          if (t < tokens.size() && tokens[t] == "BINARY") throw InputError(at() + "binary OFF is not read (write ASCII OFF or binary PLY)");
        }
      }
      for (; t < tokens.size(); ++t) {
        long long count = -1;
        if (counts.size() == 3) {
          // Counts may span lines, so a header line short of one took the first vertex's x for
          // the edge count: name the line the counts began on.
          std::string began;
          if (firstCountLine != lines_.lineNumber()) {
            began = ", read from line " + std::to_string(firstCountLine) + " on: is one missing there?";
          }
          throw InputError(at() + "unexpected " + quoteToken(tokens[t]) +
                           " after the three counts (vertices faces edges)" + began);
        }
        const bool parsed = parseInteger(tokens[t], count);
        const bool digits =
            std::all_of(tokens[t].begin(), tokens[t].end(), [](char c) { return c >= '0' && c <= '9'; });
        if (digits && (!parsed || count > kMaxCount)) {
          // A whole number past what the reader takes: say so, rather than that it is no count.
          static constexpr const char* kCountNames[3] = {"vertex", "face", "edge"};
          throw InputError(at() + "the " + kCountNames[counts.size()] + " count " + quoteToken(tokens[t]) +
                           " is more than the reader takes (" + std::to_string(kMaxCount) + ")");
        }
        if (!parsed || count < 0 || count > kMaxCount) {
          throw InputError(at() + "expected the OFF keyword or a count (vertices faces edges), got " +
                           quoteToken(tokens[t]));
        }
        if (counts.empty()) firstCountLine = lines_.lineNumber();
        counts.push_back(count);
      }
    }
  }

  /// Only blank lines and comments may follow the last face: anything else means the counts do
  /// not describe the file (a face count too low, two files joined), and reading on would guess.
  void requireNothingAfterTheFaces(long long faces) {
    std::string_view line;
    while (lines_.next(line)) {
      const std::vector<std::string_view> tokens = splitWhitespace(withoutComment(line));
      if (tokens.empty()) continue;
      throw InputError(at() + "unexpected " + quoteToken(tokens[0]) + " after the last of the " +
                       std::to_string(faces) + " faces the OFF header promises");
    }
  }

  /// The next line with data: blank lines and comments are skipped. A file that ends first is an
  /// error, with \p atTheEnd added to its message.
  std::vector<std::string_view> nextDataLine(const char* one, const char* many, long long index, long long promised,
                                             const std::string& atTheEnd = std::string()) {
    while (true) {
      if (!lines_.next(current_)) {
        throw InputError(path_ + ": the OFF header promises " + std::to_string(promised) + " " +
                         (promised == 1 ? one : many) + " but the file ends after " + std::to_string(index) + atTheEnd);
      }
      if (withoutComment(current_).size() > kMaxWordLineBytes) {
        throw InputError(at() + "line longer than " + std::to_string(kMaxWordLineBytes) +
                         " bytes (a face of millions of corners?)");
      }
      std::vector<std::string_view> tokens = splitWhitespace(withoutComment(current_));
      if (!tokens.empty()) return tokens;
    }
  }

  const std::string& path_;
  std::string_view text_;
  LineScanner lines_;
  std::string_view current_;
};

}  // namespace

bool startsWithOffKeyword(std::string_view text) {
  LineScanner lines(text);
  std::string_view line;
  while (lines.next(line)) {
    // The first word only: a binary file of another format may be one line of megabytes.
    const std::string_view content = withoutComment(line);
    const std::size_t begin = content.find_first_not_of(" \t\r\n\f\v");
    if (begin == std::string_view::npos) continue;
    const std::size_t end = content.find_first_of(" \t\r\n\f\v", begin);
    bool plain = true;
    return isOffKeyword(content.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin), plain);
  }
  return false;
}

PolygonSoup readOff(const std::string& path, std::string_view text) { return OffReader(path, text).run(); }

}  // namespace adsd::io::detail
