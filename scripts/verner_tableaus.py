#!/usr/bin/env python3
"""Writes core/include/rigid/verner_tableaus.h from Verner's published coefficients.

Source: J. H. Verner's "most efficient" pairs 6(5), 7(6), 8(7) and 9(8) with their
interpolants (Verner, "Numerically optimal Runge-Kutta pairs with interpolants",
Numer. Algorithms 53 (2010) 383-396; the coefficient files of his site,
https://www.sfu.ca/~jverner/, RKV65.IIIXb.Efficient, RKV76.IIa.Efficient,
RKV87.IIa.Efficient, RKV98.IIa.Efficient), as SciML's OrdinaryDiffEq.jl
(MIT licence) transcribes them in lib/OrdinaryDiffEqVerner/src/verner_tableaus.jl:
exact rationals where Verner gives them, 40-digit decimals otherwise, and
sqrt(6) in the nodes of the 9(8) pair. Its generic-type constructors are
evaluated here in 60-digit arithmetic (mpmath) and written out with 25
significant digits, beyond long double's 64-bit mantissa.

This script is the provenance of the header, not a build step: the header is
committed, and tests/core/free_body/verner_test.cpp checks every order condition
of every written coefficient (a transcription error shows there, not here).
Before writing, it checks the same conditions here in 60 digits and refuses
to write a tableau that fails them.

Usage: verner_tableaus.py PATH/TO/verner_tableaus.jl > core/include/rigid/verner_tableaus.h
"""

import re
import sys

import mpmath
from mpmath import mpf

mpmath.mp.dps = 60


def functions(text):
    """{name: body} of the generic-type constructors `function NAME(::Type{T}...`."""
    out = {}
    for m in re.finditer(r"^(?:@fold )?function (\w+)\(::Type\{T\}[^\n]*\n(.*?)^end", text,
                         re.S | re.M):
        out[m.group(1)] = m.group(2)
    return out


def assignments(body):
    """[(name, value)] of the `name = convert(T, expr)` lines, comments skipped."""
    body = "\n".join(line for line in body.splitlines() if not line.lstrip().startswith("#"))
    out = []
    for m in re.finditer(r"(\w+)\s*=\s*convert\(\s*T2?\s*,", body):
        i, depth = m.end(), 1
        while depth:
            depth += {"(": 1, ")": -1}.get(body[i], 0)
            i += 1
        out.append((m.group(1), evaluate(body[m.end():i - 1])))
    return out


def evaluate(expr):
    e = re.sub(r'big"\s*([^"]+)"', r'mpf("\1")', " ".join(expr.split()))
    e = e.replace("6^(1 // 2)", "mpmath.sqrt(6)").replace("BigInt", "")
    e = re.sub(r"(?<![\w.\"])(\d+)(?![\w.\"])", r"mpf(\1)", e)  # integers, not digits of strings
    e = e.replace("//", "/")
    return eval(e, {"mpf": mpf, "mpmath": mpmath})


def indices(digits):
    """'21' -> (2, 1); '021' -> (2, 1); '1001' -> (10, 1): row then column, from 1."""
    split = {2: 1, 3: 2, 4: 2}[len(digits)]
    return int(digits[:split]), int(digits[split:])


class Tableau:
    def __init__(self, name, stages, fsal, order, error_order, interp_order):
        self.name, self.stages, self.fsal = name, stages, fsal
        self.order, self.error_order, self.interp_order = order, error_order, interp_order
        self.a, self.c, self.b, self.e, self.r = {}, {}, {}, {}, {}

    def add(self, name, value, c_offset=0):
        m = re.fullmatch(r"([a-z]+)(\d+)", name)
        kind, digits = m.groups()
        if kind == "a":
            self.a[indices(digits)] = value
        elif kind == "c":
            self.c[int(digits) + c_offset] = value
        elif kind == "b":
            self.b[int(digits)] = value
        elif kind == "btilde":
            self.e[int(digits)] = value
        elif kind == "r":
            self.r[(int(digits[:-1]), int(digits[-1]))] = value
        else:
            raise ValueError(name)

    def total(self):
        return max(i for i, _ in self.a)

    def finish(self):
        n = self.total()
        A = [[self.a.get((i, j), mpf(0)) for j in range(1, n + 1)] for i in range(1, n + 1)]
        if self.fsal and not self.b:  # the last stage's row is the weights
            self.b = {j: v for (i, j), v in self.a.items() if i == self.stages}
        c = [sum(row) for row in A]
        for i, v in self.c.items():  # the given nodes are the row sums
            assert abs(v - c[i - 1]) < mpf(10) ** -35, (self.name, i, v, c[i - 1])
        self.A, self.cv = A, c
        self.bv = [self.b.get(j, mpf(0)) for j in range(1, self.stages + 1)]
        self.ev = [self.e.get(j, mpf(0)) for j in range(1, self.stages + 1)]
        deg = max(k for _, k in self.r) if self.r else 0
        self.rv = [[self.r.get((i, k), mpf(0)) for k in range(1, deg + 1)] for i in range(1, n + 1)]


