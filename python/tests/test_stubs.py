"""The type stubs (_persson.pyi) list every function and method with the
runtime's parameter names, in order, so editors complete and check calls."""

import ast
import inspect
import pathlib

import persson

STUB = pathlib.Path(persson.__file__).with_name("_persson.pyi")


def stub_signatures():
    tree = ast.parse(STUB.read_text())
    out = {}

    def params(f):
        a = f.args
        return [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs if x.arg != "self"]

    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[node.name] = params(node)
        elif isinstance(node, ast.ClassDef) and node.name == "Spectrum":
            for f in node.body:
                if isinstance(f, ast.FunctionDef):
                    out["Spectrum." + f.name] = params(f)
    return out


def test_stub_matches_runtime():
    stubs = stub_signatures()
    assert (pathlib.Path(persson.__file__).with_name("py.typed")).exists()
    for name in persson.__all__:
        obj = getattr(persson, name)
        if name == "Spectrum":
            for m in ["self_affine", "example", "tabulated", "from_csv", "from_file",
                      "from_height_map", "from_topography", "c", "rms_height", "rms_slope",
                      "rms_curvature", "report"]:
                sig = inspect.signature(getattr(persson.Spectrum, m))
                runtime = [p for p in sig.parameters if p != "self"]
                assert stubs["Spectrum." + m] == runtime, m
            continue
        runtime = list(inspect.signature(obj).parameters)
        assert stubs[name] == runtime, name
        assert obj.__doc__, name


def test_version_is_the_packages():
    """An independent value: the version pyproject.toml declares."""
    import re
    text = (pathlib.Path(__file__).resolve().parents[1] / "pyproject.toml").read_text()
    declared = re.search(r'^version = "([^"]+)"', text, re.M).group(1)
    assert persson.__version__ == persson.version() == declared
