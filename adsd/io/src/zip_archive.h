#pragma once
/// \file
/// \brief The members of a zip archive held in memory, found through its central directory and
/// inflated with zlib: what assimp would unzip from a zipped COLLADA (.zae) before reading it,
/// read here first so that the COLLADA inside can be checked (collada_check.cpp).

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace adsd::io::detail {

/// Most bytes a member may inflate to: a zip of a few kilobytes can promise gigabytes (a "zip
/// bomb"), and the check would hold them all in memory.
constexpr std::size_t kMaxInflatedMemberBytes = std::size_t{1} << 30;

/// \brief Calls \p onMember(name, contents) for each member of the zip archive in \p bytes whose
/// name \p wanted accepts, with its contents stored or inflated. The archive may follow other
/// bytes (a self-extracting one), as zip readers allow. Returns false when \p bytes hold no
/// central directory where an end record says (not a zip, or a cut one). Throws InputError naming \p path for a member
/// that cannot be read back: encrypted, compressed other than by deflate, ZIP64, sizes beyond
/// kMaxInflatedMemberBytes, records that do not fit the file, or contents that do not match
/// their CRC-32 checksum.
bool forEachZipMember(const std::string& path, std::string_view bytes,
                      const std::function<bool(std::string_view name)>& wanted,
                      const std::function<void(const std::string& name, std::string_view contents)>& onMember);

}  // namespace adsd::io::detail
