#include "file_checks.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "adsd/error.h"
#include "adsd/io/text_encoding.h"
#include "text_scan.h"

namespace adsd::io::detail {

namespace {

namespace fs = std::filesystem;

// Binary STL layout: an 80-byte free-form header, a little-endian uint32 triangle count, then 50
// bytes per triangle (normal, three corners as 12 float32, a 2-byte attribute).
constexpr std::uintmax_t kStlHeaderBytes = 80;
constexpr std::uintmax_t kStlPreambleBytes = kStlHeaderBytes + 4;
constexpr std::uintmax_t kStlBytesPerTriangle = 50;
// How much of the file decides "ASCII or binary": enough to pass the header and the first facets.
constexpr std::size_t kStlSniffBytes = 512;

bool startsWithSolid(std::string_view head) {
  // After a UTF-8 byte-order mark, as the ASCII reader's lines are (text_scan.h).
  std::size_t i = head.substr(0, kUtf8ByteOrderMark.size()) == kUtf8ByteOrderMark ? kUtf8ByteOrderMark.size() : 0;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  static const char kSolid[] = "solid";
  for (std::size_t k = 0; k < 5; ++k, ++i) {
    if (i >= head.size() || std::tolower(static_cast<unsigned char>(head[i])) != kSolid[k]) return false;
  }
  return true;
}

/// Offset of the first control byte other than whitespace, or npos. Bytes >= 0x80 count as text
/// so that a UTF-8 solid name stays ASCII STL.
std::size_t firstControlByte(std::string_view head) {
  for (std::size_t i = 0; i < head.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(head[i]);
    if (c < 0x20 && !std::isspace(c)) return i;
  }
  return std::string_view::npos;
}

/// The first \p count bytes of the file (fewer if it is shorter).
std::string readFile(const std::string& path, std::uintmax_t count) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(count), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (in.bad()) throw InputError(path + ": read error");
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

}  // namespace

std::uintmax_t requireReadableFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) throw InputError(path + ": no such file");
  if (ec) throw InputError(path + ": cannot be examined: " + ec.message());
  if (status.type() == fs::file_type::directory) {
    throw InputError(path + ": is a directory, not a mesh file");
  }
  if (status.type() != fs::file_type::regular) throw InputError(path + ": is not a regular file");

  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw InputError(path + ": cannot be opened for reading: " + std::strerror(errno));

  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot be examined: " + ec.message());
  if (size == 0) {
    // Files of /proc and /sys report size 0 and are read to their end, not to a size.
    if (probe.get() != std::ifstream::traits_type::eof()) {
      throw InputError(path +
                       ": reports a size of 0 but holds data (a /proc or /sys file?): copy it to a regular file");
    }
    throw InputError(path + ": the file is empty");
  }
  return size;
}

// ASCII STL starts with "solid" and is text. A binary STL may also start with "solid" (some
// exporters write it into the free-form header), but its triangle count (whose high bytes are zero
// below 2^24 triangles) and float data put control bytes within the first few hundred bytes.
// A binary STL is read only at exactly 84 + 50 * count bytes (a longer file is as likely a
// corrupt one as one with trailing junk); each way of missing that gets its own message.
bool isBinaryStl(std::string_view head) {
  head = head.substr(0, kStlSniffBytes);
  return !startsWithSolid(head) || firstControlByte(head) != std::string_view::npos;
}

void requireCompleteBinaryStl(const std::string& path, std::string_view head, std::uintmax_t sizeInBytes) {
  head = head.substr(0, kStlSniffBytes);
  const bool solid = startsWithSolid(head);
  const std::size_t control = firstControlByte(head);
  if (!isBinaryStl(head)) return;  // ASCII STL: its reader reports its errors, with lines

  const std::string what = solid ? path + ": neither ASCII STL (byte " + std::to_string(control) +
                                       " is a control character) nor a complete binary STL: "
                                 : path + ": ";
  if (sizeInBytes < kStlPreambleBytes || head.size() < kStlPreambleBytes) {
    throw InputError(what + "truncated binary STL: " + std::to_string(sizeInBytes) + " bytes, shorter than the " +
                     std::to_string(kStlPreambleBytes) + "-byte header and triangle count");
  }
  std::uint32_t promised = 0;
  for (int b = 3; b >= 0; --b) {
    promised = promised << 8 | static_cast<unsigned char>(head[kStlHeaderBytes + static_cast<std::size_t>(b)]);
  }
  if (promised == 0) throw InputError(what + "the file holds no triangles (the binary STL header promises 0)");
  const std::uintmax_t needed = kStlPreambleBytes + kStlBytesPerTriangle * promised;
  if (sizeInBytes < needed) {
    throw InputError(what + "truncated binary STL: the header promises " + std::to_string(promised) +
                     " triangles (" + std::to_string(needed) + " bytes) but the file has " +
                     std::to_string(sizeInBytes) + " bytes");
  }
  if (sizeInBytes > needed) {
    throw InputError(what + "binary STL with " + std::to_string(sizeInBytes - needed) +
                     " bytes after the " + std::to_string(promised) +
                     " triangles its header promises (a binary STL is read only at its exact size)");
  }
}

std::string lowerCaseExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void requireNarrowText(const std::string& path, std::string_view bytes, MeshReader reader) {
  const std::string encoding = wideTextEncoding(bytes);
  if (encoding.empty()) return;
  if (reader == MeshReader::stl && bytes.size() >= kStlPreambleBytes) {
    std::uint32_t count = 0;
    for (int i = 3; i >= 0; --i) count = count << 8 | static_cast<unsigned char>(bytes[kStlHeaderBytes + i]);
    if (bytes.size() == kStlPreambleBytes + kStlBytesPerTriangle * std::uintmax_t{count}) return;
  }
  throw InputError(path + ": the text is " + encoding + " (it starts with that byte-order mark); mesh files are " +
                   "read as ASCII or UTF-8: convert it, e.g. iconv -f " + encoding.substr(0, 6) + " -t UTF-8");
}

MeshReader chooseReader(const std::string& path, std::string_view bytes) {
  const std::string ext = lowerCaseExtension(path);
  if (ext == ".obj") return MeshReader::obj;
  if (ext == ".off") return MeshReader::off;
  if (ext == ".ply") return MeshReader::ply;
  if (ext == ".stl") return MeshReader::stl;
  const auto startsWithCaseless = [&](std::string_view word) {
    if (bytes.size() < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i) {
      if (std::tolower(static_cast<unsigned char>(bytes[i])) != word[i]) return false;
    }
    return true;
  };
  if (startsWithCaseless("ply")) return MeshReader::ply;
  if (startsWithOffKeyword(bytes)) return MeshReader::off;
  if (startsWithSolid(bytes.substr(0, kStlSniffBytes))) return MeshReader::stl;
  return MeshReader::assimp;
}

std::string readWholeFile(const std::string& path) {
  return readFile(path, requireReadableFile(path));
}

}  // namespace adsd::io::detail
