// PLY, ASCII and binary (both byte orders), read into double.
//
// The header is parsed, the data walked instance by instance (ASCII: one instance per line, as PLY
// writers emit it; binary: record by record, list lengths included), and each vertex's x, y, z
// and each face's corner list (vertex_indices or vertex_index, any integer type) kept, and each
// triangle strip of a tristrips element (vertex_indices, -1 starting a new strip), which older
// scanners wrote instead of faces. ASCII
// numbers go through std::from_chars, correctly rounded whatever type the header declares, so 17
// significant digits come back bit for bit; binary float32 and float64 values are converted to
// double exactly. Face indices are checked against the vertex count, coordinates must be finite
// and within +-1e75 (tolerances.h). Anything off is an error naming the line (ASCII) or the element
// and instance (binary).
//
// Why not CGAL's PLY reader (measured for issue 16; exact on double properties): it reads an ASCII
// "float" property with strtof, rounding 17-digit text to float, took longer than assimp on the
// Stanford dragon, reads only 32-bit index lists (a ushort list, which assimp read, fails with
// "can't find vertex indices" printed on stderr), accepts a face index beyond the vertex count,
// and answers a malformed file with "false" alone. This walk had to parse every value to name bad
// lines anyway; keeping the values costs nothing more.
//
// The check was first written for assimp 5.2's PLY reader, which looped forever on a header
// without end_header or with an element line lacking its count, aborted on a blank line inside
// ASCII data or on a face with no corners, and read past its buffer on a control character in the
// header (fuzz findings, tests/fuzz/regressions/mesh_loader/ply_*). Those rules stay: the files
// are malformed whichever library reads them, and each still gets its line.

#include <algorithm>
#include <array>
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

enum class Format { ascii, binaryLittleEndian, binaryBigEndian };

struct ScalarType {
  int bytes = 0;
  bool isInteger = false;
  bool isSigned = false;
  const char* name = "";
  /// Whether an integer read from ASCII fits the type: a binary file cannot hold a uchar of 300,
  /// and an ASCII one that says so is damaged (a list of 300 corners behind a uchar count).
  bool holds(long long value) const {
    if (!isInteger) return true;
    const int bits = 8 * bytes;
    if (isSigned) return bits >= 64 || (value >= -(1LL << (bits - 1)) && value < (1LL << (bits - 1)));
    return value >= 0 && (bits >= 64 || value < (1LL << bits));
  }
};

/// The PLY scalar types, with the sized aliases assimp also accepts. Returns bytes == 0 if unknown.
ScalarType scalarType(std::string_view name) {
  if (name == "char" || name == "int8") return {1, true, true, "int8"};
  if (name == "uchar" || name == "uint8") return {1, true, false, "uint8"};
  if (name == "short" || name == "int16") return {2, true, true, "int16"};
  if (name == "ushort" || name == "uint16") return {2, true, false, "uint16"};
  if (name == "int" || name == "int32") return {4, true, true, "int32"};
  if (name == "uint" || name == "uint32") return {4, true, false, "uint32"};
  if (name == "float" || name == "float32") return {4, false, true, "float32"};
  if (name == "double" || name == "float64") return {8, false, true, "float64"};
  return {};
}

struct Property {
  std::string name;
  bool isList = false;
  ScalarType countType;  ///< lists only
  ScalarType valueType;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

/// Element and property names are identifiers. Assimp does not read a name that starts with a
/// digit as a name: "element 9999999999face 1" becomes a count of 9999999999 (mod 2^32).
bool isIdentifier(std::string_view name) {
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (name.empty() || !letter(name.front())) return false;
  return std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9') || c == '-'; });
}

/// The face corner lists whose values are vertex indices.
bool isVertexIndexList(const Element& element, const Property& property) {
  return element.name == "face" && property.isList &&
         (property.name == "vertex_indices" || property.name == "vertex_index");
}

/// A tristrips element's index list: strips of triangles, each new index making a triangle with
/// the two before it, an index of -1 ending one strip and starting the next.
bool isStripList(const Element& element, const Property& property) {
  return element.name == "tristrips" && property.isList && property.name == "vertex_indices";
}

class PlyChecker {
 public:
  PlyChecker(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes), lines_(bytes) {}

