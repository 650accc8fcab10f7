"""rigidlab: the labs of "Rigid Body Motion in 3D" from Python.

Each lab is a function whose keywords are the lab's options in snake_case, read by the
same reader as the command line, and which returns a Result:

    >>> import rigidlab as rl
    >>> r = rl.top_nutation(mass=2, spin_rpm=500)
    >>> r.answer                    # the "in short" line
    >>> r["min_spin_rpm"]           # a value; r.results[key]: value, unit, printed, label
    >>> r.notes, r.errata           # notes, and where the text is wrong
    >>> r.series["t_s"]             # the CSV's columns as NumPy arrays
    >>> r.figures["potential"]      # shown inline in Jupyter; .save("v.pdf", size=(1600, 1200))
    >>> r.motion().at(np.linspace(0, 2, 500))   # attitude, omega, angles as arrays

rl.labs() lists the labs; help(rl.top_nutation) lists its inputs with their units,
defaults and rules. A broken rule raises ValueError with the lab's own message, an
unknown keyword TypeError naming the nearest option. The computation releases the GIL:
a thread pool runs a sweep on every core.
"""

import difflib
import inspect
import json
import keyword
import numbers
import os
import re
import tempfile
from collections import namedtuple

import numpy as np

from . import _rigidlab

__version__ = _rigidlab.__version__
__all__ = ["labs", "Result", "Quantity", "Column", "Figure", "Motion"]

_LABS = {d["name"]: d for d in _rigidlab.labs()}


def labs():
    """The labs' names, in the chapter's order."""
    return list(_LABS)


Column = namedtuple("Column", "name unit meaning")
Column.__doc__ = ("A column of a lab's series: its name (the CSV's header), its unit "
                  "(\"1\" for a pure number) and what it is.")

Quantity = namedtuple("Quantity", "value unit printed label")
Quantity.__doc__ = ("A result: its value (a float, a list, a string or None), its unit "
                    "(\"1\" for a pure number), the text's printed value (None where the "
                    "text prints none) and its label in the table.")


def _parameter(info):
    """The Python keyword of an input: its JSON key, clear of Python's own words."""
    key = info["key"]
    return key + "_" if keyword.iskeyword(key) else key


def _text(lab, name, info, value):
    """The command-line text of a keyword's value, or None for a switch left off."""
    kind = info["kind"]
    if isinstance(value, str):
        return value  # as typed on a command line: the one reader decides
    if kind == "flag":
        if isinstance(value, (bool, np.bool_)):
            return "" if value else None
        raise TypeError(f"{lab}(): {name} is a switch: True or False (got {value!r})")
    if kind == "number":
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
            raise TypeError(f"{lab}(): {name} takes a number (got {value!r})")
        # repr: the shortest text that reads back as the same double
        return str(int(value)) if isinstance(value, numbers.Integral) else repr(float(value))
    if kind in ("pair", "vector"):
        count = 2 if kind == "pair" else 3
        try:
            parts = [float(v) for v in np.asarray(value, dtype=float).ravel()]
        except (TypeError, ValueError):
            raise TypeError(f"{lab}(): {name} takes {count} numbers (got {value!r})") from None
        return ",".join(repr(p) for p in parts)
    if isinstance(value, numbers.Integral) and str(int(value)) in info["choices"]:
        return str(int(value))  # spin_axis=2 for "2"
    raise TypeError(f"{lab}(): {name} takes one of {', '.join(info['choices'])} (got {value!r})")


# How a figure shows inline in Jupyter: PNG, as matplotlib's inline backend does; add
# "svg" for a vector copy beside it (rigidlab.inline_formats = ("png", "svg")). Not SVG by
# default: a notebook exported to HTML (nbconvert 7.2, Debian 12) strips an SVG's drawing
# (lxml's clean_html keeps its text alone), and a frontend that has both shows the SVG.
inline_formats = ("png",)
INLINE_SIZE = (1000, 750)


