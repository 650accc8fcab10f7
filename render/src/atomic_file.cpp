// Atomic file writing: temporary in the same directory, checked, renamed.
#include "rigid/render/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rigid/support/signals.h"

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

// The temporaries this process holds, in fixed storage a signal handler may read:
// every signal that ends a process and can be caught unlinks them (unlink is
// async-signal-safe), and the process then dies by that signal as it would have.
constexpr int kMaxHeld = 64;
char g_held[kMaxHeld][PATH_MAX];
volatile std::sig_atomic_t g_used[kMaxHeld] = {};

// Another thread (a PNG encoded while the next figure draws) may be making a temporary
// while the handler runs: the handler says the process is dying, then waits for every
// creation under way to be held, so that none lands after its unlinks; a creation that
// sees the process dying makes nothing. No thread can be interrupted by the handler
// while it holds what a creation waits for: those signals are blocked while a
// thread creates a temporary or holds g_mutex (the signal then goes to another thread,
// or waits until it is let go). The wait is bounded (an open() on a stalled network
// file system), after which the handler unlinks what is held. Lock-free atomics and
// clock_gettime: what a handler may touch.
std::atomic<int> g_creating{0};
std::atomic<bool> g_dying{false};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free);

double handler_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

extern "C" void remove_held_and_die(int sig) {
  g_dying.store(true);
  const double give_up = handler_seconds() + 2.0;
  while (g_creating.load() > 0 && handler_seconds() < give_up) {
  }
  for (int i = 0; i < kMaxHeld; ++i) {
    if (g_used[i]) ::unlink(g_held[i]);
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// The signals whose default is to end the process and that can be caught, but the
// faults' and SIGXFSZ (support/signals.h).
sigset_t terminating_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (const int sig : support::ending_signals()) sigaddset(&set, sig);
  return set;
}

// The terminating signals blocked in this thread for a scope.
class SignalsBlocked {
 public:
  SignalsBlocked() {
    static const sigset_t block = terminating_signals();
    ::pthread_sigmask(SIG_BLOCK, &block, &old_);
  }
  ~SignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  SignalsBlocked(const SignalsBlocked&) = delete;
  SignalsBlocked& operator=(const SignalsBlocked&) = delete;

 private:
  sigset_t old_;
};

// Brackets the making of a temporary (held, then created): see remove_held_and_die.
class Creating {
 public:
  Creating() {
    g_creating.fetch_add(1);
    if (g_dying.load()) {
      // the handler is removing the temporaries and ends the process: make nothing
      g_creating.fetch_sub(1);
      for (;;) ::pause();
    }
  }
  ~Creating() { g_creating.fetch_sub(1); }
  Creating(const Creating&) = delete;
  Creating& operator=(const Creating&) = delete;

 private:
  SignalsBlocked blocked_;  // made before the count goes up, let go after it comes down
};

// A signal the process was told to ignore (nohup, a shell's background job) stays
// ignored, and one a program handles itself keeps its handler: only a default death
// becomes a clean one.
void install_handlers_once() {
  static const bool installed = [] {
    struct sigaction action {};
    action.sa_handler = remove_held_and_die;
    action.sa_mask = terminating_signals();  // the others wait while this handler runs
    for (int sig = 1; sig < NSIG; ++sig) {
      struct sigaction old {};
      if (sigismember(&action.sa_mask, sig) != 1 || ::sigaction(sig, nullptr, &old) != 0) continue;
      if (old.sa_handler == SIG_DFL) ::sigaction(sig, &action, nullptr);
    }
    struct sigaction old {};
    if (::sigaction(SIGXFSZ, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) {
      std::signal(SIGXFSZ, SIG_IGN);
    }
    return true;
  }();
  (void)installed;
}

// Files may be written from more than one thread (an animation encodes on its own).
std::mutex g_mutex;

int hold(const std::string& tmp) {
  install_handlers_once();
  const SignalsBlocked blocked;
  const std::lock_guard<std::mutex> lock(g_mutex);
  for (int i = 0; i < kMaxHeld; ++i) {
    if (!g_used[i] && tmp.size() < PATH_MAX) {
      std::memcpy(g_held[i], tmp.c_str(), tmp.size() + 1);
      g_used[i] = 1;
      return i;
    }
  }
  return -1;  // more than kMaxHeld at once: still removed on failure, not on a signal
}

void release(int slot) {
  const SignalsBlocked blocked;
  const std::lock_guard<std::mutex> lock(g_mutex);
  if (slot >= 0) g_used[slot] = 0;
}

// The file a target names, whatever its spelling: its folder (device and inode) and
// its name in it. Two of a transaction's outputs with one file would replace each other.
struct FileKey {
  dev_t dev = 0;
  ino_t ino = 0;
  std::string leaf;
  bool operator==(const FileKey& o) const { return dev == o.dev && ino == o.ino && leaf == o.leaf; }
};
FileKey file_key(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "."
                          : slash == 0               ? "/"
                                                     : path.substr(0, slash);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) return {};
  return {st.st_dev, st.st_ino, slash == std::string::npos ? path : path.substr(slash + 1)};
}

// The pending renames of the live transaction (temporary, target, slot, target's file).
struct Pending {
  std::string tmp, path;
  int slot;
  FileKey key;
};
std::vector<Pending>* g_transaction = nullptr;

// True if the live transaction already writes the file `key` names.
bool pending_in_transaction(const FileKey& key) {
  const SignalsBlocked blocked;
  const std::lock_guard<std::mutex> lock(g_mutex);
  if (g_transaction == nullptr || key.leaf.empty()) return false;
  for (const Pending& p : *g_transaction)
    if (p.key == key) return true;
  return false;
}

// Temporaries are named TARGET.rigidlab-tmp-PID-RANDOM: the marker, the writer's
// process id and 16 hex digits of randomness, so that no user's file has that name by
// accident (a "c.csv.tmp-99999" of theirs is not ours). A target whose name leaves no
// room for the suffix (NAME_MAX) gets a hidden ".rigidlab-tmp-PID-RANDOM" beside it.
constexpr char kMarker[] = ".rigidlab-tmp-";
constexpr std::size_t kRandomDigits = 16;

std::string temporary_name(const std::string& path) {
  static std::random_device device;
  static std::mutex mutex;
  std::uint64_t random = 0;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    random = (std::uint64_t{device()} << 32) ^ device();
  }
  char hex[kRandomDigits + 1];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(random));
  const std::string suffix = kMarker + std::to_string(::getpid()) + "-" + hex;
  const std::size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  if (base.size() + suffix.size() <= NAME_MAX) return path + suffix;
  return dir + suffix;
}

