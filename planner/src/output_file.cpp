#include "output_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "adsd/error.h"

namespace adsd::planner {

void writeOutputFile(const std::string& path, const std::string& what, const std::function<void(std::ostream&)>& body) {
  const std::string temporary = path + ".partial";
  {
    // Binary: the bytes written are the file's (a viewer page's scripts, a path's lines), with no
    // line-ending translation on any platform.
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw InputError(path + ": cannot write the " + what);
    try {
      body(out);
    } catch (...) {
      // Nothing half-written is left behind, whatever stopped the body.
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::remove(temporary.c_str());
      throw InputError(path + ": writing the " + what + " failed");
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
