#include "zip_archive.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>

#include "adsd/error.h"

namespace adsd::io::detail {

namespace {

// The zip format's records (PKWARE's APPNOTE), little-endian: the end of central directory
// record, one central directory entry per member, and each member's local header before its data.
constexpr std::string_view kEndOfDirectory("PK\5\6", 4);
constexpr std::string_view kDirectoryEntry("PK\1\2", 4);
constexpr std::string_view kLocalHeader("PK\3\4", 4);
constexpr std::string_view kZip64Locator("PK\6\7", 4);
constexpr std::size_t kEndOfDirectorySize = 22;
constexpr std::size_t kLongestArchiveComment = 0xFFFF;
constexpr std::size_t kDirectoryEntrySize = 46;
constexpr std::size_t kLocalHeaderSize = 30;
constexpr std::uint16_t kStored = 0, kDeflated = 8;
constexpr std::uint16_t kEncryptedFlag = 1;
constexpr std::uint32_t kZip64Marker = 0xFFFFFFFFu;

std::uint32_t little(std::string_view bytes, std::size_t at, int size) {
  std::uint32_t value = 0;
  for (int i = size - 1; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

/// \p compressed inflated (raw deflate, as zip members are), expecting \p size bytes.
std::string inflateMember(const std::string& where, std::string_view compressed, std::size_t size) {
  std::string out(size, '\0');
  z_stream stream{};
  if (inflateInit2(&stream, -MAX_WBITS) != Z_OK) throw InputError(where + ": zlib could not start inflating");
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  stream.avail_in = static_cast<uInt>(compressed.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int status = inflate(&stream, Z_FINISH);
  const std::size_t produced = stream.total_out;
  inflateEnd(&stream);
  // Z_BUF_ERROR with no room left: the data would inflate past the size its header gives.
  if (status != Z_STREAM_END || produced != size) {
    throw InputError(where + ": the deflated data do not inflate to the " + std::to_string(size) +
                     " bytes the archive's directory gives");
  }
  return out;
}

}  // namespace

bool forEachZipMember(const std::string& path, std::string_view bytes,
                      const std::function<bool(std::string_view name)>& wanted,
                      const std::function<void(const std::string& name, std::string_view contents)>& onMember) {
  // The end record lies within the last 22 bytes plus the longest archive comment.
  if (bytes.size() < kEndOfDirectorySize) return false;
  const std::size_t earliest =
      bytes.size() > kEndOfDirectorySize + kLongestArchiveComment ? bytes.size() - kEndOfDirectorySize - kLongestArchiveComment : 0;
  std::size_t end = bytes.rfind(kEndOfDirectory, bytes.size() - kEndOfDirectorySize);
  if (end == std::string_view::npos || end < earliest) return false;
  const std::uint32_t directorySize = little(bytes, end + 12, 4);
  const std::uint32_t directoryOffset = little(bytes, end + 16, 4);
  const std::string zipped = path + ": zip archive";
  // A ZIP64 locator before the end record points unzip to another directory than this one.
  const bool zip64 = end >= 20 && bytes.substr(end - 20, 4) == kZip64Locator;
  if (zip64) throw InputError(zipped + ": ZIP64 is not read, so its members cannot be checked");
  // An end record whose directory does not fit is no zip's (unzip cannot open it either): the
  // signature may occur by chance in a file of another format.
  if (directoryOffset == kZip64Marker || directorySize > end || directoryOffset > end - directorySize) return false;
  // Offsets count from the archive's first byte, which other bytes may precede.
  const std::size_t base = end - directorySize - directoryOffset;
  std::size_t at = base + directoryOffset;
  // Every entry up to the end record, whatever count the record gives: unzip reads on past a
  // count of 0.
  if (bytes.substr(at, 4) != kDirectoryEntry && at != end) return false;
  while (at + 4 <= end && bytes.substr(at, 4) == kDirectoryEntry) {
    if (at + kDirectoryEntrySize > end) throw InputError(zipped + ": a central directory entry runs past its end");
    const std::uint16_t flags = static_cast<std::uint16_t>(little(bytes, at + 8, 2));
    const std::uint16_t method = static_cast<std::uint16_t>(little(bytes, at + 10, 2));
    const std::uint32_t checksum = little(bytes, at + 16, 4);
    const std::uint32_t compressedSize = little(bytes, at + 20, 4), size = little(bytes, at + 24, 4);
    const std::uint32_t nameLength = little(bytes, at + 28, 2), extraLength = little(bytes, at + 30, 2),
                        commentLength = little(bytes, at + 32, 2), localOffset = little(bytes, at + 42, 4);
    if (at + kDirectoryEntrySize + nameLength > end) throw InputError(zipped + ": a member's name runs past its directory");
    const std::string name(bytes.substr(at + kDirectoryEntrySize, nameLength));
    at += kDirectoryEntrySize + nameLength + extraLength + commentLength;
    if (!wanted(name)) continue;

    const std::string where = path + ": zip member '" + name + "'";
    if (flags & kEncryptedFlag) throw InputError(where + " is encrypted, so it cannot be checked");
    if (method != kStored && method != kDeflated) {
      throw InputError(where + " is compressed by method " + std::to_string(method) + ", not deflate, so it cannot be checked");
    }
    if (compressedSize == kZip64Marker || size == kZip64Marker || localOffset == kZip64Marker) {
      throw InputError(where + " is ZIP64, which is not read");
    }
    if (size > kMaxInflatedMemberBytes) {
      throw InputError(where + " inflates to " + std::to_string(size) + " bytes, more than the " +
                       std::to_string(kMaxInflatedMemberBytes) + " a mesh file is allowed here");
    }
    const std::size_t local = base + localOffset;
    if (local + kLocalHeaderSize > bytes.size() || bytes.substr(local, 4) != kLocalHeader) {
      throw InputError(where + ": its local header is not where the directory says");
    }
    const std::uint32_t localNameLength = little(bytes, local + 26, 2);
    // assimp's unzip stops at an assertion when the two copies of a member's header disagree.
    if (local + kLocalHeaderSize + localNameLength > bytes.size() ||
        bytes.substr(local + kLocalHeaderSize, localNameLength) != name ||
        little(bytes, local + 8, 2) != method) {
      throw InputError(where + ": its local header does not match its directory entry: the archive is damaged");
    }
    const std::size_t data = local + kLocalHeaderSize + localNameLength + little(bytes, local + 28, 2);
    if (data > bytes.size() || compressedSize > bytes.size() - data) throw InputError(where + " runs past the end of the file");
    const std::string_view stored = bytes.substr(data, compressedSize);
    if (method == kStored && compressedSize != size) throw InputError(where + " is stored with two different sizes");
    const std::string inflated = method == kStored ? std::string() : inflateMember(where, stored, size);
    const std::string_view contents = method == kStored ? stored : std::string_view(inflated);
    // assimp's unzip aborts the process on a checksum that does not match (an assertion, not an
    // error it reports), so a member it will read is checked here first.
    const auto crc = crc32(0, reinterpret_cast<const Bytef*>(contents.data()), static_cast<uInt>(contents.size()));
    if (static_cast<std::uint32_t>(crc) != checksum) {
      throw InputError(where + " does not match its CRC-32 checksum: the archive is damaged");
    }
    onMember(name, contents);
  }
  return true;
}

}  // namespace adsd::io::detail
