"""The web page against the command line, in a real headless Chromium.

    python3 check.py SITE LAB_DIR [--random N] [--seed S]

Serves SITE (build/web) on a free local port, then through browse.js:
- every lab's page loads at the text's example and at N random valid inputs given in
  the address (valid: the native lab takes them), with no console error, and its JSON
  equals the native `LAB ARGS --json`: the same keys, texts and notes, every number
  within ULPS (emscripten's libm is musl's, not glibc's: sin, exp and the like may
  round their last bit differently) or, where an integrator's error control took
  another step on that difference, within its tolerance;
- the fields show the address's inputs, and the command shown is the native one's;
- a broken rule typed in a field shows the rule and keeps the last valid state; a
  valid one is taken; a link reproduces its inputs; offline, another lab opens; touch
  and keys reach the controls, which all have labels; the page reflows on a tablet;
- the canvas's scene and plot are the command line's figures (image_match.h's rule for
  another rasteriser).
Exit 0 when all holds, 1 with each failure on stderr.
"""
import argparse
import base64
import functools
import http.server
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import threading

HERE = os.path.dirname(os.path.abspath(__file__))
ULPS = 64  # a closed-form result is at most a few dozen libm calls deep
# An integrated result: the integrator's tolerance bounds how far two runs whose
# roundoff differs can land apart (its error control may take another step); the labs'
# default tolerance is 1e-10 relative (--tol), and a flip or a turning point's time is a
# root found on that trajectory. Relative to the result, or to 1 for a result near 0.
INTEGRATED = 1e-8
# An error at equal cost this small is roundoff's, whatever its unit (see equal_cost_close).
ROUNDOFF = 1e-9

failures = []
LAB_DIR = FIGURE_SAME = ""


def fail(text):
    failures.append(text)
    print(f"FAIL {text}", file=sys.stderr)


def serve(site):
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=site)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}"


def browse(base, *args):
    subprocess.run(["node", os.path.join(HERE, "browse.js"), base, *args], check=True,
                   env=dict(os.environ, NODE_PATH=os.environ.get("RIGID_NODE_MODULES", "")))


def native(lab_dir, lab, args):
    run = subprocess.run([os.path.join(lab_dir, lab), *args, "--json"], capture_output=True,
                         text=True)
    return json.loads(run.stdout) if run.returncode == 0 else None


# ---- random valid inputs -------------------------------------------------------------

def sample_number(rng, default, bound):
    """A number about `default` (half to twice it), held inside the input's bound."""
    kind, lo, hi = bound["kind"], bound.get("lo"), bound.get("hi")
    value = default * math.exp(rng.uniform(-0.7, 0.7)) if default != 0 else rng.uniform(-1, 1)
    if kind in ("positive", "non_negative"):
        value = abs(value) or 1.0
    if kind in ("open_range", "range_from"):
        span = hi - lo
        value = min(max(value, lo + 1e-3 * span), hi - 1e-3 * span)
    return value


def sample_input(rng, spec):
    """Text for one input, or None to leave it at the lab's default."""
    kind, default = spec["kind"], spec["default"]
    if kind == "choice":
        return rng.choice(spec["choices"])
    if kind == "flag" or spec["numerical"] or not spec["has_default"] or not default:
        return None
    try:
        numbers = [float(x) for x in default.split(",")]
    except ValueError:
        return None  # a vector given as a word
    return ",".join(repr(sample_number(rng, x, spec["bound"])) for x in numbers)


def random_cases(rng, lab, lab_dir, count):
    cases, tries = [], 0
    while len(cases) < count and tries < 40 * count:
        tries += 1
        args = []
        for spec in lab["inputs"]:
            if rng.random() < 0.5:
                continue
            text = sample_input(rng, spec)
            if text is not None:
                args.append(f"{spec['flag']}={text}")
        if args and native(lab_dir, lab["name"], args) is not None:
            cases.append(args)
    return cases


def query(lab, args):
    parts = [f"lab={lab}"]
    for a in args:
        flag, _, value = a.partition("=")
        parts.append(f"{flag[2:]}={value}")
    return "&".join(parts)


# ---- comparing -------------------------------------------------------------------------

