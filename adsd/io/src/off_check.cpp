// The structure check for OFF files, run before assimp reads them.
//
// Assimp 5.2's OFF reader repairs bad files without a word: an index beyond the vertex count is
// clamped to the last vertex, a face with 0 or more than 9 corners is dropped, a missing vertex
// line leaves vertices at the origin, and a line longer than its 4096-byte buffer is split in two.
// Each of those would turn a broken file into a wrong mesh, so the file is read here first, the
// way assimp will read it, and anything it would repair is an error naming the line.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "adsd/error.h"
#include "file_checks.h"
#include "text_scan.h"

namespace adsd::io::detail {

namespace {

/// Assimp's OFF reader copies each data line into a 4096-byte buffer (including the terminator).
constexpr std::size_t kAssimpOffLineBuffer = 4096;
/// Assimp drops faces with more corners than this.
constexpr long long kAssimpOffMaxCorners = 9;
constexpr long long kMaxCount = UINT32_MAX;

std::string_view withoutComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

bool isCommentLine(std::string_view line) {
  const std::vector<std::string_view> tokens = splitWhitespace(line);
  return !tokens.empty() && tokens.front().front() == '#';
}

/// "OFF" with assimp's optional prefixes ST, C, N, 4, n in that order. Sets \p plain false for the
/// 4 (homogeneous) and n (dimension) variants, whose lines this check does not model.
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

class OffChecker {
 public:
  OffChecker(const std::string& path, std::string_view text) : path_(path), lines_(text) {}

  void run() {
    std::vector<long long> counts;
    if (!readHeader(counts)) return;
    const long long vertices = counts[0];
    const long long faces = counts[1];
    if (vertices == 0) throw InputError(path_ + ": the OFF header promises 0 vertices");
    if (faces == 0) throw InputError(path_ + ": the file holds no triangles (the OFF header promises 0 faces)");

    skipBlankAndCommentLines();
    for (long long v = 0; v < vertices; ++v) {
      const std::vector<std::string_view> tokens = nextDataLine("vertex", v, vertices);
      double coordinate;
      if (tokens.size() < 3 || !parseDouble(tokens[0], coordinate) || !parseDouble(tokens[1], coordinate) ||
          !parseDouble(tokens[2], coordinate)) {
        throw InputError(at() + "vertex " + std::to_string(v) + ": expected 3 coordinates, got " +
                         (tokens.empty() ? std::string("an empty line") : quoteToken(current_)));
      }
    }
    for (long long f = 0; f < faces; ++f) {
      const std::vector<std::string_view> tokens = nextDataLine("face", f, faces);
      long long corners = 0;
      if (tokens.empty() || !parseInteger(tokens[0], corners)) {
        throw InputError(at() + "face " + std::to_string(f) + ": expected a corner count, got " +
                         (tokens.empty() ? std::string("an empty line") : quoteToken(tokens[0])));
      }
      if (corners < 1 || corners > kAssimpOffMaxCorners) {
        throw InputError(at() + "face " + std::to_string(f) + " has " + std::to_string(corners) +
                         " corners; assimp reads faces of 1 to " + std::to_string(kAssimpOffMaxCorners));
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
      }
    }
  }

 private:
  std::string at() const { return path_ + ":" + std::to_string(lines_.lineNumber()) + ": "; }

  /// Reads the keyword (optional) and the three counts, which may span lines and carry comments
  /// (assimp skips blank and '#' lines between them). Returns false for variants not modelled here.
  bool readHeader(std::vector<long long>& counts) {
    bool first = true;
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
          if (!plain) return false;
          ++t;
        }
      }
      for (; t < tokens.size(); ++t) {
        long long count = -1;
        if (counts.size() == 3) {
          throw InputError(at() + "unexpected " + quoteToken(tokens[t]) +
                           " after the three counts (vertices faces edges)");
        }
        if (!parseInteger(tokens[t], count) || count < 0 || count > kMaxCount) {
          throw InputError(at() + "expected the OFF keyword or a count (vertices faces edges), got " +
                           quoteToken(tokens[t]));
        }
        counts.push_back(count);
      }
    }
    return true;
  }

  /// Assimp moves from the counts to the first vertex past blank lines and '#' lines.
  void skipBlankAndCommentLines() {
    std::string_view line;
    LineScanner lookahead = lines_;
    while (lookahead.next(line) && (isBlank(line) || isCommentLine(line))) lines_ = lookahead;
  }

  /// The next line assimp would read as data: empty lines are skipped (its line reader swallows
  /// runs of line ends), anything else counts, including a blank or comment line.
  std::vector<std::string_view> nextDataLine(const char* what, long long index, long long promised) {
    do {
      if (!lines_.next(current_)) {
        throw InputError(path_ + ": the OFF header promises " + std::to_string(promised) + " " + what +
                         (promised == 1 ? "" : "s") + " but the file ends after " + std::to_string(index));
      }
    } while (current_.empty());
    if (current_.size() >= kAssimpOffLineBuffer) {
      throw InputError(at() + "line longer than " + std::to_string(kAssimpOffLineBuffer - 1) +
                       " characters, which assimp's OFF reader would split");
    }
    return splitWhitespace(current_);
  }

  const std::string& path_;
  LineScanner lines_;
  std::string_view current_;
};

}  // namespace

void requireConsistentOff(const std::string& path, std::string_view text) { OffChecker(path, text).run(); }

}  // namespace adsd::io::detail
