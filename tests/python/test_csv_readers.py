"""A lab's CSV is read whole by the five readers students reach for, each with no option
but the delimiter: numpy's loadtxt (skiprows=1) and genfromtxt (names=True), pandas'
read_csv, csv.DictReader and R's read.csv. What each column means and its unit stand
beside it, in W3C CSV on the Web metadata (FILE-metadata.json) and in the JSON report."""

import csv
import json
import os
import shutil
import subprocess

import numpy as np
import pytest

import rigidlab as rl

LAB_DIR = os.environ.get("RIGID_LAB_DIR", "")
CSV_LABS = [d["name"] for d in rl._rigidlab.labs() if d["csv"]]


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """Each lab's CSV as its command line writes it, with the run's JSON report."""
    folder = tmp_path_factory.mktemp("csv")
    out = {}
    for lab in CSV_LABS:
        path = folder / f"{lab}.csv"
        proc = subprocess.run([os.path.join(LAB_DIR, lab), "--json", "--csv", str(path)],
                              capture_output=True, text=True, check=True)
        out[lab] = (path, json.loads(proc.stdout))
    return out


def ulps(read, exact):
    """The largest difference of `read` from `exact`, in units of exact's last place."""
    return (np.abs(read - exact) / np.spacing(np.abs(exact))).max()


def header_and_rows(path):
    """The header's names and the numbers, read by hand: what every reader must give."""
    lines = path.read_text().splitlines()
    return lines[0].split(","), np.array([[float(x) for x in line.split(",")]
                                          for line in lines[1:]])


@pytest.mark.parametrize("lab", CSV_LABS)
def test_numpy_pandas_and_the_csv_module_read_it_in_one_call(lab, written):
    path, _ = written[lab]
    names, rows = header_and_rows(path)
    assert np.isfinite(rows).all()  # no inf or nan for a reader to take as text
    # 17 digits in the file, and a correctly rounded reader: the same doubles
    assert np.array_equal(np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2), rows)
    table = np.genfromtxt(path, names=True, delimiter=",")
    assert list(table.dtype.names) == names
    assert all(np.array_equal(table[n], rows[:, k]) for k, n in enumerate(names))
    pandas = pytest.importorskip("pandas")
    frame = pandas.read_csv(path, float_precision="round_trip")
    assert list(frame.columns) == names
    assert np.array_equal(frame.to_numpy(), rows)
    # pandas' default parser ("high") is fast and not correctly rounded: 663 ulps seen (a
    # relative 1.5e-13) on 17 digits of 4.9e-17; round_trip above gives the doubles
    default = pandas.read_csv(path).to_numpy()
    assert (np.abs(default - rows) <= 1e-12 * np.abs(rows)).all()
    with open(path, newline="") as f:
        records = list(csv.DictReader(f))
    assert list(records[0]) == names
    assert np.array_equal(np.array([[float(r[n]) for n in names] for r in records]), rows)


@pytest.mark.skipif(shutil.which("Rscript") is None, reason="R (r-base-core) is not installed")
def test_r_reads_it_with_read_csv(written, tmp_path):
    # R prints what it read as 17 digits: the names, then each row
    script = ('d <- read.csv(commandArgs(TRUE)[1]); writeLines(paste(names(d), collapse=",")); '
              'stopifnot(all(sapply(d, is.numeric))); '
              'write.table(format(d, digits=17), sep=",", quote=FALSE, row.names=FALSE, '
              'col.names=FALSE)')
    for lab in CSV_LABS:
        path, _ = written[lab]
        names, rows = header_and_rows(path)
        proc = subprocess.run(["Rscript", "-e", script, str(path)], capture_output=True,
                              text=True)
        assert proc.returncode == 0, (lab, proc.stderr)
        lines = proc.stdout.splitlines()
        assert lines[0].split(",") == names, lab
        read = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
        # R promises 15 digits (read.csv's numerals = "allow.loss") and format(digits =
        # 17) rounds once more; R 4.2 gives the very doubles (0 ulps seen): within one
        assert read.shape == rows.shape, lab
        assert ulps(read, rows) <= 1, lab


@pytest.mark.parametrize("lab", CSV_LABS)
def test_the_metadata_beside_it_says_each_column_and_its_unit(lab, written):
    path, report = written[lab]
    names, _ = header_and_rows(path)
    meta = json.loads((path.parent / (path.name + "-metadata.json")).read_text())
    # CSV on the Web: the context, the table's url relative to the metadata, one column
    # description a header cell, in order, named as the header names it
    assert meta["@context"][0] == "http://www.w3.org/ns/csvw"
    assert meta["url"] == path.name
    assert meta["dc:title"].startswith(lab + ": ")
    columns = meta["tableSchema"]["columns"]
    assert [c["name"] for c in columns] == names
    assert [c["titles"] for c in columns] == names
    for c in columns:
        assert c["datatype"] == "double"
        assert c["dc:description"] and c["schema:unitText"], c["name"]
    # the JSON report says the same of the same columns
    assert report["series"]["title"] == meta["dc:title"]
    assert [(c["name"], c["unit"], c["meaning"]) for c in report["series"]["columns"]] == \
        [(c["name"], c["schema:unitText"], c["dc:description"]) for c in columns]
    # every file the run wrote is listed
    assert str(path) in report["outputs"] and str(path) + "-metadata.json" in report["outputs"]
    # and Python says it too
    r = getattr(rl, lab)()
    assert r.series_title == meta["dc:title"]
    assert [(c.name, c.unit, c.meaning) for c in r.series_columns.values()] == \
        [(c["name"], c["schema:unitText"], c["dc:description"]) for c in columns]


def test_a_file_name_becomes_a_relative_url(tmp_path):
    path = tmp_path / "run 1#ü.csv"
    subprocess.run([os.path.join(LAB_DIR, "poinsot"), "--quiet", "--csv", str(path)],
                   check=True)
    meta = json.loads((tmp_path / "run 1#ü.csv-metadata.json").read_text())
    assert meta["url"] == "run%201%23%C3%BC.csv"