def swapped_ties(a, b):
    """Whether the methods' ranks at equal cost differ only between methods whose errors
    tie within how far the two runs' errors are apart (an error at roundoff's level is
    itself roundoff: which of two such methods comes first is not physics)."""
    ranks = [k for k in a if k.startswith("equal_cost_rank_")]
    moved = [k for k in ranks if a[k] != b.get(k)]
    if not moved:
        return True

    def error_key(method):
        pattern = re.compile(r"^equal_cost_max_(?:\w+_)?error_" + re.escape(method) + r"(?:_deg)?$")
        keys = [k for k in a if pattern.match(k)]
        return keys[0] if keys else None

    by_rank = {a[k]: k[len("equal_cost_rank_"):] for k in ranks}
    for k in moved:
        x = k[len("equal_cost_rank_"):]
        y = by_rank.get(b[k])
        ex, ey = error_key(x), error_key(y) if y else None
        if ex is None or ey is None:
            return False
        apart = max(abs(a[ex] - b[ex]), abs(a[ey] - b[ey]))
        if abs(a[ex] - a[ey]) > apart and max(a[ex], a[ey]) > ROUNDOFF:
            return False
    return True


def equal_cost_close(path, a, b):
    """The integrators' work and their comparison at equal cost: an adaptive method's
    error control (and the search for the tolerance that spends a given number of
    evaluations) can decide a step the other way on another libm's roundoff, so steps
    agree within one (or 5 % of a long run; Bulirsch-Stoer's, whose order moves too,
    within 50 %) and evaluations within a step's share of a 10-step run (10 %); errors driven down to roundoff's level (ROUNDOFF) are roundoff:
    only that both are is compared."""
    key = path.split(".")[-1]
    # "work": the answer's evaluations, weighted (rigid::work_done)
    work = "evaluations" in key or "steps" in key or key == "work"
    if not (work or key.startswith("equal_cost_") or key.startswith("recommended_method")):
        return False
    if isinstance(a, str):
        numbers = [float(x) for x in re.findall(r"\d+(?:\.\d+)?e-\d+", a + " " + b)]
        return bool(numbers) and all(x <= ROUNDOFF for x in numbers)
    if work:  # an adaptive integrator's work, wherever it is counted
        if "steps" in key and "bulirsch_stoer" in key:
            # extrapolation picks its order too: an order more costs (k+1)^2/k^2 the
            # evaluations a step, so at equal evaluations its steps move by that much
            return abs(a - b) <= 0.5 * max(abs(a), abs(b))
        if "steps" in key:  # a step more or fewer, or 5 % of a long run
            return abs(a - b) <= max(1.0, 0.05 * max(abs(a), abs(b)))
        # a step's evaluations: Bulirsch-Stoer's are a tenth of a 10-step run's
        return abs(a - b) <= 0.10 * max(abs(a), abs(b))
    return max(abs(a), abs(b)) <= ROUNDOFF or abs(a - b) <= 0.5 * max(abs(a), abs(b))


def compare(a, b, path, worst):
    if isinstance(a, dict):
        if (isinstance(b, dict) and sorted(a) == sorted(b) and list(a) != list(b)
                and swapped_ties(a, b)):
            b = {k: (a[k] if k.startswith("equal_cost_rank_") else b[k]) for k in a}
        if not isinstance(b, dict) or list(a) != list(b):
            return f"{path}: keys differ ({list(a)[:6]} against {list(b)[:6] if isinstance(b, dict) else b})"
        for k in a:
            why = compare(a[k], b[k], f"{path}.{k}", worst)
            if why:
                return why
    elif isinstance(a, list):
        if not isinstance(b, list) or len(a) != len(b):
            return f"{path}: lengths differ"
        for i, (x, y) in enumerate(zip(a, b)):
            why = compare(x, y, f"{path}[{i}]", worst)
            if why:
                return why
    elif isinstance(a, float) or isinstance(b, float):
        scale = max(abs(a), abs(b), sys.float_info.min)
        ulps = abs(a - b) / (scale * sys.float_info.epsilon)
        if ulps <= ULPS:
            worst[0] = max(worst[0], ulps)
        else:
            worst[1] = max(worst[1], abs(a - b) / max(1.0, scale))
        if (ulps > ULPS and abs(a - b) > INTEGRATED * max(1.0, scale)
                and not equal_cost_close(path, a, b)):
            return f"{path}: native {a!r} web {b!r} ({ulps:.0f} ulps)"
    elif isinstance(a, int) and isinstance(b, int) and a != b:
        return None if equal_cost_close(path, a, b) else f"{path}: native {a!r} web {b!r}"
    elif a != b:
        # a printed number may round its last digit the other way
        if numeric_text(a, b) or equal_cost_close(path, a, b):
            return None
        return f"{path}: native {a!r} web {b!r}"
    return None


