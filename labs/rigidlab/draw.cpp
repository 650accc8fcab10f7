// rigidlab-draw: several labs run in turn in one process, for `rigidlab figures`:
//
//   rigidlab-draw LAB... -- ARG...        each LAB as `LAB ARG...` would run
//
// A lab's figures cost a process start-up that is most of a small lab's time: the
// dynamic libraries linked, a GL context made, its drawing buffers (tens of MB, zeroed
// page by page) and its shaders compiled. Labs drawn in one process pay it once, and
// rigidlab runs one such process a processor instead of one a lab.
//
// One LAB: the exit status is the lab's own, and rigidlab says its line. Several: after
// each lab's own lines on stderr, "rigidlab: LAB: figures drawn" or "rigidlab: LAB:
// FAILED"; the exit status is how many failed. Not a command for a user: it has no
// options of its own and is installed out of PATH.
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "rigid/support/memory.h"
#include "rigidlab/lab_commands.h"

int main(int argc, char** argv) {
  std::vector<std::string> labs;
  int at = 1;
  for (; at < argc && std::strcmp(argv[at], "--") != 0; ++at) labs.emplace_back(argv[at]);
  if (labs.empty() || at == argc) {
    std::cerr << "rigidlab-draw: error: usage: rigidlab-draw LAB... -- ARG... (run by "
                 "rigidlab figures)\n";
    return 2;
  }
  // with this program's own arguments, before any lab asks (a lab's ask is then a no-op)
  rigid::support::restart_with_huge_pages(argv);
  int failed = 0;
  for (const std::string& lab : labs) {
    // the lab's argv: its name, then the arguments after "--" (a lab may keep pointers
    // into it while it runs; it ends before the next lab starts)
    std::vector<std::string> words{lab};
    words.insert(words.end(), argv + at + 1, argv + argc);
    std::vector<char*> lab_argv;
    for (std::string& w : words) lab_argv.push_back(w.data());
    lab_argv.push_back(nullptr);
    const std::optional<int> status =
        rigid::lab::run_lab_command(lab, static_cast<int>(words.size()), lab_argv.data());
    if (!status) std::cerr << "rigidlab-draw: error: " << lab << ": no such lab\n";
    if (labs.size() == 1) return status.value_or(2);
    const bool ok = status == 0;
    std::cerr << "rigidlab: " << lab << (ok ? ": figures drawn" : ": FAILED") << "\n";
    failed += ok ? 0 : 1;
  }
  return failed;
}