// The process id in `name` if it is exactly `prefix` + PID + "-" + 16 hex digits.
long pid_of_temporary(const std::string& name, const std::string& prefix) {
  if (name.size() <= prefix.size() + 1 + kRandomDigits || name.rfind(prefix, 0) != 0) return -1;
  const std::size_t dash = name.size() - kRandomDigits - 1;
  if (name[dash] != '-') return -1;
  for (std::size_t i = dash + 1; i < name.size(); ++i) {
    if (!std::isxdigit(static_cast<unsigned char>(name[i])) || std::isupper(name[i])) return -1;
  }
  const std::string digits = name.substr(prefix.size(), dash - prefix.size());
  if (digits.empty() || digits.size() > 10 ||
      digits.find_first_not_of("0123456789") != std::string::npos || digits[0] == '0') {
    return -1;
  }
  // a number no process id can be (past pid_t) names no process of ours: not ours to
  // remove (kill() would ask about a process group instead)
  const long pid = std::stol(digits);
  return pid <= std::numeric_limits<pid_t>::max() ? pid : -1;
}

// Removes the temporaries beside `path` that a killed run (SIGKILL, a power cut) left
// behind, and only those: exactly our pattern (for this target, or the hidden short
// form), a regular file of this user, and its process gone.
void remove_stale(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "./" : path.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return;
  const std::string ours = base + kMarker;
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    long pid = pid_of_temporary(name, ours);
    if (pid < 0) pid = pid_of_temporary(name, kMarker);
    if (pid <= 0 || pid == ::getpid()) continue;
    const std::string full = dir + name;
    struct stat st {};
    if (::lstat(full.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::getuid()) {
      continue;
    }
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) ::unlink(full.c_str());
  }
  ::closedir(d);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write) {
  if (path.empty()) fail(path, "empty file name");
  const FileKey key = file_key(path);
  if (pending_in_transaction(key)) fail(path, "another output of this run is the same file");
  remove_stale(path);
  const std::string tmp = temporary_name(path);
  // O_EXCL: never write through a file (or link) that is already there; 0666
  // less the umask gives an ordinary file's permissions.
  int slot = -1, fd = -1;
  {
    const Creating creating;
    slot = hold(tmp);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  }
  if (fd < 0) {
    const int e = errno;
    release(slot);
    fail(path, std::strerror(e));
  }
  std::FILE* f = ::fdopen(fd, "wb");
  if (f == nullptr) {
    const int e = errno;
    ::close(fd);
    std::remove(tmp.c_str());
    release(slot);
    fail(path, std::strerror(e));
  }
  std::string error;
  int stream_errno = 0;
  try {
    errno = 0;
    write(f);
    stream_errno = errno;
  } catch (const std::exception& e) {
    stream_errno = errno;
    error = e.what();
  } catch (...) {
    stream_errno = errno;
    error = "unknown error while writing";
  }
  // A short write (full disk, say) shows as the stream's error flag, or when
  // the buffer is flushed and the file closed. The stream's errno is the cause:
  // an encoder that gave up on it ("libpng failed while encoding") only echoes it.
  if (std::ferror(f)) {
    error = stream_errno != 0 ? std::strerror(stream_errno) : error.empty() ? "write error" : error;
  }
  if (std::fflush(f) != 0 && error.empty()) error = std::strerror(errno);
  if (std::fclose(f) != 0 && error.empty()) error = std::strerror(errno);
  if (error.empty()) {
    const SignalsBlocked blocked;
    const std::lock_guard<std::mutex> lock(g_mutex);
    if (g_transaction != nullptr) {
      g_transaction->push_back({tmp, path, slot, key});  // renamed at commit()
      return;
    }
  }
  if (error.empty() && std::rename(tmp.c_str(), path.c_str()) != 0) error = std::strerror(errno);
  if (!error.empty()) std::remove(tmp.c_str());
  release(slot);
  if (!error.empty()) fail(path, error);
}

