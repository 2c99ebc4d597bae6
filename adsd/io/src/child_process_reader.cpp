#include "child_process_reader.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <string_view>
#include <type_traits>

#include "adsd/error.h"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define ADSD_UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define ADSD_UNDER_SANITIZER 1
#endif
#endif

#ifdef ADSD_UNDER_SANITIZER
#include <sanitizer/common_interface_defs.h>
#endif

namespace adsd::io::detail {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_trivially_copyable_v<TriangleIndices> &&
                  sizeof(TriangleIndices) == 3 * sizeof(std::uint32_t),
              "the child sends vertices and triangles as their bytes");

/// What the child writes to the pipe: one tag byte, the answer's length in bytes (std::uint64_t),
/// then the answer. The parent stops reading once it has that many: it need not wait for the end
/// of the pipe, which a child forked meanwhile by another thread's load could hold open.
constexpr char kTriangles = 'T';  // four std::uint64_t (vertex, triangle, line, point counts), the arrays
constexpr char kError = 'E';      // the InputError's message
constexpr std::size_t kFrameHead = 1 + sizeof(std::uint64_t);

/// Writes all of \p bytes to \p fd; false when the pipe is gone (the parent stopped reading).
bool writeAll(int fd, const void* bytes, std::size_t count) {
  const char* p = static_cast<const char*>(bytes);
  while (count > 0) {
    const ssize_t n = ::write(fd, p, count);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    count -= static_cast<std::size_t>(n);
  }
  return true;
}

/// In the child: caps its address space at what it holds plus \p budget, so that a reader asking
/// for tens of gigabytes gets std::bad_alloc instead of the machine's memory.
void capAddressSpace(std::uint64_t budget) {
#ifndef ADSD_UNDER_SANITIZER
  // The address space the child holds already, from /proc/self/statm (pages).
  std::uint64_t pages = 0;
  if (std::ifstream statm("/proc/self/statm"); !(statm >> pages)) return;
  const std::uint64_t now = pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  rlimit cap{};
  cap.rlim_cur = cap.rlim_max = static_cast<rlim_t>(now + std::min(budget, ~std::uint64_t{0} - now));
  ::setrlimit(RLIMIT_AS, &cap);
#else
  (void)budget;
#endif
}

/// The child's whole life: read, send the answer or the error, exit without running the parent's
/// exit handlers or flushing its stdio buffers (they were copied at the fork).
/// noexcept: whatever escapes (a message that cannot be built after std::bad_alloc) aborts the
/// child, reported as a crash, instead of running on in the parent's code.
[[noreturn]] void runChild(int pipeEnd, const std::string& path, const std::function<ReadTriangles()>& read,
                           const ReaderLimits& limits) noexcept {
  // The write end above the standard descriptors (a parent run with some of them closed may have
  // been given one), and no other descriptor kept: another thread's load must see the end of its
  // pipe when its own child ends, not when this one does.
  const int fd = ::fcntl(pipeEnd, F_DUPFD, 3);
  if (fd < 0) ::_exit(1);
  ::close_range(3, static_cast<unsigned>(fd) - 1, 0);
  ::close_range(static_cast<unsigned>(fd) + 1, ~0u, 0);
  // A reader's own complaints (and a C++ runtime's last words) would mix into the parent's
  // output; the parent reports what happened in one line instead.
  if (const int devNull = ::open("/dev/null", O_WRONLY); devNull >= 0) {
    ::dup2(devNull, STDERR_FILENO);
    ::dup2(devNull, STDOUT_FILENO);
    ::close(devNull);
  }
  // A crash in the reader must end the child by its signal, for the parent to report. The
  // parent's handlers would act on the child's crash as on their own: a crash reporter's, a
  // sanitizer's report (and libFuzzer's death callback, which would save the parent's input as a
  // finding).
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP}) {
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    ::sigemptyset(&fallback.sa_mask);
    ::sigaction(signal, &fallback, nullptr);
  }
  sigset_t all;
  ::sigfillset(&all);
  ::sigprocmask(SIG_UNBLOCK, &all, nullptr);
