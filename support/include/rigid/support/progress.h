// A progress line on stderr for work that takes more than a couple of seconds (an
// animation, a benchmark): on a terminal, one line rewritten in place (what is done
// of how much, the time left), quiet for the first half second and at most ten times
// a second; the final line replaces it. When stderr is not a terminal only the final
// line is written, and with `quiet` nothing at all. The same contract in Python is
// bench/progress.py.
#pragma once

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <string_view>

namespace rigid::support {

class Progress {
 public:
  /// `who` starts every line ("poinsot", "bench work_precision"); `total` units of work,
  /// counted in `unit` ("frames", "runs").
  Progress(std::string who, std::string unit, int total, bool quiet)
      : who_(std::move(who)),
        unit_(std::move(unit)),
        total_(total),
        quiet_(quiet),
        live_(!quiet && ::isatty(STDERR_FILENO) != 0),
        start_(Clock::now()) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() { clear(); }

  /// `done` of the total units are done; `now` says what is under way.
  void update(int done, std::string_view now = {}) {
    if (!live_) return;
    const double elapsed = seconds();
    if (elapsed < 0.5 || elapsed - last_ < 0.1) return;
    last_ = elapsed;
    std::string line = fmt::format("{}: {}/{} {}", who_, done, total_, unit_);
    if (done > 0 && done < total_) {
      line += fmt::format(", {} left", duration(elapsed / done * (total_ - done)));
    }
    if (!now.empty()) line += fmt::format(" ({})", now);
    // one terminal row: a wrapped line could not be rewritten in place
    winsize size{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 1 &&
        line.size() >= size.ws_col) {
      line.resize(size.ws_col - 1);
    }
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
  }
  /// The one final line, "<who>: <summary>", in place of the progress line.
  void finish(std::string_view summary) {
    clear();
    if (quiet_) return;
    std::fprintf(stderr, "%s: %.*s\n", who_.c_str(), static_cast<int>(summary.size()),
                 summary.data());
    std::fflush(stderr);
  }
  /// Seconds since the work began.
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// "42 s", "3 min 5 s": a time left or taken, as a person reads it.
  static std::string duration(double s) {
    if (s < 60.0) return fmt::format("{:.0f} s", s);
    const long whole = static_cast<long>(s + 0.5);
    return fmt::format("{} min {} s", whole / 60, whole % 60);
  }

 private:
  using Clock = std::chrono::steady_clock;
  void clear() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
  }
  std::string who_, unit_;
  int total_;
  bool quiet_, live_, drawn_ = false;
  double last_ = 0.0;
  Clock::time_point start_;
};

}  // namespace rigid::support