class Figure:
    """One of a result's figures, drawn by the same renderer as the command line's.

    In Jupyter it shows inline (as PNG; rigidlab.inline_formats); save(path) writes PNG,
    SVG or PDF (from the suffix, or format=), at size=(width, height) pixels (1600 x 1200
    by default)."""

    def __init__(self, run, name, caption, kind):
        self._run, self.name, self.caption, self.kind = run, name, caption, kind

    def __repr__(self):
        return f"<rigidlab figure {self.name!r} ({self.kind}): {self.caption}>"

    def save(self, path, size=(1600, 1200), format=None):
        """Writes the figure to path (PNG, SVG or PDF) and returns the path."""
        path = os.fspath(path)
        if format is None:
            format = os.path.splitext(path)[1].lstrip(".").lower() or "png"
        width, height = (int(v) for v in size)
        self._run.save_figure(self.name, path, format, width, height)
        return path

    def data(self, format="png", size=(1600, 1200)):
        """The figure's bytes in a format (png, svg or pdf)."""
        with tempfile.TemporaryDirectory(prefix="rigidlab-") as folder:
            path = self.save(os.path.join(folder, f"{self.name}.{format}"), size, format)
            with open(path, "rb") as f:
                return f.read()

    def _repr_png_(self):
        return self.data("png", INLINE_SIZE) if "png" in inline_formats else None

    def _repr_svg_(self):
        if "svg" not in inline_formats:
            return None
        # the <svg> element alone: a notebook embeds it in HTML, where an XML declaration
        # is not allowed (nbconvert's HTML export refuses the notebook)
        text = self.data("svg", INLINE_SIZE).decode("utf-8")
        return re.sub(r"^<\?xml[^>]*\?>\s*", "", text)


class Motion:
    """A result's body in motion, in the lab's own time: the closed form, or the
    integrator the lab's method names (its run's samples kept, integrated on from the
    nearest earlier one), so that at a time the lab's CSV samples it gives the CSV's
    row.

    at(t): t in seconds, a number or an array (t >= 0); returns a dict of NumPy arrays
    shaped as t: t_s, the attitude qw, qx, qy, qz (body axes to space axes), omega in
    body axes omega1..3 and in space omega_x, omega_y, omega_z, and the z-x-z Euler
    angles phi_rad, theta_rad, psi_rad. Motion.columns[name]: its unit and meaning."""

    columns = {name: Column(name, unit, meaning)
               for name, unit, meaning in _rigidlab.motion_columns()}

    def __init__(self, lab, motion):
        self.lab, self._motion = lab, motion

    def at(self, t):
        times = np.asarray(t, dtype=float)
        rows = self._motion.at(times.ravel())
        return {name: rows[:, k].reshape(times.shape) for k, name in enumerate(self.columns)}

    def __repr__(self):
        return f"<rigidlab {self.lab} motion: .at(t) gives {', '.join(self.columns)}>"


class Figures(dict):
    """A result's figures by name, in the lab's order."""

    def __missing__(self, name):
        near = difflib.get_close_matches(str(name), list(self), n=1)
        hint = f"; did you mean {near[0]!r}?" if near else f"; the figures: {', '.join(self)}"
        raise KeyError(f"no figure {name!r}{hint}")


