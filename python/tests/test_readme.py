"""The Python examples of the README and of the user guide (docs/*.md) run as written."""

import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]


def python_blocks():
    """Every ```python block of every page, with its page and first line."""
    for page in PAGES:
        text = page.read_text()
        for match in re.finditer(r"^```python\n(.*?)^```", text, re.S | re.M):
            line = text.count("\n", 0, match.start()) + 1
            yield pytest.param(match.group(1), id=f"{page.relative_to(ROOT)}:{line}")


BLOCKS = list(python_blocks())


def test_the_readme_and_the_guide_have_python_examples():
    assert any("README.md" in b.id for b in BLOCKS), "no python block in the README"
    assert any("docs/python.md" in b.id for b in BLOCKS), "no python block in docs/python.md"
    assert "pip install ./python" in (ROOT / "docs" / "python.md").read_text()


@pytest.mark.parametrize("code", BLOCKS)
def test_example_runs(code):
    exec(compile(code, "example", "exec"), {})
