// rigidlab: the front door to the labs. It lists them, runs one by name, and
// draws every lab's figures into one folder at one size:
//
//   rigidlab list                                  each lab and its sections
//   rigidlab poinsot --omega 1,2,3                 a lab, with its own options
//   rigidlab figures --out DIR [--figure-size WxH] [--figure-prefix P] [--figure-format F]
//   rigidlab --version
//
// The labs are the executables beside this one (bin/ when installed, build/labs/
// in a build tree), their figures drawn by rigidlab-draw (draw.cpp); rigidlab holds no
// physics and no drawing of its own.
#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "rigid/support/cli.h"
#include "rigid/support/memory.h"
#include "rigid/support/programs.h"
#include "rigid/support/signals.h"
#include "rigid/support/subprocess.h"
#include "rigid/support/text.h"
#include "rigidlab/staging.h"

namespace fs = std::filesystem;
using rigid::front_door::Staging;
using rigid::support::Redirect;
using rigid::support::Subprocess;

namespace {

// A stdout closed when rigidlab starts: /dev/null holds descriptor 1, so that no file
// or pipe rigidlab opens takes its place, and std::cout is failed from the start: what
// is written there is a failed write, as on a full disk.
bool g_stdout_closed = false;
void hold_closed_stdout() {
  if (::fcntl(STDOUT_FILENO, F_GETFD) >= 0 || errno != EBADF) return;
  g_stdout_closed = true;
  std::cout.setstate(std::ios::badbit);
  const int fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (fd >= 0 && fd != STDOUT_FILENO) {
    ::dup3(fd, STDOUT_FILENO, O_CLOEXEC);
    ::close(fd);
  }
}

// Why the last write to stdout failed, read right after it.
int stdout_errno() {
  return g_stdout_closed ? EBADF : errno;
}

void say_stdout_failed(int why) {
  std::cerr << "rigidlab: error: stdout: the output could not be written (" << std::strerror(why)
            << ")\n";
}

// The one list of labs (labs/CMakeLists.txt), in section order.
std::vector<std::string> lab_names() {
  std::vector<std::string> names;
  std::stringstream list(RIGID_LAB_NAMES);
  for (std::string name; std::getline(list, name, ',');) names.push_back(name);
  return names;
}

bool is_lab(const std::string& name) {
  for (const std::string& lab : lab_names()) {
    if (lab == name) return true;
  }
  return false;
}

// The labs are beside this executable.
fs::path lab_path(const std::string& lab) {
  return rigid::support::own_directory() / lab;
}

// What draws the labs' figures for `figures`: rigidlab-draw, beside rigidlab in a build
// tree, in libexec/rigidlab/ (RIGID_DRAW_FROM_BIN, from bin/) when installed.
fs::path draw_path() {
  const fs::path beside = rigid::support::own_directory() / "rigidlab-draw";
  std::error_code ec;
  if (fs::exists(beside, ec)) return beside;
  return (rigid::support::own_directory() / RIGID_DRAW_FROM_BIN / "rigidlab-draw")
      .lexically_normal();
}

// A lab's title: the first line of its --help, read from the lab run directly (no
// shell: the install path may hold any character a shell would act on).
std::string title_of(const std::string& lab) {
  std::string text;
  try {
    Subprocess help(lab_path(lab), {lab_path(lab).string(), "--help"},
                    {Redirect::pipe(), Redirect::null()});
    text = help.read_to_end();
    help.wait();
  } catch (const std::system_error&) {
    // not there to run: said below as no title
  }
  const std::string line = text.substr(0, text.find_first_of("\r\n"));
  return line.empty() ? "(not found beside rigidlab)" : line;
}

int list(bool names_only) {
  std::size_t width = 0;
  for (const std::string& lab : lab_names()) width = std::max(width, lab.size());
  for (const std::string& lab : lab_names()) {
    if (names_only) {
      std::cout << lab << "\n";
    } else {
      std::cout << lab << std::string(width - lab.size() + 2, ' ') << title_of(lab) << "\n";
    }
  }
  return 0;
}

// The labs `figures` runs, in fixed storage a signal handler may read: a signal that
// would end rigidlab is passed on to each (kill is async-signal-safe), which then
// removes its temporaries and dies; rigidlab waits for them all and dies as asked.
constexpr int kMaxChildren = 256;
// Every signal whose default is to end the process and that a handler can catch
// (support/signals.h), but SIGPIPE, which rigidlab ignores (a failed write is reported).
std::vector<int> ending_signals() {
  std::vector<int> signals = rigid::support::ending_signals();
  signals.erase(std::remove(signals.begin(), signals.end(), SIGPIPE), signals.end());
  return signals;
}
volatile std::sig_atomic_t g_child[kMaxChildren] = {};
volatile std::sig_atomic_t g_signal = 0;

extern "C" void forward_signal(int sig) {
  g_signal = sig;
  for (int i = 0; i < kMaxChildren; ++i) {
    if (g_child[i] > 0) ::kill(static_cast<pid_t>(g_child[i]), sig);
  }
}

void forward_signals() {
  for (const int sig : ending_signals()) {
    struct sigaction action {};
    action.sa_handler = forward_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(sig, &action, nullptr);
  }
}

void track(pid_t pid, bool running) {
  for (int i = 0; i < kMaxChildren; ++i) {
    if (running ? g_child[i] == 0 : g_child[i] == pid) {
      g_child[i] = running ? pid : 0;
      return;
    }
  }
}

// After every lab has ended: die by the signal that was forwarded, if one was.
void die_if_signalled() {
  if (g_signal == 0) return;
  std::signal(g_signal, SIG_DFL);
  std::raise(g_signal);
}

// Starts rigidlab-draw on `labs` with `args`, its stdout to /dev/null and its stderr as
// `err` says. One that cannot be started has its one line in `why` and no process.
std::optional<Subprocess> start(const std::vector<std::string>& labs,
                                const std::vector<std::string>& args, const Redirect& err,
                                std::string& why) {
  std::vector<std::string> argv{draw_path().string()};
  argv.insert(argv.end(), labs.begin(), labs.end());
  argv.push_back("--");
  argv.insert(argv.end(), args.begin(), args.end());
  // A signal arriving between the spawn and track would miss the child: held until then;
  // the lab starts with the mask rigidlab had.
  sigset_t block, old;
  sigemptyset(&block);
  for (const int sig : ending_signals()) sigaddset(&block, sig);
  ::sigprocmask(SIG_BLOCK, &block, &old);
  std::optional<Subprocess> child;
  try {
    child.emplace(argv.front(), argv, Subprocess::Options{Redirect::null(), err, &old, true});
    track(child->pid(), true);
    if (g_signal != 0) ::kill(child->pid(), g_signal);  // already asked to stop
  } catch (const std::system_error& e) {
    why = "rigidlab: error: " + argv.front() + ": cannot run (" + e.code().message() + ")\n";
  }
  ::sigprocmask(SIG_SETMASK, &old, nullptr);
  return child;
}

// Runs a lab with `args` to its end, its stderr captured; returns its exit status
// (-1 if it did not exit, 127 if it could not be run), its stderr in `err` and the
// most memory it held in `peak_bytes`.
int run_captured(const std::string& lab, const std::vector<std::string>& args, std::string& err,
                 std::uint64_t& peak_bytes) {
  std::optional<Subprocess> child = start({lab}, args, Redirect::pipe(), err);
  if (!child) return 127;
  err += child->read_to_end();
  const int status = child->wait();
  track(child->pid(), false);
  peak_bytes = child->peak_bytes();
  return status;
}

// How many labs draw at once: one a processor, as many as the memory budget holds
// (support/memory.h) at what the first lab took, with a quarter to spare (the labs'
// peaks at one figure size lie within a tenth of each other, and a process drawing
// several in turn peaks within a tenth of its largest: at 4000x3000, 635-652 MB a lab,
// 638-665 MB three in one). Said on stderr when the memory is what limits it.
long labs_at_once(std::uint64_t first_peak) {
  const long cpus = std::max(1L, ::sysconf(_SC_NPROCESSORS_ONLN));
  std::optional<rigid::support::MemoryBudget> budget;
  try {
    budget = rigid::support::memory_budget();
  } catch (const std::invalid_argument&) {
    // the first lab has refused a bad setting already
  }
  if (!budget || first_peak == 0) return cpus;
  const std::uint64_t a_lab = first_peak + first_peak / 4;
  const long fit = static_cast<long>(std::min<std::uint64_t>(budget->bytes / a_lab, cpus));
  if (fit >= cpus) return cpus;
  const long n = std::max(1L, fit);
  std::cerr << "rigidlab: figures: " << n << (n == 1 ? " lab" : " labs")
            << " at a time, as memory allows (a lab took " << rigid::support::bytes_text(first_peak)
            << "; " << budget->source << ": " << rigid::support::bytes_text(budget->bytes) << ")\n";
  return n;
}

// The staged figures renamed into `out`, once every lab has drawn its own; the exit status.
int land(const Staging& stage, const std::string& out, std::size_t labs) {
  // a directory where a figure goes is the --out given: refused whole, as a lab refuses it
  if (const std::string why = stage.blocked(); !why.empty()) {
    stage.discard();
    std::cerr << "rigidlab: error: figures: --out: " << rigid::support::terminal_safe(why) << "\n";
    return 2;
  }
  // Said before any figure lands: a run whose line cannot be written lands nothing, as a
  // lab whose stdout fails lands nothing.
  std::cout << "figures of " << labs << " labs in "
            << rigid::support::terminal_safe(fs::absolute(out).string()) << "\n"
            << std::flush;
  if (!std::cout) {
    const int why = stdout_errno();
    stage.discard();
    say_stdout_failed(why);
    return 1;
  }
  if (const std::string why = stage.land(); !why.empty()) {
    std::cerr << "rigidlab: error: figures: " << rigid::support::terminal_safe(why) << "\n";
    return 1;
  }
  return 0;
}

// The labs after the first in `at_once` groups (labs_at_once), each group drawn by one
// rigidlab-draw, all at once, into the staging folder; how many labs failed. A group's
// stderr goes into a file of its own, shown when it ends with the staging folder's name
// said as `out` (its lines name the paths it wrote to). A group of one has its line said
// here, as the first lab; a larger one says each lab's own, and a lab it did not say was
// drawn (the group killed or crashed) failed.
int other_labs(const Staging& stage, const std::vector<std::string>& labs,
               const std::vector<std::string>& args, long at_once) {
  struct Group {
    std::vector<std::string> labs;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> err{nullptr, std::fclose};
  };
  // round the labs in section order, so that each group has a share of the heavy ones
  std::vector<Group> groups(std::min<std::size_t>(static_cast<std::size_t>(at_once),
                                                  labs.size() > 1 ? labs.size() - 1 : 0));
  for (std::size_t k = 1; k < labs.size(); ++k)
    groups[(k - 1) % groups.size()].labs.push_back(labs[k]);
  std::vector<Subprocess> children;
  std::vector<Group> running;  // beside children, one for one
  int failed = 0;
  const auto said = [&](const Group& group, const std::optional<int>& status,
                        const std::string& err) {
    std::string text = stage.said_of_out(err);
    for (const std::string& lab : group.labs) {
      const std::string line = "rigidlab: " + lab + ": ";
      const bool ok = group.labs.size() == 1
                          ? status == 0
                          : text.find(line + "figures drawn\n") != std::string::npos;
      if (group.labs.size() == 1 || (!ok && text.find(line + "FAILED\n") == std::string::npos))
        text += line + (ok ? "figures drawn" : "FAILED") + "\n";
      failed += ok ? 0 : 1;
    }
    std::cerr << text;
  };
  const auto wait_one = [&] {
    const std::size_t k = Subprocess::wait_any(children);
    track(children[k].pid(), false);
    std::string text;
    if (std::FILE* err = running[k].err.get()) {
      std::rewind(err);
      std::array<char, 4096> buffer{};
      for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), err)) > 0;) {
        text.append(buffer.data(), n);
      }
    }
    said(running[k], children[k].exit_status(), text);
    children.erase(children.begin() + static_cast<std::ptrdiff_t>(k));
    running.erase(running.begin() + static_cast<std::ptrdiff_t>(k));
  };
  for (Group& group : groups) {
    if (g_signal != 0) break;
    group.err.reset(std::tmpfile());  // null: the group's stderr is rigidlab's own
    std::string why;
    std::optional<Subprocess> child = start(
        group.labs, args, group.err ? Redirect::file(::fileno(group.err.get())) : Redirect(), why);
    if (!child) {
      said(group, std::nullopt, why);
      continue;
    }
    children.push_back(std::move(*child));
    running.push_back(std::move(group));
  }
  while (!children.empty()) wait_one();
  return failed;
}

