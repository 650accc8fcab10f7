"""import rigidlab against the command line: the same lab libraries give the same JSON
bit for bit at the defaults and at random keyword sets, the same message for every
broken rule, the same CSV numbers and the same figure files. ctest runs it with
PYTHONPATH at the build's python/ folder and RIGID_LAB_DIR at its labs/."""

import json
import os
import random
import subprocess
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import rigidlab as rl

LAB_DIR = os.environ.get("RIGID_LAB_DIR", "")
LABS = rl.labs()
INFO = {d["name"]: d for d in rl._rigidlab.labs()}
# What a run says of its own call: the rest of the JSON is the lab's, compared whole.
OWN = ("command",)


def cli(lab, args, cwd=None):
    """(exit status, parsed JSON or None, stderr) of the lab's program with --json."""
    proc = subprocess.run([os.path.join(LAB_DIR, lab), "--json", *args], capture_output=True,
                          text=True, cwd=cwd)
    return proc.returncode, (json.loads(proc.stdout) if proc.returncode == 0 else None), \
        proc.stderr


def lab_part(report):
    return {k: v for k, v in report.items() if k not in OWN}


def keyword(flag):
    return flag.lstrip("-").replace("-", "_")


def test_labs_are_the_command_lines():
    assert LABS == ["lamina_tensor", "tire_balancing", "poinsot", "tennis_racquet", "football",
                    "euler_angles", "top_nutation"]
    for lab in LABS:
        assert os.access(os.path.join(LAB_DIR, lab), os.X_OK), lab


@pytest.mark.parametrize("lab", LABS)
def test_defaults_equal_the_command_line_json_bit_for_bit(lab):
    status, expected, _ = cli(lab, [])
    assert status == 0
    r = getattr(rl, lab)()
    # Parsed JSON compares floats exactly: the same 17 digits, the same double.
    assert lab_part(r.json) == lab_part(expected)
    assert r.command == [lab]
    assert r.answer == expected["results"]["answer"]
    for key, q in r.results.items():
        assert q.value == expected["results"][key]
        assert q.unit == expected["units"].get(key)
        assert q.printed == expected["textbook"].get(key)
        assert q.label, key


def random_text(rng, info):
    """A keyword's value near its default (mostly valid), as Python gives it."""
    kind, default = info["kind"], info["default"]
    if kind == "flag":
        return rng.random() < 0.5
    if kind == "choice":
        return rng.choice(info["choices"])
    if info["words"] and rng.random() < 0.3:
        return rng.choice(info["words"])
    count = {"number": 1, "pair": 2, "vector": 3}[kind]
    try:
        base = [float(x) for x in default.split(",")] if default else []
    except ValueError:
        base = []
    if len(base) != count:
        base = [1.0] * count
    values = [(b if b != 0 else 0.3) * rng.uniform(0.5, 1.6) for b in base]
    if rng.random() < 0.1:
        values[0] = -values[0]  # now and then a broken rule, said the same way
    return values[0] if count == 1 else values


@pytest.mark.parametrize("lab", LABS)
def test_random_keyword_sets_agree_with_the_command_line(lab):
    rng = random.Random(20261202 + LABS.index(lab))
    inputs = [i for i in INFO[lab]["inputs"] if not i["numerical"] or i["kind"] == "choice"]
    agreed = computed = 0
    for case in range(100):
        chosen = rng.sample(inputs, rng.randint(1, min(3, len(inputs))))
        given = {keyword(i["flag"]): random_text(rng, i) for i in chosen}
        args = []
        for i in chosen:
            value = given[keyword(i["flag"])]
            if i["kind"] == "flag":
                args += [i["flag"]] if value else []
            elif isinstance(value, list):
                args.append(i["flag"] + "=" + ",".join(repr(v) for v in value))
            elif isinstance(value, float):
                args.append(i["flag"] + "=" + repr(value))
            else:
                args.append(i["flag"] + "=" + str(value))
        status, expected, stderr = cli(lab, args)
        try:
            r = getattr(rl, lab)(**given)
        except ValueError as e:
            assert status == 2, (given, stderr)
            assert stderr.strip() == f"{lab}: error: {e}", given
        else:
            assert status == 0, (given, stderr)
            assert lab_part(r.json) == lab_part(expected), given
            computed += 1
        agreed += 1
    assert agreed == 100
    # Mostly valid: the comparison is of results, not of refusals alone.
    assert computed >= 50


def bad_value(info):
    """A value that breaks the input's own rule, and why it must."""
    if info["kind"] == "choice":
        return "no-such-word"
    if info["kind"] == "flag":
        return "maybe"
    if info["kind"] in ("pair", "vector"):
        return "1"  # too few numbers
    return "nan"  # every number is finite


@pytest.mark.parametrize("lab", LABS)
def test_every_input_rule_raises_with_the_command_lines_message(lab):
    for info in INFO[lab]["inputs"]:
        value = bad_value(info)
        status, _, stderr = cli(lab, [f"{info['flag']}={value}"])
        assert status == 2, info["flag"]
        with pytest.raises(ValueError) as raised:
            getattr(rl, lab)(**{keyword(info["flag"]): value})
        assert stderr.strip() == f"{lab}: error: {raised.value}", info["flag"]
        assert str(raised.value).startswith(info["flag"] + ": ")


