#include "basis/child_process.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace sscc::detail {

namespace {

bool write_all(int fd, const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::write(fd, p, bytes);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

/// What the child sends before its bytes: whether they are an error message, and their size.
struct Header {
  std::uint64_t failed;
  std::uint64_t size;
};

}  // namespace

std::string run_in_child(const std::string& what, const std::function<std::string()>& work) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(what + ": cannot create a pipe");
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(what + ": cannot fork");
  }
  if (child == 0) {
    // A crash is the child's end: handlers the caller installed (a test framework's, a crash
    // reporter's) must not run the caller's code on in the child.
    for (int crash : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL}) std::signal(crash, SIG_DFL);
    ::close(fds[0]);
    std::string bytes;
    Header header{0, 0};
    try {
      bytes = work();
    } catch (const std::exception& e) {
      bytes = e.what();
      header.failed = 1;
    }
    header.size = bytes.size();
    const bool sent = write_all(fds[1], &header, sizeof header) && write_all(fds[1], bytes.data(), bytes.size());
    ::close(fds[1]);
    ::_exit(sent ? 0 : 3);
  }
  ::close(fds[1]);
  std::string received;
  char buffer[1 << 16];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    received.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    throw std::runtime_error(what + " crashed (signal " + std::to_string(WTERMSIG(status)) + ")");
  Header header{0, 0};
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || received.size() < sizeof header) {
    throw std::runtime_error(what + " failed without a result");
  }
  std::memcpy(&header, received.data(), sizeof header);
  if (received.size() != sizeof header + header.size) throw std::runtime_error(what + " failed without a result");
  std::string bytes = received.substr(sizeof header);
  if (header.failed) throw std::runtime_error(bytes);
  return bytes;
}

}  // namespace sscc::detail