// Every lab's figures into `out`, drawn with `options` (the labs' own figure options), as
// many labs at once as the processors and the memory allow.
int figures(const std::string& out, const std::vector<std::string>& options) {
  forward_signals();
  const Staging stage(out);
  const auto end_if_signalled = [&] {
    if (g_signal == 0) return;
    stage.discard();
    die_if_signalled();
  };
  std::vector<std::string> args{"--quiet", "--figures", stage.dir()};
  args.insert(args.end(), options.begin(), options.end());
  // The first lab alone: it checks the options by the labs' own rules, so bad ones are
  // one line and exit status 2 here, not one failure per lab.
  const std::vector<std::string> labs = lab_names();
  std::string err;
  std::uint64_t first_peak = 0;
  const int first = run_captured(labs.front(), args, err, first_peak);
  end_if_signalled();
  err = stage.said_of_out(err);
  if (first == 2) {
    stage.discard();
    const std::string prefix_of_lab = labs.front() + ": error: ";
    if (err.rfind(prefix_of_lab, 0) == 0) err.erase(0, prefix_of_lab.size());
    // the labs' --figures is rigidlab's --out
    if (err.rfind("--figures:", 0) == 0) err.replace(0, 9, "--out");
    std::cerr << "rigidlab: error: figures: " << err.substr(0, err.find('\n')) << "\n";
    return 2;
  }
  rigid::front_door::say_left_stages(out, stage.dir());
  std::cerr << err;
  std::cerr << "rigidlab: " << labs.front() << (first == 0 ? ": figures drawn" : ": FAILED")
            << "\n";
  const int failed = (first == 0 ? 0 : 1) + other_labs(stage, labs, args, labs_at_once(first_peak));
  end_if_signalled();
  if (failed > 0) {
    stage.discard();
    std::cerr << "rigidlab: error: figures: " << failed
              << " lab(s) failed (their lines above); no figure landed\n";
    return 1;
  }
  return land(stage, out, labs.size());
}