def test_an_unknown_keyword_names_the_nearest_option():
    with pytest.raises(TypeError, match="did you mean 'spin_rpm'"):
        rl.top_nutation(spin_rmp=500)
    with pytest.raises(TypeError, match="takes a number"):
        rl.top_nutation(mass=[1, 2])
    # a choice of numbers takes the number itself
    assert rl.tennis_racquet(spin_axis=1).inputs["spin_axis"] == "1"
    with pytest.raises(TypeError, match="takes one of 1, 2, 3"):
        rl.tennis_racquet(spin_axis=4.5)


def test_help_shows_every_input_with_its_unit_default_and_rule():
    doc = rl.top_nutation.__doc__
    for info in INFO["top_nutation"]["inputs"]:
        assert f"\n{keyword(info['flag'])} : " in doc
    assert "mass : number [kg], default " in doc
    # the rules as --help states them, the options named as keywords
    assert "(between 0 and 2, exclusive; default: the preset's; not with inertia)" in \
        rl.football.__doc__


@pytest.mark.parametrize("lab", [lab for lab in LABS if INFO[lab]["csv"]])
def test_series_equal_the_command_lines_csv(lab, tmp_path):
    csv_path = tmp_path / f"{lab}.csv"
    status, _, _ = cli(lab, ["--csv", str(csv_path)])
    assert status == 0
    lines = csv_path.read_text().splitlines()
    columns = lines[0].split(",")
    numbers = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    r = getattr(rl, lab)()
    assert list(r.series) == columns
    for k, column in enumerate(columns):
        # 17 digits in the file: the same doubles
        assert np.array_equal(r.series[column], numbers[:, k]), column
    again = tmp_path / "again.csv"
    assert r.csv(again) == str(again) and again.read_text() == csv_path.read_text()
    # its metadata too, but for the file it names
    meta = (tmp_path / "again.csv-metadata.json").read_text()
    assert meta == (tmp_path / f"{lab}.csv-metadata.json").read_text().replace(
        f'"url": "{lab}.csv"', '"url": "again.csv"')
    # a path --csv refuses is refused with its rule, and nothing is written
    with pytest.raises(ValueError, match="is a directory, not a file"):
        r.csv(tmp_path)
    with pytest.raises(ValueError, match="leaves no room for the metadata"):
        r.csv(tmp_path / ("z" * 238 + ".csv"))
    assert not (tmp_path / ("z" * 238 + ".csv")).exists()


@pytest.mark.skipif(not rl._rigidlab.has_renderer, reason="built without the renderer")
@pytest.mark.parametrize("lab", LABS)
def test_figures_save_as_the_command_line_draws_them(lab, tmp_path):
    status, _, _ = cli(lab, ["--figures", str(tmp_path / "cli"), "--figure-size", "800x600"])
    assert status == 0
    r = getattr(rl, lab)()
    names = list(r.figures)
    assert names
    first = names[0]
    png = r.figures[first].save(tmp_path / f"{first}.png", size=(800, 600))
    assert open(png, "rb").read() == (tmp_path / "cli" / f"{lab}_{first}.png").read_bytes()
    for fmt, magic in (("svg", b"<?xml"), ("pdf", b"%PDF")):
        data = r.figures[first].data(fmt, (800, 600))
        assert data.startswith(magic), fmt
    # inline as PNG; SVG too when asked for, the <svg> element alone (HTML allows no XML
    # declaration)
    assert r.figures[first]._repr_png_().startswith(b"\x89PNG")
    assert r.figures[first]._repr_svg_() is None
    try:
        rl.inline_formats = ("png", "svg")
        assert r.figures[first]._repr_svg_().startswith("<svg")
    finally:
        rl.inline_formats = ("png",)


def test_a_thread_pool_gives_what_one_thread_gives():
    # The GIL is released while a lab computes: two threads at once, the same answers.
    def answer(spin):
        return rl.top_nutation(spin_rpm=spin).json["results"]

    spins = [300 + 25 * k for k in range(8)]
    serial = [answer(s) for s in spins]
    with ThreadPoolExecutor(2) as pool:
        assert list(pool.map(answer, spins)) == serial


@pytest.mark.skipif(not rl._rigidlab.has_renderer, reason="built without the renderer")
def test_a_figure_shows_inline_and_survives_an_html_export():
    # what IPython's display machinery sends for a figure, then nbconvert's HTML export of
    # a notebook holding that output: the figure's PNG is in the page
    formatters = pytest.importorskip("IPython.core.formatters")
    nbformat = pytest.importorskip("nbformat")
    exporters = pytest.importorskip("nbconvert.exporters")
    import base64

    data, _ = formatters.DisplayFormatter().format(rl.tennis_racquet().figures["growth"])
    assert "image/png" in data and "image/svg+xml" not in data
    png = data["image/png"]
    png = png if isinstance(png, str) else base64.b64encode(png).decode()
    assert base64.b64decode(png).startswith(b"\x89PNG")
    cell = nbformat.v4.new_code_cell("r.figures['growth']", outputs=[
        nbformat.v4.new_output("display_data", data={"image/png": png, "text/plain": "fig"})])
    html, _ = exporters.HTMLExporter().from_notebook_node(nbformat.v4.new_notebook(cells=[cell]))
    assert f"data:image/png;base64,{png}" in html.replace("\n", "")