class Result:
    """What a lab computed for its inputs: the numbers, the words, the series, the figures.

    r.answer: the "in short" line; r[key]: a value; r.results[key]: a Quantity (value,
    unit, printed, label); r.notes; r.errata (where, printed, correction); r.series: the
    CSV's columns as NumPy arrays (r.series_columns[name]: its unit and meaning;
    r.series_title: what the table is); r.figures; r.motion(): the body at any time; r.json:
    the command line's --json, parsed; r.command: the command line that gives the same;
    r.table: the command line's table. Each part is made when first asked for: a sweep
    that reads r[key] pays for that value alone."""

    def __init__(self, lab, run):
        self.lab = lab
        self._run = run
        self._cache = {}

    def _once(self, name, make):
        if name not in self._cache:
            self._cache[name] = make()
        return self._cache[name]

    @property
    def json(self):
        return self._once("json", lambda: json.loads(self._run.json()))

    @property
    def command(self):
        return self._run.command()

    @property
    def inputs(self):
        return self.json["inputs"]

    @property
    def answer(self):
        return self._run.value("answer")

    @property
    def results(self):
        def make():
            labels = {key: label for key, label, *_ in self._run.rows() if key}
            j = self.json
            units, printed = j["units"], j["textbook"]
            return {key: Quantity(value, units.get(key), printed.get(key), labels.get(key, key))
                    for key, value in j["results"].items()}
        return self._once("results", make)

    @property
    def notes(self):
        return list(self.json["notes"])

    @property
    def errata(self):
        return list(self.json["errata"])

    def _series(self):
        def make():
            series = self._run.series()
            if series is None:
                return {}, None, {}
            title, columns, data = series
            return ({name: data[:, k] for k, (name, _, _) in enumerate(columns)}, title,
                    {name: Column(name, unit, meaning) for name, unit, meaning in columns})
        return self._once("series", make)

    @property
    def series(self):
        return self._series()[0]

    @property
    def series_title(self):
        return self._series()[1]

    @property
    def series_columns(self):
        return self._series()[2]

    @property
    def figures(self):
        return self._once("figures", lambda: Figures(
            (name, Figure(self._run, name, caption, kind))
            for name, caption, kind in self._run.figures()))

    def motion(self):
        """The body in motion (see Motion); ValueError for a lab whose body does not move."""
        motion = self._run.body_motion()
        if not motion:
            raise ValueError(f"{self.lab} has no motion: its body does not move")
        return Motion(self.lab, motion)

    def __getitem__(self, key):
        try:
            return self._run.value(key)
        except KeyError:
            keys = list(self.json["results"])
            near = difflib.get_close_matches(str(key), keys, n=1)
            hint = f"; did you mean {near[0]!r}?" if near else ""
            raise KeyError(f"{self.lab} has no result {key!r}{hint}") from None

    def keys(self):
        return self.json["results"].keys()

    @property
    def table(self):
        return self._run.table()

    def csv(self, path):
        """Writes the CSV the command line's --csv writes, with its metadata beside it
        (PATH-metadata.json, W3C CSV on the Web: each column's unit and meaning), and
        returns the path."""
        path = os.fspath(path)
        self._run.write_csv(path)
        return path

    def __repr__(self):
        return f"<rigidlab {self.lab}: {self.answer}>"

    def _repr_markdown_(self):
        lines = [f"**{self.lab}**: {self.answer}", "", "| quantity | value | unit | text |",
                 "|---|---|---|---|"]
        for key, label, value, unit, printed, remark, heading in self._run.rows():
            if heading:
                lines.append(f"| *{label}* | | | |")
            elif key != "answer":
                cell = [c.replace("|", "\\|") for c in (label, value, unit, printed or remark)]
                lines.append("| " + " | ".join(cell) + " |")
        return "\n".join(lines)


def _docstring(info):
    lines = [info["title"], "", "Parameters (keyword only; None or left out: the default)",
             "----------"]
    for i in info["inputs"]:
        unit = f" [{i['unit']}]" if i["unit"] else ""
        default = (i["default"] if i["has_default"] and i["default"] != "" else
                   (i["lab_default"] or "none"))
        kind = i["kind"] + (f": {'|'.join(i['choices'])}" if i["choices"] else "")
        lines.append(f"{_parameter(i)} : {kind}{unit}, default {default}")
        # the command line's --options named as this function's keywords
        lines.append("    " + re.sub(r"--([a-z0-9-]+)", lambda m: m[1].replace("-", "_"),
                                      i["description"]))
    lines += ["", "Returns", "-------", "Result", "    answer, results, notes, errata, series, "
              "figures; see help(rigidlab.Result)."]
    if info["csv"]:
        lines += ["", f"series: {info['csv']}"]
    return "\n".join(lines)


def _make(name, info):
    by_parameter = {_parameter(i): i for i in info["inputs"]}
    # the options in the lab's own order, as --help lists them and the command line reads them
    order = {i["flag"]: k for k, i in enumerate(info["inputs"])}

    def lab(**given):
        texts = []
        for key, value in given.items():
            i = by_parameter.get(key)
            if i is None:
                near = difflib.get_close_matches(key, list(by_parameter), n=1)
                hint = f"; did you mean {near[0]!r}?" if near else ""
                raise TypeError(f"{name}() got an unexpected keyword argument {key!r}{hint}")
            if value is None:
                continue
            text = _text(name, key, i, value)
            if text is not None:
                texts.append((i["flag"], text))
        texts.sort(key=lambda t: order[t[0]])
        return Result(name, _rigidlab.run(name, texts))

    lab.__name__ = lab.__qualname__ = name
    lab.__doc__ = _docstring(info)
    lab.__signature__ = inspect.Signature([
        inspect.Parameter(_parameter(i), inspect.Parameter.KEYWORD_ONLY, default=None)
        for i in info["inputs"]])
    lab.__module__ = __name__
    return lab


for _name, _info in _LABS.items():
    globals()[_name] = _make(_name, _info)
    __all__.append(_name)
del _name, _info