void usage(std::ostream& os) {
  os << "rigidlab - course labs for \"Rigid Body Motion in 3D\"\n"
     << "Usage:\n"
     << "  rigidlab list [--names]        each lab and its sections\n"
     << "  rigidlab LAB [options]         run a lab (rigidlab LAB --help for its options)\n"
     << "  rigidlab figures --out DIR [--figure-size WxH] [--figure-prefix P] [--figure-format F]\n"
     << "                                 every lab's figures into DIR\n"
     << "  rigidlab explore [LAB] [options]  a lab live in a window (rigidlab-explore --help)\n"
     << "  rigidlab --version             the version\n";
}

// `rigidlab figures ...`: its options read, then every lab's figures drawn.
int figures_command(const std::vector<std::string>& args) {
  CLI::App app("every lab's figures into one folder", "rigidlab figures");
  std::string out, size = "1600x1200", prefix, format = "png";
  app.add_option("--out", out, "the folder for the figures (made if missing)")->required();
  app.add_option("--figure-size", size, "figure size in pixels, 800x600 to 8192x8192")
      ->capture_default_str();
  app.add_option("--figure-prefix", prefix, "prefix of the figure files' names");
  app.add_option("--figure-format", format, "png, svg or pdf (vectors for slides and papers)")
      ->capture_default_str();
  if (const std::string twice = rigid::support::repeated_option(app, args); !twice.empty()) {
    std::cerr << "rigidlab: error: figures: " << twice << ": given twice: give it once\n";
    return 2;
  }
  try {
    app.parse(std::vector<std::string>(args.rbegin(), args.rend() - 1));
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "rigidlab: error: figures: " << rigid::support::terminal_safe(e.what()) << "\n";
    return 2;
  }
  // the labs' rule, in their words: rigidlab's --out is their --figures
  if (out.empty()) {
    std::cerr << "rigidlab: error: figures: --out: needs a directory name\n";
    return 2;
  }
  std::vector<std::string> options{"--figure-size", size, "--figure-format", format};
  // given, even empty: the labs judge it
  if (app.count("--figure-prefix") > 0) options.insert(options.end(), {"--figure-prefix", prefix});
  return figures(out, options);
}

