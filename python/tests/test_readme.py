"""The Python examples of python/README.md and the repository's README.md
run as written (each block in order, from the repository's root, where
their paths point); blocks that import GeoPandas or Dask are skipped when
those are not installed."""

import importlib.util
import os
import re
from pathlib import Path

import pytest

from conftest import REPO

BLOCK = re.compile(r"```python\n(.*?)```", re.S)


def blocks(path: Path):
    return BLOCK.findall(path.read_text())


def needs(code: str):
    return [m for m in ("geopandas", "dask") if re.search(rf"^\s*(import|from) {m}\b", code, re.M)]


CASES = [(p, i) for p in (REPO / "python" / "README.md", REPO / "README.md") for i in range(len(blocks(p)))]


@pytest.mark.parametrize("path,index", CASES, ids=[f"{p.parent.name}/{p.name}#{i}" for p, i in CASES])
def test_readme_block(path, index, monkeypatch):
    code = blocks(path)[index]
    missing = [m for m in needs(code) if importlib.util.find_spec(m) is None]
    if missing:
        pytest.skip(f"needs {', '.join(missing)}")
    monkeypatch.chdir(REPO)
    exec(compile(code, f"{path.name} block {index}", "exec"), {"__name__": "readme"})


def test_python_readme_has_examples():
    assert len(blocks(REPO / "python" / "README.md")) >= 5
    assert os.path.exists(REPO / "python" / "docs" / "centerlines.svg")
