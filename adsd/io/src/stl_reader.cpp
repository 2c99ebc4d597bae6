// STL, ASCII and binary, read into double.
//
// Binary STL stores float32 coordinates: each becomes the double of the same value, exactly (the
// file's own precision, no more). ASCII STL is read word by word, every number through
// std::from_chars (correctly rounded: 17 significant digits come back bit for bit), and a bad
// word is reported with its line. Why not CGAL's STL reader (the exact library candidate): given
// an ASCII file it cannot parse it falls back to reading it as binary, and a file shorter than
// 80 bytes then reads as an empty mesh without complaint; it also says nothing but "false".
// requireCompleteBinaryStl (file_checks.cpp) has decided which of the two a file is, and checked a
// binary file's size, before either reader here runs.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "adsd/error.h"
#include "adsd/tolerances.h"
#include "file_checks.h"
#include "text_scan.h"

namespace adsd::io::detail {

namespace {

constexpr std::size_t kStlPreambleBytes = 84;
constexpr std::size_t kStlBytesPerTriangle = 50;

std::string shortest(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

/// Whether \p word is the keyword \p lower in any case: some CAD exporters write "SOLID" and
/// "FACET NORMAL", which the format sniffing (file_checks.cpp) already takes for ASCII STL.
bool isKeyword(std::string_view word, std::string_view lower) {
  if (word.size() != lower.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    const char c = word[i];
    if ((c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c) != lower[i]) return false;
  }
  return true;
}

/// The words of an ASCII STL with the line each is on.
class WordScanner {
 public:
  explicit WordScanner(std::string_view text) : lines_(text) {}

  /// The next word, or false at the end of the file.
  bool next(std::string_view& word) {
    while (pending_ >= words_.size()) {
      std::string_view line;
      if (!lines_.next(line)) return false;
      words_ = splitWhitespace(line);
      pending_ = 0;
    }
    word = words_[pending_++];
    return true;
  }
  int line() const { return lines_.lineNumber(); }
  /// Drops the words left on the current line (a solid's name), whatever their number.
  void skipRestOfLine() { pending_ = words_.size(); }

 private:
  LineScanner lines_;
  std::vector<std::string_view> words_;
  std::size_t pending_ = 0;
};

class AsciiStlReader {
 public:
  AsciiStlReader(const std::string& path, std::string_view text) : path_(path), words_(text) {}

  PolygonSoup run() {
    std::string_view word;
    bool inSolid = false;
    while (words_.next(word)) {
      if (isKeyword(word, "solid") && !inSolid) {
        inSolid = true;
        words_.skipRestOfLine();  // the solid's name, any words
      } else if (isKeyword(word, "endsolid") && inSolid) {
        inSolid = false;
        words_.skipRestOfLine();
      } else if (isKeyword(word, "facet") && inSolid) {
        readFacet();
      } else {
        throw InputError(at() + "expected " + (inSolid ? "'facet' or 'endsolid'" : "'solid'") + ", got " +
                         quoteToken(word));
      }
    }
    if (inSolid) throw InputError(path_ + ": the file ends inside a solid (no 'endsolid'): truncated ASCII STL?");
    if (soup_.polygonCount() == 0) throw InputError(path_ + ": the file holds no triangles (no facets)");
    return std::move(soup_);
  }

 private:
  std::string at() const { return path_ + ":" + std::to_string(words_.line()) + ": "; }

  void expect(std::string_view wanted) {
    std::string_view word;
    if (!words_.next(word)) throw InputError(path_ + ": the file ends inside a facet, before '" + std::string(wanted) + "'");
    if (!isKeyword(word, wanted)) {
      throw InputError(at() + "expected '" + std::string(wanted) + "', got " + quoteToken(word));
    }
  }

  double number(const char* what) {
    std::string_view word;
    double value = 0.0;
    if (!words_.next(word)) throw InputError(path_ + ": the file ends inside a facet, before its " + what);
    if (!parseDouble(word, value)) throw InputError(at() + "expected a number (" + what + "), got " + quoteToken(word));
    return value;
  }

  void readFacet() {
    expect("normal");
    for (int k = 0; k < 3; ++k) number("normal");  // unused: the corners define the triangle
    expect("outer");
    expect("loop");
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      Vec3 p;
      for (int axis = 0; axis < 3; ++axis) p(axis) = number("vertex coordinate");
      for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(p(axis))) throw InputError(at() + "vertex has a non-finite coordinate " + shortest(p(axis)));
        if (std::abs(p(axis)) > tolerance::kMaxCoordinate) {
          throw InputError(at() + "vertex coordinate " + shortest(p(axis)) +
                           " is beyond +-1e75, where the distance computation's squared lengths would overflow");
        }
      }
      if (soup_.points.size() >= UINT32_MAX) throw InputError(at() + "more than 2^32 - 1 vertices");
      soup_.addCorner(static_cast<std::uint32_t>(soup_.points.size()));
      soup_.points.push_back(p);
    }
    soup_.closePolygon();
    expect("endloop");
    expect("endfacet");
  }

  const std::string& path_;
  WordScanner words_;
  PolygonSoup soup_;
};

float floatAt(std::string_view bytes, std::size_t offset) {
  // Little-endian float32, as STL stores it (this reads it on any host).
  std::uint32_t bits = 0;
  for (int b = 3; b >= 0; --b) bits = bits << 8 | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(b)]);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

PolygonSoup readStl(const std::string& path, std::string_view bytes) {
  if (!isBinaryStl(bytes)) return AsciiStlReader(path, bytes).run();
  // requireCompleteBinaryStl has checked that the size is exactly 84 + 50 x count.
  const std::size_t count = (bytes.size() - kStlPreambleBytes) / kStlBytesPerTriangle;
  if (count > UINT32_MAX / 3) throw InputError(path + ": more than 2^32 - 1 vertices (3 per binary STL triangle)");
  PolygonSoup soup;
  soup.points.reserve(3 * count);
  soup.corners.reserve(3 * count);
  soup.starts.reserve(count + 1);
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t record = kStlPreambleBytes + kStlBytesPerTriangle * t;
    for (int k = 0; k < 3; ++k) {
      Vec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        p(axis) = floatAt(bytes, record + 12 + 12 * static_cast<std::size_t>(k) + 4 * static_cast<std::size_t>(axis));
      }
      if (!p.allFinite()) {
        throw InputError(path + ": triangle " + std::to_string(t) + " has a vertex with a non-finite coordinate (" +
                         shortest(p.x()) + ", " + shortest(p.y()) + ", " + shortest(p.z()) + ")");
      }
      soup.addCorner(static_cast<std::uint32_t>(soup.points.size()));
      soup.points.push_back(p);
    }
    soup.closePolygon();
  }
  return soup;
}

}  // namespace adsd::io::detail
