#include "output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "adsd/error.h"

namespace adsd::planner {

namespace {

/// ": " and what the system said of the last failed call (a full disk, a file-size limit, a
/// permission), or nothing when it said nothing: the streams keep no reason of their own, and
/// "writing failed" alone left the user to guess.
std::string systemReason() {
  const int error = errno;
  return error != 0 ? std::string(": ") + std::strerror(error) : std::string();
}

}  // namespace

void writeOutputFile(const std::string& path, const std::string& what, const std::function<void(std::ostream&)>& body) {
  const std::string temporary = path + ".partial";
  {
    // Binary: the bytes written are the file's (a viewer page's scripts, a path's lines), with no
    // line-ending translation on any platform.
    errno = 0;
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw InputError(path + ": cannot write the " + what + systemReason());
    try {
      errno = 0;
      body(out);
    } catch (...) {
      // Nothing half-written is left behind, whatever stopped the body.
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      const std::string reason = systemReason();
      out.close();
      std::remove(temporary.c_str());
      throw InputError(path + ": writing the " + what + " failed" + reason);
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(path + ": cannot rename the finished " + what + " into place: " + ec.message());
  }
}

}  // namespace adsd::planner
