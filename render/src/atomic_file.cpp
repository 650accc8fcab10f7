// Atomic file writing: temporary in the same directory, checked, renamed.
#include "rigid/render/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace rigid::render {

namespace {

// Error messages are one line: a path or reason carrying a line break or other
// control character (a file name may) would split a lab's one-line report.
std::string one_line(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return s;
}

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw std::runtime_error("cannot write '" + one_line(path) + "': " + one_line(reason));
}

// A name no other writer in this process or another can be using: pid and a
// per-process counter (threads), in the target's directory so rename() is atomic.
std::string temporary_name(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write) {
  if (path.empty()) fail(path, "empty file name");
  const std::string tmp = temporary_name(path);
  // O_EXCL: never write through a file (or link) that is already there; 0666
  // less the umask gives an ordinary file's permissions.
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, std::strerror(errno));
  std::FILE* f = ::fdopen(fd, "wb");
  if (f == nullptr) {
    const int e = errno;
    ::close(fd);
    std::remove(tmp.c_str());
    fail(path, std::strerror(e));
  }
  std::string error;
  try {
    write(f);
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown error while writing";
  }
  // A short write (full disk, say) shows as the stream's error flag, or when
  // the buffer is flushed and the file closed.
  if (error.empty() && std::ferror(f)) error = "write error";
  if (std::fflush(f) != 0 && error.empty()) error = std::strerror(errno);
  if (std::fclose(f) != 0 && error.empty()) error = std::strerror(errno);
  if (error.empty() && std::rename(tmp.c_str(), path.c_str()) != 0) error = std::strerror(errno);
  if (!error.empty()) {
    std::remove(tmp.c_str());
    fail(path, error);
  }
}

}  // namespace rigid::render