  PolygonSoup run() {
    readHeader();
    for (const Element& e : elements_) {
      if (e.name == "vertex") vertexCount_ = e.count;
    }
    if (vertexCount_ > UINT32_MAX) throw InputError(path_ + ": more than 2^32 - 1 vertices");
    if (format_ == Format::ascii) {
      walkAscii();
      requireNothingAfterAscii();
    } else {
      walkBinary();
      requireNothingAfterBinary();
    }
    return std::move(soup_);
  }

 private:
  std::string at() const { return path_ + ":" + std::to_string(lines_.lineNumber()) + ": "; }

  void readHeader() {
    std::string_view line;
    if (!lines_.next(line) || splitWhitespace(line) != std::vector<std::string_view>{"ply"}) {
      throw InputError(path_ + ":1: a PLY file starts with the line 'ply'");
    }
    bool formatSeen = false;
    while (true) {
      if (!lines_.next(line)) throw InputError(path_ + ": the PLY header has no end_header line");
      requireNoControlCharacter(line);
      const std::vector<std::string_view> t = splitWhitespace(line);
      if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
      if (t[0] == "end_header") break;
      if (t[0] == "format") {
        if (t.size() != 3 || t[2] != "1.0") throw InputError(at() + "expected 'format <kind> 1.0'");
        if (t[1] == "ascii") format_ = Format::ascii;
        else if (t[1] == "binary_little_endian") format_ = Format::binaryLittleEndian;
        else if (t[1] == "binary_big_endian") format_ = Format::binaryBigEndian;
        else throw InputError(at() + "unknown PLY format " + quoteToken(t[1]));
        formatSeen = true;
      } else if (t[0] == "element") {
        long long count = -1;
        if (t.size() != 3 || !parseInteger(t[2], count) || count < 0 || count > UINT32_MAX) {
          throw InputError(at() + "expected 'element <name> <count>' with a count from 0 to 2^32 - 1");
        }
        if (!isIdentifier(t[1])) throw InputError(at() + "element name " + quoteToken(t[1]) + " is not an identifier");
        // A second vertex element: would its indices go on from the first one's or start again?
        // Writers declare each element once; a file that does not is damaged or made to mislead.
        for (const Element& e : elements_) {
          if (e.name == t[1]) throw InputError(at() + "element " + e.name + " is declared twice");
        }
        elements_.push_back({std::string(t[1]), count, {}});
      } else if (t[0] == "property") {
        if (elements_.empty()) throw InputError(at() + "a property before any element");
        Property p;
        if (t.size() == 5 && t[1] == "list") {
          p.isList = true;
          p.countType = scalarType(t[2]);
          p.valueType = scalarType(t[3]);
          p.name = std::string(t[4]);
          if (p.countType.bytes == 0 || !p.countType.isInteger) {
            throw InputError(at() + "list count type " + quoteToken(t[2]) + " is not an integer type");
          }
          // Corners listed as floats were skipped, and the file read as one with no triangles.
          if (isVertexIndexList(elements_.back(), p) && p.valueType.bytes != 0 && !p.valueType.isInteger) {
            throw InputError(at() + "the face list " + p.name + " holds vertex indices, but its value type " +
                             quoteToken(t[3]) + " is not an integer type");
          }
        } else if (t.size() == 3) {
          p.valueType = scalarType(t[1]);
          p.name = std::string(t[2]);
        } else {
          throw InputError(at() + "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
        }
        if (p.valueType.bytes == 0) throw InputError(at() + "unknown property type in " + quoteToken(line));
        if (!isIdentifier(p.name)) throw InputError(at() + "property name " + quoteToken(p.name) + " is not an identifier");
        // Two x properties: which is the coordinate? The last one was taken without a word.
        for (const Property& q : elements_.back().properties) {
          if (q.name == p.name) {
            throw InputError(at() + "element " + elements_.back().name + " declares property " + p.name + " twice");
          }
        }
        elements_.back().properties.push_back(p);
      }
      // Any other line is ignored, as assimp ignores it (Blender 2.4 wrote its banner without
      // "comment"; assimp's own test model Wuson.ply has one).
    }
    if (!formatSeen) throw InputError(path_ + ": the PLY header has no format line");
    // Faces without a corner list were skipped, and the file read as one with no triangles.
    for (const Element& e : elements_) {
      const auto corners = [&e](const Property& p) { return isVertexIndexList(e, p); };
      const auto strips = [&e](const Property& p) { return isStripList(e, p) && p.valueType.isInteger; };
      if (e.name == "tristrips" && e.count > 0 && std::none_of(e.properties.begin(), e.properties.end(), strips)) {
        throw InputError(path_ + ": the PLY header's element tristrips has no 'property list <count type> <integer "
                         "type> vertex_indices': its strips have no corners");
      }
      if (e.name == "face" && e.count > 0 && std::none_of(e.properties.begin(), e.properties.end(), corners)) {
        throw InputError(path_ + ": the PLY header's element face (" + std::to_string(e.count) +
                         " faces) has no 'property list <count type> <index type> vertex_indices' (or " +
                         "vertex_index): its faces have no corners");
      }
    }
    dataOffset_ = lines_.offset();
  }

  /// Header lines are words separated by spaces or tabs (the LineScanner has dropped a CR before
  /// the line end); any other control character is one assimp's header reader chokes on.
  void requireNoControlCharacter(std::string_view line) const {
    for (const char c : line) {
      const auto byte = static_cast<unsigned char>(c);
      if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
        const char digits[] = "0123456789abcdef";
        throw InputError(at() + "control character 0x" + digits[byte >> 4] + digits[byte & 15] +
                         " in the PLY header (words are separated by spaces, lines by a newline)");
      }
    }
  }

