// Another program run as a child, as rigidlab runs the labs and the explorer records
// through a lab's own --animate: started with its stdout and stderr where the caller
// says (inherited, /dev/null, a pipe this process reads, or a file it holds), then
// polled or waited for, or asked to end. No shell: the path and arguments are passed
// as they are, so a file name may hold any character.
//
//   Subprocess lab(path, {"poinsot", "--help"}, {Redirect::null(), Redirect::pipe()});
//   const std::string help = lab.read_to_end();
//   if (lab.wait() != 0) ...
//
// A child still running when its Subprocess goes is asked to end (SIGTERM) and reaped:
// none is left behind as a zombie or an orphan. One started with `end_with_parent` is
// asked so by the kernel too if this process dies first, even by SIGKILL, which no
// handler sees (Linux's PR_SET_PDEATHSIG).
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rigid::support {

/// Where a child's stdout or stderr goes.
struct Redirect {
  enum class To { kInherit, kNull, kPipe, kFile };
  To to = To::kInherit;
  int fd = -1;  ///< kFile's descriptor (this process's, still its own after)

  static Redirect inherit() { return {}; }
  static Redirect null() { return {To::kNull, -1}; }
  /// A pipe that this process reads (read_available, read_to_end).
  static Redirect pipe() { return {To::kPipe, -1}; }
  static Redirect file(int fd) { return {To::kFile, fd}; }
};

class Subprocess {
 public:
  /// The child's streams, of which one at most is a pipe (two would need reading at once
  /// never to block the child), and the signal mask it starts with (null: this process's).
  struct Options {
    Redirect out, err;
    const sigset_t* signal_mask = nullptr;
    /// SIGTERM to the child when the thread that starts it ends (the whole process
    /// with it, as a rule: start it from the main thread). Started by fork and exec,
    /// since posix_spawn cannot set it between the two.
    bool end_with_parent = false;
  };

  /// Starts `path` with `args` (args[0] the name it is given). Throws std::system_error
  /// with the cause if it cannot be started (no such file, not executable).
  Subprocess(const std::filesystem::path& path, const std::vector<std::string>& args,
             const Options& options);
  ~Subprocess();
  Subprocess(Subprocess&& other) noexcept;
  Subprocess& operator=(Subprocess&& other) noexcept;
  Subprocess(const Subprocess&) = delete;
  Subprocess& operator=(const Subprocess&) = delete;

  pid_t pid() const { return pid_; }

  /// What the child has written into its pipe since the last read, without waiting.
  std::string read_available();
  /// Everything it writes into its pipe, until it closes it (it ends, as a rule).
  std::string read_to_end();

  /// Whether the child has ended (it is then reaped: exit_status() says how), without
  /// waiting.
  bool poll();
  /// Waits for the child to end; its exit status.
  int wait();
  /// Asks the child to end (SIGTERM) and waits for it; its exit status.
  int terminate();
  /// The exit status once it has ended: its exit code, or -1 if a signal ended it.
  std::optional<int> exit_status() const { return status_; }
  /// Once it has ended, the most memory it held at once (its peak resident set, in
  /// bytes, as the kernel counted it); 0 before, or if not known.
  std::uint64_t peak_bytes() const { return peak_bytes_; }

  /// Waits for whichever of `children` (not empty, each still running) ends first; its index.
  static std::size_t wait_any(std::vector<Subprocess>& children);

 private:
  void spawn(const std::filesystem::path& path, char* const argv[], const Options& options,
             const int ends[2]);
  void fork_exec(const std::filesystem::path& path, char* const argv[], const Options& options,
                 const int ends[2]);
  void ended(int wait_status, const rusage& usage);
  void close_pipe();
  pid_t pid_ = -1;
  int pipe_ = -1;  // the read end of the child's piped stream, if any
  std::optional<int> status_;
  std::uint64_t peak_bytes_ = 0;
};

}  // namespace rigid::support