def at_default(arg, defaults):
    flag, _, text = arg.partition("=")
    default = defaults.get(flag, "")
    if text == default:
        return True
    try:
        return [float(x) for x in text.split(",")] == [float(x) for x in default.split(",")]
    except ValueError:
        return False


def numeric_text(a, b):
    """Two texts the same but for numbers within the tolerance."""
    number = r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?"
    if not (isinstance(a, str) and isinstance(b, str)):
        return False
    if re.sub(number, "#", a) != re.sub(number, "#", b):
        return False
    for x, y in zip(re.findall(number, a), re.findall(number, b)):
        x, y = float(x), float(y)
        digits = 10 ** -(len(str(x).split(".")[-1]) if "." in str(x) else 0)
        if abs(x - y) > max(INTEGRATED * max(1.0, abs(x)), 1.01 * digits * max(1.0, abs(x))):
            return False
    return True


KEYS = ("inputs", "results", "units", "textbook", "textbook_values", "notes", "errata")


def check_numbers(base, labs, lab_dir, count, rng, work):
    cases, expected = [], {}
    for lab in labs:
        for k, args in enumerate([[]] + random_cases(rng, lab, lab_dir, count)):
            case_id = f"{lab['name']}#{k}"
            cases.append({"id": case_id, "query": query(lab["name"], args)})
            expected[case_id] = (lab, args, native(lab_dir, lab["name"], args))
    with open(os.path.join(work, "cases.json"), "w") as f:
        json.dump(cases, f)
    out = os.path.join(work, "numbers.json")
    browse(base, "numbers", os.path.join(work, "cases.json"), out)
    worst_by_lab = {}
    for answer in json.load(open(out)):
        lab, args, want = expected[answer["id"]]
        where = f"{answer['id']} ({' '.join(args) or 'the text'})"
        if answer["problems"]:
            fail(f"{where}: the console says {answer['problems']}")
        got = json.loads(answer["json"])
        mine, theirs = want.get("results", {}), got.get("results", {})
        if (mine.get("recommended_method") != theirs.get("recommended_method") and
                equal_cost_close("recommended_method_reason",
                                 mine.get("recommended_method_reason", ""),
                                 theirs.get("recommended_method_reason", ""))):
            theirs["recommended_method"] = mine["recommended_method"]  # a tie at roundoff
        worst = [0.0, 0.0]
        for key in KEYS:
            if key in want or key in got:
                why = compare(want.get(key), got.get(key), key, worst)
                if why:
                    fail(f"{where}: {why}")
        old = worst_by_lab.get(lab["name"], [0.0, 0.0])
        worst_by_lab[lab["name"]] = [max(old[0], worst[0]), max(old[1], worst[1])]
        # the page names the inputs that are not the text's: every one given but those
        # given at the text's value
        given, named = want["command"][1:-1], got["command"][1:]
        defaults = {i["flag"]: i["default"] for i in lab["inputs"]}
        left = [g for g in given if g not in named and not at_default(g, defaults)]
        if left or any(n not in given for n in named):
            fail(f"{where}: the page names {named}, the command line took {given}")
        if answer["command"].split()[0] != lab["name"]:
            fail(f"{where}: the command shown is {answer['command']!r}")
    for name, (ulps, beyond) in worst_by_lab.items():
        print(f"web: {name}: {count + 1} inputs, the JSON equal to the native run's: "
              f"{ulps:.0f} ulps at most, or {beyond:.1e} of max(1, |x|) beyond that")


