#include "output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

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
  // The whole file is formed in memory first (a path, an SRDF, a viewer page: megabytes at most),
  // so a body that throws leaves nothing on disk. Binary: the bytes are the file's, with no
  // line-ending translation on any platform.
  std::ostringstream buffer(std::ios::binary);
  body(buffer);
  const std::string bytes = buffer.str();
  // The temporary is created anew, never opened through what is there: a symbolic link planted at
  // NAME.partial had the file written into its target (the problem's own mesh, in an adversarial
  // review), and a stale file there is a run that was stopped mid-write. O_EXCL creates the file
  // or fails, following no link; something put back in between is an error, not a target.
  const std::string temporary = path + ".partial";
  ::unlink(temporary.c_str());
  errno = 0;
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw InputError(path + ": cannot write the " + what + systemReason());
  const auto fail = [&](const std::string& message) {
    const std::string reason = systemReason();
    ::close(fd);
    ::unlink(temporary.c_str());
    throw InputError(path + ": " + message + reason);
  };
  for (std::size_t written = 0; written < bytes.size();) {
    errno = 0;
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("writing the " + what + " failed");
    written += static_cast<std::size_t>(n);
  }
  errno = 0;
  if (::close(fd) != 0) {
    const std::string reason = systemReason();
    ::unlink(temporary.c_str());
    throw InputError(path + ": writing the " + what + " failed" + reason);
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    ::unlink(temporary.c_str());
    throw InputError(path + ": cannot rename the finished " + what + " into place: " + ec.message());
  }
}

}  // namespace adsd::planner
