// The index-list check for COLLADA files, run before assimp reads them.
//
// Assimp 5.2's COLLADA parser reads a primitive's index list (<p>) number by number until the end
// of its text, and a character that is neither a digit, a sign nor whitespace stops its number
// reader without moving past it: the list then grows by one zero index per step until memory runs
// out. Found by fuzzing (tests/fuzz/regressions/mesh_loader/collada_quote_in_index_list_oom): one
// stray '"' in `<p>0"2 1 ...</p>` made `adsd distance` allocate 12.6 GB in 42 s before
// std::bad_alloc. So every <p> here must hold integers and whitespace only, up to its </p>.
//
// The check reads the raw text, not the XML tree: an index list written with character references
// (&#48;), with CDATA or with a comment inside is refused too, though an XML parser would decode
// it; no exporter writes indices that way, and refusing is safe where guessing is not.

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string>
#include <string_view>

#include "adsd/error.h"
#include "file_checks.h"
#include "text_scan.h"
#include "zip_archive.h"

namespace adsd::io::detail {

namespace {

/// What assimp's index reader steps over: digits, a plus sign, and the whitespace it skips between
/// numbers (space, tab, CR, LF). A minus sign, which it reads too, makes a negative index, which
/// it took as a vertex beyond the list (an extra vertex, 371 of 370) without a word.
bool isIndexListCharacter(char c) {
  return (c >= '0' && c <= '9') || c == '+' || c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// True when \p text at \p at starts the start tag of an element named exactly "p".
bool startsParagraphTag(std::string_view text, std::size_t at) {
  if (text.compare(at, 2, "<p") != 0 || at + 2 >= text.size()) return false;
  const char next = text[at + 2];
  return next == '>' || next == '/' || next == ' ' || next == '\t' || next == '\r' || next == '\n';
}

/// The offset after `</p>` (blanks allowed before the '>') when \p text at \p at starts one, else npos.
std::size_t closingParagraphTagEnd(std::string_view text, std::size_t at) {
  if (text.compare(at, 3, "</p") != 0) return std::string_view::npos;
  std::size_t i = at + 3;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
  return i < text.size() && text[i] == '>' ? i + 1 : std::string_view::npos;
}

int lineOf(std::string_view text, std::size_t at) {
  int line = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

/// Whether \p bytes are a zip archive holding a COLLADA file: a member named *.dae or
/// manifest.xml (a .zae's). assimp tries every file as a zip, whatever its name, and its zip
/// library finds an archive by the directory at its end, so a zip with other bytes before it
/// (a self-extracting one) is one too: both the members' local headers and the central
/// directory's entries are searched, each naming its member uncompressed.
bool zipHoldsCollada(std::string_view bytes) {
  auto little16 = [&](std::size_t at) {
    return static_cast<std::size_t>(static_cast<unsigned char>(bytes[at])) |
           static_cast<std::size_t>(static_cast<unsigned char>(bytes[at + 1])) << 8;
  };
  auto namesCollada = [&](std::size_t nameAt, std::size_t length) {
    if (nameAt + length > bytes.size()) return false;
    std::string name(bytes.substr(nameAt, length));
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    auto endsWith = [&](std::string_view tail) {
      return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    return endsWith(".dae") || endsWith("manifest.xml");
  };
  // {signature, offset of the name's length, offset of the name} of a local header and of a
  // central directory entry.
  struct Record {
    std::string_view signature;
    std::size_t lengthAt, nameAt;
  };
  const Record records[] = {{std::string_view("PK\3\4", 4), 26, 30}, {std::string_view("PK\1\2", 4), 28, 46}};
  for (const Record& r : records) {
    for (std::size_t at = bytes.find(r.signature); at != std::string_view::npos; at = bytes.find(r.signature, at + 1)) {
      if (at + r.nameAt > bytes.size()) break;
      if (namesCollada(at + r.nameAt, little16(at + r.lengthAt))) return true;
    }
  }
  return false;
}

}  // namespace

bool readAsCollada(const std::string& path, std::string_view bytes) {
  if (lowerCaseExtension(path) == ".dae") return true;
  static const char kTag[] = "<collada";
  std::size_t matched = 0;
  for (const char c : bytes) {
    if (c == '\0') continue;
    matched = std::tolower(static_cast<unsigned char>(c)) == kTag[matched] ? matched + 1 : (c == '<' ? 1 : 0);
    if (matched == sizeof kTag - 1) return true;
  }
  return false;
}

void checkZippedCollada(const std::string& path, std::string_view bytes) {
  // Every member of any zip is read back and matched against its checksum: assimp opens every
  // file as a zip (COLLADA, 3MF), reads textures from it too, and aborts on a damaged member. A
  // member that is COLLADA by its name or its content has its index lists checked: assimp reads
  // the one manifest.xml names, whatever that name is, or else the first .dae.
  const bool read = forEachZipMember(path, bytes, [](std::string_view) { return true; },
                                     [&](const std::string& name, std::string_view contents) {
                                       if (readAsCollada(name, contents)) {
                                         requireIntegerIndexLists(path + " (" + name + ")", contents);
                                       }
                                     });
  if (!read && (lowerCaseExtension(path) == ".zae" || zipHoldsCollada(bytes))) {
    throw InputError(path + ": zipped COLLADA without a central directory: the COLLADA inside cannot be checked "
                            "before assimp reads it");
  }
}

void requireIntegerIndexLists(const std::string& path, std::string_view text) {
  if (text.find('\0') != std::string_view::npos) {
    std::string narrowed;
    std::copy_if(text.begin(), text.end(), std::back_inserter(narrowed), [](char c) { return c != '\0'; });
    requireIntegerIndexLists(path, narrowed);
    return;
  }
  std::size_t at = 0;
  while ((at = text.find('<', at)) != std::string_view::npos) {
    if (text.compare(at, 4, "<!--") == 0) {  // a comment may mention <p> freely
      const std::size_t end = text.find("-->", at + 4);
      if (end == std::string_view::npos) return;  // unterminated: the XML parser reports it
      at = end + 3;
      continue;
    }
    if (!startsParagraphTag(text, at)) {
      ++at;
      continue;
    }
    const std::size_t tagEnd = text.find('>', at);
    if (tagEnd == std::string_view::npos) return;  // unterminated tag: the XML parser reports it
    at = tagEnd + 1;
    if (text[tagEnd - 1] == '/') continue;  // <p/>: an empty list
    std::size_t i = at;
    while (i < text.size() && isIndexListCharacter(text[i])) ++i;
    if (const std::size_t end = closingParagraphTagEnd(text, i); end != std::string_view::npos) {
      at = end;
      continue;
    }
    const std::string where = path + ":" + std::to_string(lineOf(text, i));
    if (i < text.size() && text[i] == '-') {
      throw InputError(where + ": the index list <p> holds a negative index (indices start at 0)");
    }
    const std::string what = i < text.size() ? quoteToken(text.substr(i, 1)) : std::string("the end of the file");
    throw InputError(where + ": the index list <p> holds " + what +
                     "; expected integers separated by whitespace up to </p>");
  }
}

}  // namespace adsd::io::detail