def trees(order):
    """Rooted trees up to `order` nodes as sorted tuples of children (canonical), by order."""
    by = {1: [()]}
    for n in range(2, order + 1):
        found = set()
        # a tree of n nodes: a root with children whose orders sum to n - 1
        def children(rest, max_child, acc):
            if rest == 0:
                found.add(tuple(sorted(acc)))
                return
            for k in range(min(rest, max_child), 0, -1):
                for t in by[k]:
                    children(rest - k, k, acc + [t])
        children(n - 1, n - 1, [])
        by[n] = sorted(found)
    return by


def size(t):
    return 1 + sum(size(s) for s in t)


def gamma(t):
    g = size(t)
    for s in t:
        g *= gamma(s)
    return g


def phi(t, A, n):
    """The stage vector of t: product over children of A times the child's vector."""
    v = [mpf(1)] * n
    for s in t:
        w = phi(s, A, n)
        Aw = [sum(A[i][j] * w[j] for j in range(n)) for i in range(n)]
        v = [v[i] * Aw[i] for i in range(n)]
    return v


def check(t: Tableau):
    """The order conditions, in 60 digits: (the worst residual of b to order p and of
    e = b - bhat to order p - 1, where it must vanish; the highest order q <= p to which the
    interpolant holds at theta = 1/3 and 1/2, and its worst residual at order q + 1)."""
    by = trees(t.order)
    n, s = t.total(), t.stages
    As = [row[:s] for row in t.A[:s]]
    worst = mpf(0)
    interp = {}
    thetas = [mpf(1) / 3, mpf(1) / 2]
    bths = [[sum(rk * th ** (k + 1) for k, rk in enumerate(row)) for row in t.rv] for th in thetas]
    for order, ts in by.items():
        interp[order] = mpf(0)
        for tr in ts:
            ph = phi(tr, As, s)
            worst = max(worst, abs(sum(bi * p for bi, p in zip(t.bv, ph)) - mpf(1) / gamma(tr)))
            if order <= t.error_order:
                worst = max(worst, abs(sum(ei * p for ei, p in zip(t.ev, ph))))
            full = phi(tr, t.A, n)
            for th, bth in zip(thetas, bths):
                got = sum(bi * p for bi, p in zip(bth, full))
                interp[order] = max(interp[order], abs(got - th ** order / gamma(tr)))
    q = 0
    while q + 1 in interp and interp[q + 1] < mpf(10) ** -30:
        q += 1
    return worst, q, interp.get(q + 1, mpf(0))


def fmt(v):
    s = mpmath.nstr(v, 25, min_fixed=-5, max_fixed=5, strip_zeros=True)
    if "e" not in s and "." not in s:
        s += ".0"
    return s + "L"


def rows(name, matrix, lengths, indent="    "):
    lines = [f"  static constexpr long double {name} = {{"]
    for row, length in zip(matrix, lengths):
        items = [fmt(v) for v in row[:length]]
        text, line = [], indent + "{"
        for k, item in enumerate(items):
            piece = item + (", " if k + 1 < len(items) else "")
            if len(line) + len(piece) > 99:
                text.append(line.rstrip())
                line = indent + " "
            line += piece
        text.append(line + "},")
        lines += text
    lines.append("  };")
    return lines


def vector(name, values):
    lines = rows(name, [values], [len(values)], "      ")
    body = [lines[1].replace("      {", "      ", 1)] + [l[1:] for l in lines[2:-1]]
    body[-1] = body[-1][:-2]  # the row's closing "},"
    return [lines[0]] + body + ["  };"]


