#pragma once
/// \file
/// \brief Internal: parsing the XML of a URDF or SRDF file with TinyXML so that every failure is
/// one adsd::InputError naming the file and, where TinyXML knows it, the line.
///
/// TinyXML (ours, and urdfdom's) parses each element by a recursive call, so that a few hundred
/// kilobytes of `<z><z><z>...` overflow the stack: refuseDeepNesting() scans first, flat and
/// linear. Not installed.

#include <string>

#include <tinyxml.h>

namespace adsd::planner::xml {

/// Deepest element nesting accepted. Real URDF and SRDF files nest about 5 deep (robot, link,
/// collision, geometry, mesh); TinyXML2 refuses beyond 500 for the same reason, and 500 of
/// TinyXML's recursive frames fit in the stack with room to spare, even under AddressSanitizer.
constexpr int kMaxElementDepth = 500;

/// \brief Throws an InputError "PATH:LINE: elements nested more than 500 deep ..." when \p text
/// nests elements deeper than kMaxElementDepth.
///
/// Comments, processing instructions, CDATA sections, declarations and quoted attribute values
/// are skipped, so that a '<' or '/>' inside them is not counted. Mismatched tags are left for the
/// parser to report.
void refuseDeepNesting(const std::string& path, const std::string& text);

/// \brief Parses \p text into \p doc after refuseDeepNesting(); a syntax error is an InputError
/// "PATH:LINE: not XML: ...", without the line when TinyXML does not know it (an empty file, one
/// cut off inside an element: it reports row 0).
void parseXml(const std::string& path, const std::string& text, TiXmlDocument& doc);

}  // namespace adsd::planner::xml
