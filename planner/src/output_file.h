#pragma once
/// \file
/// \brief Internal: writing an output file the user names (a path, an SRDF, a viewer page) so that
/// a failure leaves nothing half-written. Not installed.

#include <functional>
#include <ostream>
#include <string>

namespace adsd::planner {

/// \brief Writes \p path through a temporary name beside it (`PATH.partial`), renamed into place
/// once \p body has written everything; a stream that cannot be opened or fails on the way, or a
/// rename that fails, is an InputError naming the file as \p what ("path file") and leaves no
/// temporary behind. An existing file at \p path is replaced only by a complete one.
void writeOutputFile(const std::string& path, const std::string& what, const std::function<void(std::ostream&)>& body);

}  // namespace adsd::planner
