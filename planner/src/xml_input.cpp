#include "xml_input.h"

#include <algorithm>
#include <cstring>

#include "adsd/error.h"

namespace adsd::planner::xml {

namespace {

/// The position just past the first \p terminator at or after \p from, or the end of \p text.
std::size_t pastNext(const std::string& text, std::size_t from, const char* terminator) {
  const std::size_t at = text.find(terminator, from);
  return at == std::string::npos ? text.size() : at + std::strlen(terminator);
}

/// The position just past the '>' that ends the tag opened at \p from, skipping quoted attribute
/// values; \p selfClosing tells whether the tag ended with "/>".
std::size_t pastTag(const std::string& text, std::size_t from, bool& selfClosing) {
  char quote = 0;
  for (std::size_t i = from; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      selfClosing = i > from && text[i - 1] == '/';
      return i + 1;
    }
  }
  selfClosing = false;
  return text.size();
}

}  // namespace

void refuseDeepNesting(const std::string& path, const std::string& text) {
  int depth = 0;
  std::size_t i = 0;
  while ((i = text.find('<', i)) != std::string::npos) {
    if (text.compare(i, 4, "<!--") == 0) {
      i = pastNext(text, i + 4, "-->");
    } else if (text.compare(i, 9, "<![CDATA[") == 0) {
      i = pastNext(text, i + 9, "]]>");
    } else if (text.compare(i, 2, "<?") == 0) {
      i = pastNext(text, i + 2, "?>");
    } else if (text.compare(i, 2, "<!") == 0) {
      i = pastNext(text, i + 2, ">");
    } else if (text.compare(i, 2, "</") == 0) {
      if (depth > 0) --depth;
      i = pastNext(text, i + 2, ">");
    } else {
      const std::size_t opened = i;
      bool selfClosing = false;
      i = pastTag(text, i + 1, selfClosing);
      if (!selfClosing && ++depth > kMaxElementDepth) {
        const long line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(opened), '\n');
        throw InputError(path + ":" + std::to_string(line) + ": elements nested more than " +
                         std::to_string(kMaxElementDepth) + " deep: refused before parsing (a robot description nests about 5 deep)");
      }
    }
  }
}

void parseXml(const std::string& path, const std::string& text, TiXmlDocument& doc) {
  refuseDeepNesting(path, text);
  doc.Parse(text.c_str());
  if (doc.Error()) {
    const std::string line = doc.ErrorRow() > 0 ? ":" + std::to_string(doc.ErrorRow()) : "";
    throw InputError(path + line + ": not XML: " + doc.ErrorDesc());
  }
  // A document has one root element; TinyXML reads on past it, and the readers, which take the
  // first, dropped a second <robot> in silence (an outside review).
  const TiXmlElement* root = doc.FirstChildElement();
  if (root != nullptr && root->NextSiblingElement() != nullptr) {
    const TiXmlElement* second = root->NextSiblingElement();
    throw InputError(path + ":" + std::to_string(second->Row()) + ": not XML: a second root element <" +
                     second->ValueStr() + "> after <" + root->ValueStr() + "> (line " + std::to_string(root->Row()) +
                     ")");
  }
}

}  // namespace adsd::planner::xml