#ifdef ADSD_UNDER_SANITIZER
  __sanitizer_set_death_callback(nullptr);
#endif
  capAddressSpace(limits.memoryBytes);
  std::string error;
  try {
    const ReadTriangles t = read();
    const std::uint64_t header[4] = {t.vertices.size(), t.triangles.size(), t.lines, t.points};
    const std::uint64_t length =
        sizeof header + t.vertices.size() * sizeof(Vec3) + t.triangles.size() * sizeof(TriangleIndices);
    const bool sent = writeAll(fd, &kTriangles, 1) && writeAll(fd, &length, sizeof length) &&
                      writeAll(fd, header, sizeof header) &&
                      writeAll(fd, t.vertices.data(), t.vertices.size() * sizeof(Vec3)) &&
                      writeAll(fd, t.triangles.data(), t.triangles.size() * sizeof(TriangleIndices));
    ::_exit(sent ? 0 : 1);
  } catch (const InputError& e) {
    error = e.what();
  } catch (const std::bad_alloc&) {
#ifdef ADSD_UNDER_SANITIZER
    error = path + ": out of memory while loading the mesh (in assimp)";
#else
    error = path + ": out of memory while loading the mesh (assimp asked for more than its limit of " +
            std::to_string(limits.memoryBytes >> 20) + " MiB)";
#endif
  } catch (const std::exception& e) {
    error = path + ": cannot be parsed: " + e.what();
  } catch (...) {
    error = path + ": cannot be parsed: assimp's reader failed";
  }
  const std::uint64_t length = error.size();
  const bool sent = writeAll(fd, &kError, 1) && writeAll(fd, &length, sizeof length) &&
                    writeAll(fd, error.data(), error.size());
  ::_exit(sent ? 0 : 1);
}

/// How many bytes the answer in \p bytes takes, head included, once its head has arrived.
std::uint64_t frameSize(const std::string& bytes) {
  if (bytes.size() < kFrameHead) return UINT64_MAX;
  std::uint64_t length = 0;
  std::memcpy(&length, bytes.data() + 1, sizeof length);
  return length > UINT64_MAX - kFrameHead ? UINT64_MAX : kFrameHead + length;
}

