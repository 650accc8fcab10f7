// A child program (subprocess.h), over posix_spawn: no fork of a large process, and a
// failed exec is reported to the caller, not by the child. A child that must die with
// its parent is forked (the request is made between fork and exec), its failed exec
// told through a close-on-exec pipe.
#include "rigid/support/subprocess.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <system_error>
#include <utility>

extern char** environ;

namespace rigid::support {

namespace {

// A posix_spawn object, destroyed on every path out.
template <class T, int (*Init)(T*), int (*Destroy)(T*)>
struct Scoped {
  T value;
  Scoped() { Init(&value); }
  ~Scoped() { Destroy(&value); }
  Scoped(const Scoped&) = delete;
  Scoped& operator=(const Scoped&) = delete;
};
using FileActions = Scoped<posix_spawn_file_actions_t, posix_spawn_file_actions_init,
                           posix_spawn_file_actions_destroy>;
using SpawnAttributes = Scoped<posix_spawnattr_t, posix_spawnattr_init, posix_spawnattr_destroy>;

// `stream` (1 or 2) of the child as `redirect` says; the pipe's ends in `ends` if it is one.
void redirect(FileActions& f, int stream, const Redirect& redirect, const int ends[2]) {
  switch (redirect.to) {
    case Redirect::To::kInherit:
      break;
    case Redirect::To::kNull:
      posix_spawn_file_actions_addopen(&f.value, stream, "/dev/null", O_WRONLY, 0);
      break;
    case Redirect::To::kPipe:
      posix_spawn_file_actions_adddup2(&f.value, ends[1], stream);
      break;
    case Redirect::To::kFile:
      posix_spawn_file_actions_adddup2(&f.value, redirect.fd, stream);
      break;
  }
}

}  // namespace

Subprocess::Subprocess(const std::filesystem::path& path, const std::vector<std::string>& args,
                       const Options& options) {
  const bool piped = options.out.to == Redirect::To::kPipe || options.err.to == Redirect::To::kPipe;
  // close-on-exec: the child keeps only its dup2'd copy, so the pipe ends when it does
  int ends[2] = {-1, -1};
  if (piped && ::pipe2(ends, O_CLOEXEC) != 0) {
    throw std::system_error(errno, std::generic_category(), "pipe");
  }
  // execv's argv is of char*: the strings' own buffers, copied here, are writable
  std::vector<std::string> words = args;
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  try {
    if (options.end_with_parent) {
      fork_exec(path, argv.data(), options, ends);
    } else {
      spawn(path, argv.data(), options, ends);
    }
  } catch (...) {
    if (piped) {
      ::close(ends[0]);
      ::close(ends[1]);
    }
    pid_ = -1;
    throw;
  }
  if (piped) {
    ::close(ends[1]);
    pipe_ = ends[0];
    ::fcntl(pipe_, F_SETFL, ::fcntl(pipe_, F_GETFL) | O_NONBLOCK);
  }
}

void Subprocess::spawn(const std::filesystem::path& path, char* const argv[],
                       const Options& options, const int ends[2]) {
  FileActions actions;
  redirect(actions, STDOUT_FILENO, options.out, ends);
  redirect(actions, STDERR_FILENO, options.err, ends);
  SpawnAttributes attributes;
  if (options.signal_mask != nullptr) {
    posix_spawnattr_setsigmask(&attributes.value, options.signal_mask);
    posix_spawnattr_setflags(&attributes.value, POSIX_SPAWN_SETSIGMASK);
  }
  const int spawned =
      ::posix_spawn(&pid_, path.c_str(), &actions.value, &attributes.value, argv, environ);
  if (spawned != 0) throw std::system_error(spawned, std::generic_category(), path.string());
}

namespace {

// In the child between fork and exec (this process may have other threads, whose locks
// the child holds copies of): async-signal-safe calls only. Its stream as `redirect`
// says; false if it could not be set.
bool redirect_in_child(int stream, const Redirect& redirect, const int ends[2]) {
  switch (redirect.to) {
    case Redirect::To::kInherit:
      return true;
    case Redirect::To::kNull: {
      const int fd = ::open("/dev/null", O_WRONLY);
      if (fd < 0) return false;
      const bool ok = fd == stream || ::dup2(fd, stream) == stream;
      if (fd != stream) ::close(fd);
      return ok;
    }
    case Redirect::To::kPipe:
      return ::dup2(ends[1], stream) == stream;
    case Redirect::To::kFile:
      return redirect.fd == stream || ::dup2(redirect.fd, stream) == stream;
  }
  return false;
}

}  // namespace

void Subprocess::fork_exec(const std::filesystem::path& path, char* const argv[],
                           const Options& options, const int ends[2]) {
  // the child's errno if it cannot exec, through a pipe that exec closes
  int failure[2] = {-1, -1};
  if (::pipe2(failure, O_CLOEXEC) != 0)
    throw std::system_error(errno, std::generic_category(), "pipe");
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ == 0) {
    ::close(failure[0]);
    // asked to end when the parent does; a parent already gone (the child adopted before
    // the request took) is seen by getppid, and the child ends at once
    int error = 0;
    if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || ::getppid() != parent) ::_exit(127);
    if (!redirect_in_child(STDOUT_FILENO, options.out, ends) ||
        !redirect_in_child(STDERR_FILENO, options.err, ends) ||
        (options.signal_mask != nullptr &&
         ::sigprocmask(SIG_SETMASK, options.signal_mask, nullptr) != 0)) {
      error = errno;
    } else {
      ::execv(path.c_str(), argv);
      error = errno;
    }
    [[maybe_unused]] const ssize_t said = ::write(failure[1], &error, sizeof error);
    ::_exit(127);
  }
  const int fork_error = errno;
  ::close(failure[1]);
  if (pid_ < 0) {
    ::close(failure[0]);
    throw std::system_error(fork_error, std::generic_category(), "fork");
  }
  int error = 0;
  ssize_t n = 0;
  while ((n = ::read(failure[0], &error, sizeof error)) < 0 && errno == EINTR) {
  }
  ::close(failure[0]);
  if (n == static_cast<ssize_t>(sizeof error)) {
    while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
    throw std::system_error(error, std::generic_category(), path.string());
  }
}