def emit(t: Tableau, doc):
    n, s = t.total(), t.stages
    import textwrap
    out = ["/// " + line for line in textwrap.wrap(doc, 96)] + [f"struct {t.name} {{"]
    out.append(f"  static constexpr int kStages = {s};  ///< stages of a step")
    out.append(f"  static constexpr int kTotalStages = {n};  ///< with the interpolant's extra stages")
    out.append(f"  static constexpr int kOrder = {t.order}, kErrorOrder = {t.error_order};")
    out.append(f"  static constexpr int kInterpolantOrder = {t.interp_order};")
    out.append(f"  static constexpr bool kFsal = {'true' if t.fsal else 'false'};"
               "  ///< the last stage is f at the new state")
    out.append("  /// nodes")
    out += vector(f"c[{n}]", t.cv)
    out.append("  /// the stage matrix, row i holding a(i, 0..i-1)")
    out += rows(f"a[{n}][{n}]", t.A, [max(i, 1) for i in range(n)])
    out.append("  /// weights of the order-p solution")
    out += vector(f"b[{s}]", t.bv)
    out.append("  /// error weights, b - bhat (bhat of order p - 1)")
    out += vector(f"e[{s}]", t.ev)
    deg = len(t.rv[0])
    out.append(f"  /// the interpolant: b_i(theta) = sum_k r[i][k] theta^(k+1)")
    out += rows(f"r[{n}][{deg}]", t.rv, [deg] * n)
    out.append("};")
    return out


def main():
    text = open(sys.argv[1]).read()
    fn = functions(text)
    specs = [  # name, stages, fsal, p, p-1, the interpolant's order as published, c offset, doc
        ("Vern6", 9, True, 6, 5, 6, 1,
         "Verner's most efficient 6(5) pair, RKV65.IIIXb.Efficient: 9 stages, the 9th FSAL."),
        ("Vern7", 10, False, 7, 6, 7, 0,
         "Verner's most efficient 7(6) pair, RKV76.IIa.Efficient: 10 stages."),
        ("Vern8", 13, False, 8, 7, 8, 0,
         "Verner's most efficient 8(7) pair, RKV87.IIa.Efficient: 13 stages."),
        ("Vern9", 16, False, 9, 8, 9, 1,
         "Verner's most efficient 9(8) pair, RKV98.IIa.Efficient: 16 stages."),
    ]
    out = [
        "// Generated by scripts/verner_tableaus.py from Verner's published coefficients (see",
        "// that script for the source); do not edit. tests/core/free_body/verner_test.cpp checks",
        "// every order condition of these numbers.",
        "#pragma once",
        "",
        "namespace rigid::verner {",
        "",
    ]
    for name, stages, fsal, p, q, pi, c_off, doc in specs:
        t = Tableau(name, stages, fsal, p, q, pi)
        for part, off in ((f"{name}Tableau", c_off), (f"{name}ExtraStages", 0),
                          (f"{name}InterpolationCoefficients", 0)):
            for k, v in assignments(fn[part]):
                t.add(k, v, off if k.startswith("c") else 0)
        t.finish()
        published = t.interp_order
        worst, t.interp_order, next_residual = check(t)
        extra = t.total() - stages
        doc += (f" Interpolant with {extra} extra stages, of order {t.interp_order} by its order "
                f"conditions")
        if t.interp_order < published:
            doc += (f" (the source gives it as order {published}; its order-{published} conditions miss by "
                    f"up to {mpmath.nstr(next_residual, 2)}, so it is taken as order "
                    f"{t.interp_order})")
        doc += "."
        print(f"{name}: worst order-condition residual {mpmath.nstr(worst, 3)}; interpolant of "
              f"order {t.interp_order} (order {t.interp_order + 1} residual "
              f"{mpmath.nstr(next_residual, 3)})", file=sys.stderr)
        if worst > mpf(10) ** -30:
            sys.exit(f"{name}: order conditions fail ({mpmath.nstr(worst, 3)})")
        out += emit(t, doc) + [""]
    out.append("}  // namespace rigid::verner")
    print("\n".join(out))


if __name__ == "__main__":
    main()
