"""A progress line on stderr for the bench's Python stages: the contract of
support/include/rigid/support/progress.h. On a terminal one line rewritten in place (what is done of
how much, the time left, what is under way), quiet for the first half second and at
most ten times a second; finish() replaces it with the final line. When stderr is
not a terminal only the final line is written, and with quiet nothing at all.
Measurement lines go to stdout with --verbose only (detail())."""

import os
import sys
import time


def duration(s):
    """42 s, 3 min 5 s: a time left or taken, as a person reads it."""
    if s < 60:
        return f"{s:.0f} s"
    whole = int(s + 0.5)
    return f"{whole // 60} min {whole % 60} s"


class Progress:
    """unit None: the work is counted in weights (rough seconds), shown as a percentage."""

    def __init__(self, who, unit, total, quiet=False):
        self.who, self.unit, self.total, self.quiet = who, unit, total, quiet
        self.live = not quiet and sys.stderr.isatty()
        self.start, self.last, self.drawn, self.done = time.perf_counter(), 0.0, False, 0

    def seconds(self):
        return time.perf_counter() - self.start

    def update(self, done=None, now=""):
        """done units of the total are done (one more if None); now says what is under way."""
        self.done = self.done + 1 if done is None else done
        if not self.live:
            return
        elapsed = self.seconds()
        if elapsed < 0.5 or elapsed - self.last < 0.1:
            return
        self.last = elapsed
        if self.unit is None:
            line = f"{self.who}: {100.0 * self.done / self.total:.0f}%"
        else:
            line = f"{self.who}: {self.done}/{self.total} {self.unit}"
        if 0 < self.done < self.total:
            line += f", {duration(elapsed / self.done * (self.total - self.done))} left"
        if now:
            line += f" ({now})"
        # one terminal row: a wrapped line could not be rewritten in place
        try:
            columns = os.get_terminal_size(sys.stderr.fileno()).columns
        except OSError:
            columns = 0  # unknown: as it is
        if columns > 1 and len(line) >= columns:
            line = line[:columns - 1]
        sys.stderr.write("\r\033[K" + line)
        sys.stderr.flush()
        self.drawn = True

    def finish(self, summary):
        """The one final line, '<who>: <summary>', in place of the progress line."""
        if self.drawn:
            sys.stderr.write("\r\033[K")
            self.drawn = False
        if not self.quiet:
            sys.stderr.write(f"{self.who}: {summary}\n")
        sys.stderr.flush()


VERBOSE = False


def add_arguments(parser):
    """--verbose and --quiet, as the C++ bench programs take them."""
    parser.add_argument("--verbose", action="store_true", help="a line per measurement on stdout")
    parser.add_argument("--quiet", action="store_true", help="no progress line, no final line")


def configure(args):
    global VERBOSE
    VERBOSE = args.verbose


def detail(text):
    """A measurement's line on stdout, with --verbose only."""
    if VERBOSE:
        print(text, flush=True)
