"""Shared helpers: the `persson` CLI as the oracle of every Python function.

Each test runs the CLI with ``--json`` on the same input as a Python call and
compares the two to the last digit: both serialise the same typed report with
serde_json, so equal floats print equal. Only wall times (``seconds``) differ
from run to run and are dropped; the CLI binary is ``$PERSSON_BIN`` or the
release build of this repository.
"""

import json
import os
import re
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = os.environ.get("PERSSON_BIN", str(ROOT / "target" / "release" / "persson"))


def run_cli(*args, cwd=None):
    """`persson ARGS --json` parsed; fails the test with the CLI's stderr."""
    r = subprocess.run(
        [BIN, *map(str, args), "--json"],
        capture_output=True,
        text=True,
        cwd=cwd,
        env={**os.environ, "RUST_BACKTRACE": "0"},
    )
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def cli_error(*args, cwd=None):
    """The CLI's one-line error without the `persson: error: ` prefix and
    without the flags the CLI names before the library's text (`--hurst: `):
    the text Python gives for the same input."""
    r = subprocess.run(
        [BIN, *map(str, args)],
        capture_output=True,
        text=True,
        cwd=cwd,
        env={**os.environ, "RUST_BACKTRACE": "0"},
    )
    assert r.returncode != 0, r.stdout
    line = r.stderr.strip().splitlines()[-1]
    prefix = "persson: error: "
    assert line.startswith(prefix), r.stderr
    return re.sub(r"^--[a-z0-9-]+(, --[a-z0-9-]+)*: ", "", line[len(prefix):])


def strip(value, drop=("seconds",)):
    """`value` without the keys in `drop` (wall times), at any depth."""
    if isinstance(value, dict):
        return {k: strip(v, drop) for k, v in value.items() if k not in drop}
    if isinstance(value, list):
        return [strip(v, drop) for v in value]
    return value


def same(python, cli, drop=("seconds",)):
    """Assert two reports equal to the last digit, wall times aside. A
    top-level `warnings` list the CLI prints beside the report (issue 15)
    is compared only when the Python dict has one too."""
    cli, python = dict(cli), dict(python)
    # A scene's sections and compare/hertz from Python carry no warnings list.
    if "warnings" in cli and "warnings" not in python:
        cli.pop("warnings")
    if "warnings" in python and "warnings" not in cli:
        python.pop("warnings")
    assert strip(python, drop) == strip(cli, drop)


def read_from(python, stand_in, path):
    """A Python report on heights given as an array, its warnings naming the
    file the CLI read instead of the stand-in (`(array)`, `(topography)`):
    the `file` field and the message's leading name. Nothing else changes,
    so the rest of each warning is compared as it is."""
    python = dict(python)
    warnings = []
    for w in python.get("warnings", []):
        w = dict(w)
        if w.get("file") == stand_in:
            w["file"] = str(path)
            assert w["message"].startswith(stand_in + ": "), w["message"]
            w["message"] = str(path) + w["message"][len(stand_in):]
        warnings.append(w)
    python["warnings"] = warnings
    return python


@pytest.fixture(scope="session", autouse=True)
def cli_binary():
    assert os.access(BIN, os.X_OK), f"no persson binary at {BIN}: run cargo build --release or set PERSSON_BIN"
