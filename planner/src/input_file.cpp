#include "input_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "adsd/error.h"
#include "adsd/io/text_encoding.h"

namespace adsd::planner {

void requireNarrowText(const std::string& text, const std::string& sourceName) {
  if (text.find('\0') == std::string::npos) return;
  const std::string encoding = io::wideTextEncoding(text);
  if (!encoding.empty()) {
    throw InputError(sourceName + ": the file is " + encoding + " text; save it as UTF-8 (iconv -f " + encoding +
                     " -t UTF-8)");
  }
  throw InputError(sourceName + ": not a text file (contains a NUL byte)");
}

void dropByteOrderMark(std::string& text) {
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
}

void takeLoneCarriageReturnsAsLineEnds(std::string& text) {
  if (text.find('\n') == std::string::npos) std::replace(text.begin(), text.end(), '\r', '\n');
}

std::string readInputFile(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": " + what + " does not exist");
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a " + what);
  // Read whole: a device or a pipe (/dev/zero) would be read without end, to the memory's limit.
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": is a device, a pipe or a socket, not a " + what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the " + what);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the " + what);
  std::string text = buffer.str();
  dropByteOrderMark(text);
  return text;
}

}  // namespace adsd::planner