def check_behaviour(base, work):
    out = os.path.join(work, "behaviour.json")
    browse(base, "behaviour", out)
    r = json.load(open(out))
    refusal = r["refusal"]
    if "--mass" not in refusal["error"] or "positive" not in refusal["error"]:
        fail(f"a broken rule in a field: it shows {refusal['error']!r}, not the rule")
    if refusal["invalid"] != "true":
        fail("a broken rule in a field: the field is not marked invalid")
    if refusal["command"] != refusal["before"]:
        fail(f"a broken rule in a field: the state moved to {refusal['command']!r}")
    accepted = r["accepted"]
    if accepted["error"] or accepted["invalid"] == "true" or "--mass=3" not in accepted["command"]:
        fail(f"a valid input after a refused one: {accepted}")
    if "mass=3" not in accepted["address"]:
        fail(f"the address does not hold the input: {accepted['address']}")
    if "no lab named 'nosuch'" not in r["unknownLab"]:
        fail(f"a link to no lab says {r['unknownLab']!r}")
    unknown = r["unknownInput"]
    if "--spin-rpm" not in unknown["status"] or unknown["command"] != "poinsot":
        fail(f"a link with an input poinsot has not: {unknown}")
    link = r["link"]
    if link["alpha"] != "12.5" or "--alpha-deg=12.5" not in link["command"]:
        fail(f"a link's inputs are not shown: {link}")
    if "alpha-deg=12.5" not in link["address"]:
        fail(f"a link's address changed to {link['address']}")
    if r["offline"] != "tennis_racquet":
        fail(f"offline, another lab did not open: {r['offline']}")
    if r["problems"] or r["touchProblems"]:
        fail(f"the console says {r['problems'] + r['touchProblems']}")
    if r["keyboard"]["unlabelled"]:
        fail(f"controls with no label: {r['keyboard']['unlabelled']}")
    if not r["keys"]["playing"]:
        fail("the space key on the view did not start the motion")
    if r["touch"]["focused"] != "in-mass":
        fail(f"a tap on a field focused {r['touch']['focused']!r}")
    if not r["touch"]["turned"]:
        fail("a swipe on the view did not turn the scene")
    if not r["touch"]["layout"]["stacked"] or r["touch"]["layout"]["overflow"]:
        fail(f"on a tablet held upright the page does not reflow: {r['touch']['layout']}")
    print("web: a refused field, a link, offline, the keyboard and touch behave")
    check_figures(r["figures"], work)


def check_figures(shots, work):
    """The canvas's scene and plot against the command line's figures, by image_match's
    rule for another rasteriser (WebGL on SwiftShader, text through stb_truetype)."""
    native_dir = os.path.join(work, "native-figures")
    subprocess.run([os.path.join(LAB_DIR, "top_nutation"), "--figures", native_dir,
                    "--figure-size", "800x600", "--quiet"], check=True)
    for name, shot in shots.items():
        if not shot.startswith("data:image/png;base64,"):
            fail(f"the figure {name} was not drawn: {shot}")
            continue
        mine = os.path.join(work, f"web-{name}.png")
        with open(mine, "wb") as f:
            f.write(base64.b64decode(shot.split(",", 1)[1]))
        theirs = os.path.join(native_dir, f"top_nutation_{name}.png")
        same = subprocess.run([FIGURE_SAME, "--across-rasterisers", mine, theirs],
                              capture_output=True, text=True)
        if same.returncode != 0:
            keep = os.environ.get("RIGID_WEB_KEEP")
            if keep:
                shutil.copy(mine, keep)
            fail(f"the canvas's {name} is not the command line's: {same.stdout.strip()}")
    print(f"web: the canvas draws {', '.join(shots)} as the command line does")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("site")
    parser.add_argument("lab_dir")
    parser.add_argument("--random", type=int, default=20)
    parser.add_argument("--seed", type=int, default=20261202)
    a = parser.parse_args()
    global LAB_DIR, FIGURE_SAME
    LAB_DIR = a.lab_dir
    FIGURE_SAME = os.path.join(os.path.dirname(os.path.abspath(a.lab_dir)), "render", "figure-same")
    server, base = serve(a.site)
    with tempfile.TemporaryDirectory() as work:
        labs_file = os.path.join(work, "labs.json")
        browse(base, "describe", labs_file)
        labs = json.load(open(labs_file))
        check_numbers(base, labs, a.lab_dir, a.random, random.Random(a.seed), work)
        check_behaviour(base, work)
    server.shutdown()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