// `rigidlab explore ...` and `rigidlab LAB ...`: the program run in rigidlab's place.
int run_program(const std::string& command, const std::vector<std::string>& args) {
  if (command == "explore") {
    const fs::path path = rigid::support::explorer_path();
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      std::cerr << "rigidlab: error: explore: this build has no explorer (it is built where "
                   "libglfw3-dev and libimgui-dev are installed)\n";
      return 2;
    }
    std::vector<std::string> explore_args{"rigidlab-explore"};
    explore_args.insert(explore_args.end(), args.begin() + 1, args.end());
    const std::string why = rigid::support::exec(path, explore_args);
    std::cerr << "rigidlab: error: explore: cannot run "
              << rigid::support::terminal_safe(path.string()) << " (" << why << ")\n";
    return 1;
  }
  const std::string path = lab_path(command).string();
  const std::string why = rigid::support::exec(path, args);
  std::cerr << "rigidlab: error: " << command << ": cannot run "
            << rigid::support::terminal_safe(path) << " (" << why << ")\n";
  return 1;
}

int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    // Asked for: the usage on stdout; no command at all: on stderr, as an error.
    usage(args.empty() ? std::cerr : std::cout);
    return args.empty() ? 2 : 0;
  }
  const std::string& command = args[0];
  if (command == "--version") {
    if (args.size() > 1) {
      std::cerr << "rigidlab: error: --version: takes nothing after it (got '"
                << rigid::support::terminal_safe(args[1]) << "')\n";
      return 2;
    }
    std::cout << "rigidlab " << RIGID_VERSION << "\n";
    return 0;
  }
  if (command == "list") {
    CLI::App app("each lab and its sections", "rigidlab list");
    bool names = false;
    app.add_flag("--names", names, "only the labs' names, one a line");
    try {
      app.parse(std::vector<std::string>(args.rbegin(), args.rend() - 1));
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == 0) return app.exit(e);
      std::cerr << "rigidlab: error: list: " << rigid::support::terminal_safe(e.what()) << "\n";
      return 2;
    }
    return list(names);
  }
  if (command == "figures") return figures_command(args);
  if (command == "explore" || is_lab(command)) return run_program(command, args);
  std::cerr << "rigidlab: error: " << rigid::support::terminal_safe(command)
            << ": no such lab or command (rigidlab list shows the labs)\n";
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  // A closed pipe, or a file past the size limit (EFBIG), is a failed write to report,
  // not a silent death by SIGPIPE or SIGXFSZ.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  hold_closed_stdout();
  const int status = run(argc, argv);
  // What went to stdout (the usage, the version, the list) must have arrived.
  std::cout.flush();
  if (!std::cout && status == 0) {
    say_stdout_failed(stdout_errno());
    return 1;
  }
  return status;
}