FileTransaction::FileTransaction() {
  if (g_transaction != nullptr) throw std::logic_error("FileTransaction: one at a time");
  g_transaction = new std::vector<Pending>();
}

FileTransaction::~FileTransaction() {
  if (g_transaction == nullptr) return;
  for (const Pending& p : *g_transaction) {
    std::remove(p.tmp.c_str());
    release(p.slot);
  }
  delete g_transaction;
  g_transaction = nullptr;
}

void FileTransaction::commit() {
  std::vector<Pending> pending = std::move(*g_transaction);
  delete g_transaction;
  g_transaction = nullptr;
  std::string error, failed;
  std::size_t landed = 0;
  for (const Pending& p : pending) {
    if (error.empty()) {
      if (std::rename(p.tmp.c_str(), p.path.c_str()) == 0) {
        ++landed;
      } else {
        error = std::strerror(errno);
        failed = p.path;
      }
    }
    if (!error.empty()) std::remove(p.tmp.c_str());
    release(p.slot);
  }
  if (!error.empty()) {
    throw CommitError("cannot write '" + one_line(failed) + "': " + one_line(error) + "; " +
                          std::to_string(landed) + " of " + std::to_string(pending.size()) +
                          " files had landed before it, the rest were removed",
                      failed, landed, pending.size());
  }
}

}  // namespace rigid::render