/// Reads the pipe until the answer is complete or the pipe ends, or until \p deadline; false on
/// the deadline.
bool readAnswer(int fd, std::chrono::steady_clock::time_point deadline, std::string& out) {
  char buffer[1 << 16];
  for (;;) {
    if (out.size() >= frameSize(out)) return true;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) return true;  // nothing more can be read: judged by what came
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

/// The child's answer, as runChild wrote it; \p complete is false when it was cut short.
ReadTriangles decode(const std::string& all, bool& complete) {
  complete = false;
  ReadTriangles t;
  if (frameSize(all) != all.size()) return t;
  const std::string_view bytes = std::string_view(all).substr(kFrameHead);
  if (all[0] == kError) {
    // One line, whatever a reader's exception said.
    std::string message(bytes);
    std::replace_if(message.begin(), message.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    throw InputError(message);
  }
  std::uint64_t header[4];
  if (all[0] != kTriangles || bytes.size() < sizeof header) return t;
  std::memcpy(header, bytes.data(), sizeof header);
  const std::uint64_t payload = bytes.size() - sizeof header;
  if (header[0] > payload / sizeof(Vec3) || header[1] > payload / sizeof(TriangleIndices) ||
      header[0] * sizeof(Vec3) + header[1] * sizeof(TriangleIndices) != payload) {
    return t;
  }
  const char* data = bytes.data() + sizeof header;
  // (An empty vector's data() may be null, which memcpy may not be given even for 0 bytes.)
  t.vertices.resize(header[0]);
  if (header[0] > 0) std::memcpy(static_cast<void*>(t.vertices.data()), data, header[0] * sizeof(Vec3));
  t.triangles.resize(header[1]);
  if (header[1] > 0) {
    std::memcpy(t.triangles.data(), data + header[0] * sizeof(Vec3), header[1] * sizeof(TriangleIndices));
  }
  t.lines = header[2];
  t.points = header[3];
  complete = true;
  return t;
}

/// The child until it is waited for: closes the read end and, unless reaped, kills and waits for
/// the child, whatever leaves readInChildProcess (std::bad_alloc while gathering a large answer).
struct ChildGuard {
  pid_t pid;
  int readEnd;
  bool reaped = false;
  ChildGuard(const ChildGuard&) = delete;
  ChildGuard& operator=(const ChildGuard&) = delete;
  ~ChildGuard() {
    closeReadEnd();
    if (!reaped) {
      ::kill(pid, SIGKILL);
      wait();
    }
  }
  void closeReadEnd() {
    if (readEnd >= 0) ::close(readEnd);
    readEnd = -1;
  }
  /// Waits for the child; its status, or none when it was reaped elsewhere (SIGCHLD ignored).
  std::optional<int> wait() {
    int status = 0;
    pid_t waited;
    do {
      waited = ::waitpid(pid, &status, 0);
    } while (waited < 0 && errno == EINTR);
    reaped = true;
    return waited == pid ? std::optional<int>(status) : std::nullopt;
  }
};

std::string signalName(int signal) {
  const char* name = ::strsignal(signal);
  return (name != nullptr ? std::string(name) : "signal") + " (" + std::to_string(signal) + ")";
}

}  // namespace

ReaderLimits effectiveLimits(const ReaderLimits& limits, std::uint64_t fileBytes) {
  ReaderLimits out = limits;
  if (!(out.seconds > 0.0) || !std::isfinite(out.seconds)) out.seconds = 10.0 + static_cast<double>(fileBytes) / 1e6;
  if (out.memoryBytes == 0) {
    const std::uint64_t perByte = fileBytes > (~std::uint64_t{0} >> 6) ? ~std::uint64_t{0} : fileBytes << 6;
    out.memoryBytes = std::max(std::uint64_t{4} << 30, perByte);
  }
  return out;
}

ReadTriangles readInChildProcess(const std::string& path, const std::function<ReadTriangles()>& read,
                                 const ReaderLimits& limits) {
  // Close-on-exec, for a program another thread of this one may start meanwhile; children of
  // other loads close what they inherit (runChild).
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return read();
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return read();
  }
  if (child == 0) {
    ::close(fds[0]);
    runChild(fds[1], path, read, limits);
  }
  ::close(fds[1]);
  ChildGuard guard{child, fds[0]};
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(std::min(limits.seconds, 1e7)));
  std::string bytes;
  const bool finished = readAnswer(fds[0], deadline, bytes);
  guard.closeReadEnd();
  if (!finished) ::kill(child, SIGKILL);
  // A parent that ignores SIGCHLD has its children reaped for it: no status then, and the
  // answer alone decides (a crash reads as an answer cut short).
  const std::optional<int> status = guard.wait();
  if (!finished) {
    std::ostringstream what;
    what.precision(3);
    what << path << ": assimp did not finish reading the file within " << limits.seconds
         << " s and was stopped (a damaged file can make some of its readers loop)";
    throw InputError(what.str());
  }
  if (status && WIFSIGNALED(*status)) {
    const int signal = WTERMSIG(*status);
    std::string what = path + ": assimp's reader crashed on the file (" + signalName(signal) +
                       "): it is damaged, or in a form assimp cannot read";
    if (signal == SIGKILL) what += " (or the system stopped it for lack of memory)";
    throw InputError(what);
  }
  bool complete = false;
  ReadTriangles t = decode(bytes, complete);
  if (!complete) {
    std::string what = path + ": assimp's reader stopped without an answer";
    if (status && WIFEXITED(*status)) what += " (exit status " + std::to_string(WEXITSTATUS(*status)) + ")";
    throw InputError(what);
  }
  return t;
}

}  // namespace adsd::io::detail