  /// A face must have corners: assimp's triangulation aborts the process on an empty one.
  void requireCorners(long long count, const Element& e, const Property& p, long long instance) const {
    if (count == 0 && isVertexIndexList(e, p)) throw InputError(where(e, instance) + ": a face with no corners");
  }

  void checkIndex(long long index, const Element& e, long long instance) const {
    if (index < 0 || index >= vertexCount_) {
      throw InputError(where(e, instance) + " refers to vertex " + std::to_string(index) + " but the file has " +
                       std::to_string(vertexCount_) + " vertices (indices start at 0)");
    }
  }

  /// Appends the triangles of strip list \p indices (instance \p instance of \p e): index k >= 2
  /// of a strip makes a triangle with the two before it, every other one turned so that all face
  /// the same way; -1 starts a new strip. A triangle repeating an index is the strips' way of
  /// joining two strips, not a surface, and is left out.
  void addStrips(const std::vector<long long>& indices, const Element& e, long long instance) {
    std::size_t start = 0;
    for (std::size_t k = 0; k < indices.size(); ++k) {
      if (indices[k] == -1) {
        start = k + 1;
        continue;
      }
      checkIndex(indices[k], e, instance);
      if (k < start + 2) continue;
      const long long a = indices[k - 2], b = indices[k - 1], c = indices[k];
      if (a == b || b == c || a == c) continue;
      const bool turned = (k - start) % 2 == 1;
      soup_.addCorner(static_cast<std::uint32_t>(turned ? b : a));
      soup_.addCorner(static_cast<std::uint32_t>(turned ? a : b));
      soup_.addCorner(static_cast<std::uint32_t>(c));
      soup_.closePolygon();
    }
  }

  std::string where(const Element& e, long long instance) const {
    const std::string prefix = format_ == Format::ascii ? at() : path_ + ": ";
    return prefix + e.name + " " + std::to_string(instance);
  }