Subprocess::~Subprocess() {
  if (pid_ > 0 && !status_) terminate();
  close_pipe();
}

Subprocess::Subprocess(Subprocess&& other) noexcept
    : pid_(std::exchange(other.pid_, -1)),
      pipe_(std::exchange(other.pipe_, -1)),
      status_(std::exchange(other.status_, std::nullopt)),
      peak_bytes_(std::exchange(other.peak_bytes_, 0)) {}

Subprocess& Subprocess::operator=(Subprocess&& other) noexcept {
  if (this != &other) {
    if (pid_ > 0 && !status_) terminate();
    close_pipe();
    pid_ = std::exchange(other.pid_, -1);
    pipe_ = std::exchange(other.pipe_, -1);
    status_ = std::exchange(other.status_, std::nullopt);
    peak_bytes_ = std::exchange(other.peak_bytes_, 0);
  }
  return *this;
}

void Subprocess::close_pipe() {
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
}

std::string Subprocess::read_available() {
  std::string text;
  std::array<char, 4096> buffer{};
  while (pipe_ >= 0) {
    const ssize_t n = ::read(pipe_, buffer.data(), buffer.size());
    if (n > 0) {
      text.append(buffer.data(), static_cast<std::size_t>(n));
    } else if (n == 0) {
      close_pipe();  // the child closed it
    } else if (errno != EINTR) {
      break;  // nothing more now (EAGAIN), or a read error: the same to the caller
    }
  }
  return text;
}

std::string Subprocess::read_to_end() {
  std::string text;
  while (pipe_ >= 0) {
    text += read_available();
    if (pipe_ < 0) break;
    pollfd ready{pipe_, POLLIN, 0};
    if (::poll(&ready, 1, -1) < 0 && errno != EINTR) break;
  }
  return text;
}

void Subprocess::ended(int wait_status, const rusage& usage) {
  status_ = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
  peak_bytes_ = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // Linux counts kB
}

bool Subprocess::poll() {
  if (status_ || pid_ <= 0) return true;
  int wait_status = 0;
  struct rusage usage {};
  if (::wait4(pid_, &wait_status, WNOHANG, &usage) != pid_) return false;
  ended(wait_status, usage);
  return true;
}

int Subprocess::wait() {
  if (!status_ && pid_ > 0) {
    int wait_status = 0;
    struct rusage usage {};
    pid_t got = 0;
    while ((got = ::wait4(pid_, &wait_status, 0, &usage)) < 0 && errno == EINTR) {
    }
    if (got == pid_) {
      ended(wait_status, usage);
    } else {
      status_ = -1;  // not this process's child to wait for: nothing more to learn
    }
  }
  return status_.value_or(-1);
}

int Subprocess::terminate() {
  if (!status_ && pid_ > 0) ::kill(pid_, SIGTERM);
  return wait();
}

std::size_t Subprocess::wait_any(std::vector<Subprocess>& children) {
  for (;;) {
    int wait_status = 0;
    struct rusage usage {};
    const pid_t pid = ::wait4(-1, &wait_status, 0, &usage);
    if (pid < 0 && errno == EINTR) continue;
    for (std::size_t k = 0; k < children.size(); ++k) {
      if (pid > 0 && children[k].pid_ == pid) {
        children[k].ended(wait_status, usage);
        return k;
      }
    }
    // no child at all left to wait for (ECHILD): say so by the first, as ended
    if (pid < 0) {
      if (!children.empty()) children.front().status_ = -1;
      return 0;
    }
  }
}

}  // namespace rigid::support
