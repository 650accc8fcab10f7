// The signals that end a program by default and that a handler can catch: what a
// program must act on before it dies, when it holds temporaries (render/atomic_file.h
// removes them) or children (rigidlab passes the signal on to its labs). Not the
// faults (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS: the program's
// state is not to be trusted then), not SIGKILL or SIGSTOP (no handler sees them), and
// not SIGXFSZ, which the programs ignore: a file past the size limit (ulimit -f) is
// a failed write, EFBIG, said as any other.
#pragma once

#include <signal.h>

#include <vector>

namespace rigid::support {

inline std::vector<int> ending_signals() {
  std::vector<int> signals{SIGHUP,  SIGINT,    SIGQUIT, SIGTERM, SIGALRM, SIGUSR1, SIGUSR2,
                           SIGPIPE, SIGVTALRM, SIGPROF, SIGXCPU, SIGPOLL, SIGPWR};
#ifdef SIGSTKFLT
  signals.push_back(SIGSTKFLT);
#endif
  for (int sig = SIGRTMIN; sig <= SIGRTMAX; ++sig) signals.push_back(sig);
  return signals;
}

}  // namespace rigid::support