  /// Walks the ASCII data, one instance per line, and keeps what the mesh needs: each vertex's x,
  /// y, z (every number through std::from_chars, correctly rounded, whatever type the header
  /// declares, so 17 significant digits come back bit for bit) and each face's corner list.
  /// For the vertex element: which property is x, y and z (-1 for other elements); every vertex
  /// element with instances must have all three.
  std::array<int, 3> coordinateProperties(const Element& e) {
    std::array<int, 3> axisOf = {-1, -1, -1};
    if (e.name != "vertex") return axisOf;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const std::string& name = e.properties[k].name;
      if (!e.properties[k].isList && name.size() == 1 && name[0] >= 'x' && name[0] <= 'z') {
        axisOf[static_cast<std::size_t>(name[0] - 'x')] = static_cast<int>(k);
      }
    }
    if (e.count > 0) {
      for (int axis = 0; axis < 3; ++axis) {
        if (axisOf[static_cast<std::size_t>(axis)] < 0) {
          throw InputError(path_ + ": the PLY vertex element has no property " + "xyz"[axis]);
        }
      }
      // Reserved for no more vertices than the data can hold: a header promising 2^32 - 2 of them
      // in a 200-byte file is a truncation to report when the walk reaches the end, not 100 GB to
      // allocate first.
      const std::uint64_t dataBytes = bytes_.size() - dataOffset_ + 1;  // +1: ASCII's last line end may be missing
      const std::uint64_t fits = dataBytes / fewestBytesPerInstance(e);
      soup_.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(static_cast<std::uint64_t>(e.count), fits)));
    }
    return axisOf;
  }

  /// The fewest bytes one instance of \p e takes in the data (at least 1 when it has properties):
  /// binary, its scalars and list counts (a list may be empty); ASCII, one digit per value and one
  /// space or line end after it.
  std::uint64_t fewestBytesPerInstance(const Element& e) const {
    std::uint64_t bytes = 0;
    for (const Property& p : e.properties) {
      bytes += format_ == Format::ascii ? 2 : static_cast<std::uint64_t>(p.isList ? p.countType.bytes : p.valueType.bytes);
    }
    return bytes;
  }

  /// A coordinate must be finite and within +-1e75 (tolerances.h); \p text shows it in the message.
  void requireCoordinate(double value, const Element& e, long long instance, const Property& p,
                         const std::string& text) const {
    if (std::abs(value) <= tolerance::kMaxCoordinate) return;
    throw InputError(where(e, instance) + ": property " + p.name + " is " + text +
                     (std::isfinite(value) ? ", beyond +-1e75, where the distance computation's squared lengths "
                                             "would overflow"
                                           : ", a non-finite coordinate"));
  }

  void walkAscii() {
    std::string_view line;
    for (const Element& e : elements_) {
      const bool isVertex = e.name == "vertex";
      const std::array<int, 3> axisOf = coordinateProperties(e);
      for (long long i = 0; i < e.count; ++i) {
        if (!lines_.next(line)) {
          throw InputError(path_ + ": the file ends after " + std::to_string(i) + " of the " +
                           std::to_string(e.count) + " '" + e.name + "' lines the header promises");
        }
        const std::vector<std::string_view> t = splitWhitespace(line);
        if (t.empty()) throw InputError(at() + "blank line inside the PLY data (one " + e.name + " per line)");
        std::size_t k = 0;
        // The next value, parsed as \p type; \p role names it in a message ("property", "list").
        auto value = [&](const ScalarType& type, const Property& p, const char* role, double& number) -> long long {
          if (k >= t.size()) {
            throw InputError(where(e, i) + ": the line ends before its " + role + " " + p.name + " (one " + e.name +
                             " per line)");
          }
          long long integer = 0;
          const bool ok = type.isInteger ? parseInteger(t[k], integer) : parseDouble(t[k], number);
          if (!ok) {
            throw InputError(where(e, i) + ": " + quoteToken(t[k]) + " is not " +
                             (type.isInteger ? "an integer" : "a number"));
          }
          if (!type.holds(integer)) {
            throw InputError(where(e, i) + ": " + quoteToken(t[k]) + " does not fit the " + role + " " + p.name +
                             "'s type " + type.name);
          }
          if (type.isInteger) number = static_cast<double>(integer);
          ++k;
          return integer;
        };
        Vec3 point = Vec3::Zero();
        for (std::size_t q = 0; q < e.properties.size(); ++q) {
          const Property& p = e.properties[q];
          double number = 0.0;
          if (!p.isList) {
            value(p.valueType, p, "property", number);
            for (int axis = 0; axis < 3; ++axis) {
              if (axisOf[static_cast<std::size_t>(axis)] != static_cast<int>(q)) continue;
              requireCoordinate(number, e, i, p, quoteToken(t[k - 1]));
              point(axis) = number;
            }
            continue;
          }
          const long long n = value(p.countType, p, "length of list", number);
          if (n < 0) throw InputError(where(e, i) + ": list " + p.name + " has negative length " + std::to_string(n));
          requireCorners(n, e, p, i);
          const bool corners = isVertexIndexList(e, p) && p.valueType.isInteger;
          const bool strip = isStripList(e, p) && p.valueType.isInteger;
          stripIndices_.clear();
          for (long long j = 0; j < n; ++j) {
            const long long item = value(p.valueType, p, "list", number);
            if (corners) {
              checkIndex(item, e, i);
              soup_.addCorner(static_cast<std::uint32_t>(item));
            }
            if (strip) stripIndices_.push_back(item);
          }
          if (corners) soup_.closePolygon();
          if (strip) addStrips(stripIndices_, e, i);
        }
        if (k != t.size()) {
          throw InputError(where(e, i) + ": " + std::to_string(t.size() - k) +
                           " values more than the header declares (one " + e.name + " per line)");
        }
        if (isVertex) soup_.points.push_back(point);
      }
    }
  }

  /// The data ends with the instances the header declares: more lines (a face count too low, which
  /// dropped the faces beyond it without a word) are an error, as in OFF. Blank lines may follow.
  void requireNothingAfterAscii() {
    std::string_view line;
    while (lines_.next(line)) {
      const std::vector<std::string_view> t = splitWhitespace(line);
      if (t.empty()) continue;
      const std::string last = elements_.empty() ? std::string("header") : "'" + elements_.back().name + "'";
      throw InputError(at() + "unexpected " + quoteToken(t[0]) + " after the data the header declares (" +
                       (elements_.empty() ? std::string("no elements") : "the last of " +
                                                std::to_string(elements_.back().count) + " " + last + " lines") +
                       "): a count in the header too low?");
    }
  }

  /// The same for binary data: bytes past the last record, other than a line end or padding some
  /// writers leave, are an error.
  void requireNothingAfterBinary() const {
    const std::string_view rest = bytes_.substr(pos_);
    const bool padding =
        std::all_of(rest.begin(), rest.end(), [](char c) { return c == '\n' || c == '\r' || c == ' ' || c == '\0'; });
    if (padding) return;
    throw InputError(path_ + ": " + std::to_string(rest.size()) +
                     " bytes after the last record the header declares: a count in the header too low?");
  }

  /// Reads one binary scalar at pos_ (bounds already checked); integers only are decoded.
  long long readInteger(const ScalarType& type) const {
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + pos_, static_cast<std::size_t>(type.bytes));
    std::uint64_t bits = 0;
    for (int b = 0; b < type.bytes; ++b) {
      const int from = format_ == Format::binaryLittleEndian ? b : type.bytes - 1 - b;
      bits |= static_cast<std::uint64_t>(raw[from]) << (8 * b);
    }
    if (type.isSigned && (bits >> (8 * type.bytes - 1)) & 1u) {
      return static_cast<long long>(bits) - (static_cast<long long>(1) << (8 * type.bytes));
    }
    return static_cast<long long>(bits);
  }

  [[noreturn]] void truncated(const Element& e, long long instance) const {
    throw InputError(path_ + ": truncated binary PLY: " + e.name + " " + std::to_string(instance) + " of " +
                     std::to_string(e.count) + " runs past the end of the file (" + std::to_string(bytes_.size()) +
                     " bytes)");
  }

  void require(std::size_t bytes, const Element& e, long long instance) const {
    if (bytes > bytes_.size() - pos_) truncated(e, instance);
  }

  /// One binary scalar at pos_ (bounds already checked) as a double: integers exactly, float32
  /// and float64 as stored.
  double readNumber(const ScalarType& type) const {
    if (type.isInteger) return static_cast<double>(readInteger(type));
    std::uint64_t bits = 0;
    for (int b = 0; b < type.bytes; ++b) {
      const int from = format_ == Format::binaryLittleEndian ? b : type.bytes - 1 - b;
      bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[pos_ + static_cast<std::size_t>(from)]))
              << (8 * b);
    }
    if (type.bytes == 4) {
      float value;
      const std::uint32_t narrow = static_cast<std::uint32_t>(bits);
      std::memcpy(&value, &narrow, sizeof value);
      return value;
    }
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  /// Walks the binary data record by record and keeps each vertex's x, y, z (as stored: float32 or
  /// float64, converted to double exactly) and each face's corner list.
  void walkBinary() {
    pos_ = dataOffset_;
    for (const Element& e : elements_) {
      const bool isVertex = e.name == "vertex";
      const std::array<int, 3> axisOf = coordinateProperties(e);
      // Instances without properties take no bytes: there is nothing to walk, and walking 2^32 - 1
      // of them one by one, element after element, took minutes.
      if (e.properties.empty()) continue;
      for (long long i = 0; i < e.count; ++i) {
        Vec3 point = Vec3::Zero();
        for (std::size_t q = 0; q < e.properties.size(); ++q) {
          const Property& p = e.properties[q];
          if (!p.isList) {
            require(static_cast<std::size_t>(p.valueType.bytes), e, i);
            for (int axis = 0; axis < 3; ++axis) {
              if (axisOf[static_cast<std::size_t>(axis)] != static_cast<int>(q)) continue;
              const double number = readNumber(p.valueType);
              char text[32];
              requireCoordinate(number, e, i, p, std::string(text, std::to_chars(text, text + sizeof text, number).ptr));
              point(axis) = number;
            }
            pos_ += static_cast<std::size_t>(p.valueType.bytes);
            continue;
          }
          require(static_cast<std::size_t>(p.countType.bytes), e, i);
          const long long n = readInteger(p.countType);
          pos_ += static_cast<std::size_t>(p.countType.bytes);
          if (n < 0) throw InputError(where(e, i) + ": list " + p.name + " has negative length " + std::to_string(n));
          requireCorners(n, e, p, i);
          const std::size_t itemBytes = static_cast<std::size_t>(p.valueType.bytes);
          if (static_cast<std::uint64_t>(n) > (bytes_.size() - pos_) / itemBytes) truncated(e, i);
          if (isVertexIndexList(e, p) && p.valueType.isInteger) {
            for (long long j = 0; j < n; ++j, pos_ += itemBytes) {
              const long long index = readInteger(p.valueType);
              checkIndex(index, e, i);
              soup_.addCorner(static_cast<std::uint32_t>(index));
            }
            soup_.closePolygon();
          } else if (isStripList(e, p) && p.valueType.isInteger) {
            stripIndices_.clear();
            for (long long j = 0; j < n; ++j, pos_ += itemBytes) stripIndices_.push_back(readInteger(p.valueType));
            addStrips(stripIndices_, e, i);
          } else {
            pos_ += static_cast<std::size_t>(n) * itemBytes;
          }
        }
        if (isVertex) soup_.points.push_back(point);
      }
    }
  }

  const std::string& path_;
  std::vector<long long> stripIndices_;  // one tristrips list, read before its triangles are made
  std::string_view bytes_;
  LineScanner lines_;
  Format format_ = Format::ascii;
  std::vector<Element> elements_;
  long long vertexCount_ = 0;
  std::size_t dataOffset_ = 0;
  std::size_t pos_ = 0;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup readPly(const std::string& path, std::string_view bytes) { return PlyChecker(path, bytes).run(); }

}  // namespace adsd::io::detail
