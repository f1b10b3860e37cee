"""Every ```python block of README.md, python/README.md and docs/*.md runs (issue 46).

The blocks are read from the documents when the test runs, never copied here. The
blocks of one document run in order in one namespace (a later block uses what an
earlier one defined: python/README.md's `deckland`, `scenario`, `Client`), in a scratch
folder where ``scenarios/`` is the repository's (the documents run from the root).
A failure names the document and the line: the code is compiled with the document's
name and line numbers, so the traceback points into the document.

Rules, each mechanical (never an edit of a document):

- Runs are shrunk: the value of a keyword argument ``runs=N`` (a literal) becomes
  min(N, RUNS_CAP).
- A block with ``if __name__ == "__main__":`` is a script: it runs in the namespace
  (defining what it defines, its guard false) and also, saved to a file, as
  ``python FILE`` in the scratch folder (as its comment says to run it).
- ``dask_jobqueue`` (``SLURMCluster``, ``PBSCluster``) and ``dask_kubernetes.operator``
  (``KubeCluster``) are stand-ins: a cluster that takes any arguments, ignores
  ``scale(...)`` and is one in-process worker thread of a ``distributed.LocalCluster``.
  No test machine has a Slurm queue or a Kubernetes cluster; the block's code runs
  as written against it.
- A ``python synopsis`` block (a signature with what the reader supplies) runs with the
  names of SYNOPSIS_NAMES bound first: ``action = None``, the built-in cascade (the
  table under ``deckland.Approach``'s synopsis).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import traceback
import types
from pathlib import Path
from typing import Dict, Iterator, List, Tuple

import pytest

REPOSITORY = Path(__file__).resolve().parents[2]
DOCUMENTS = [
    REPOSITORY / "README.md",
    REPOSITORY / "python" / "README.md",
    *sorted((REPOSITORY / "docs").glob("*.md")),
]
RUNS_CAP = 8
SYNOPSIS_NAMES = {"action": None}
PYTHON_INFO = ("python", "python synopsis")
FENCE = re.compile(r"^( *)```(.*)$")


def blocks(path: Path) -> Iterator[Tuple[int, str, str]]:
    """The fenced code blocks of ``path``: the opening fence's line (from 1), the info
    string and the code, the fence's indent removed."""
    lines = path.read_text(encoding="utf-8").split("\n")
    index = 0
    while index < len(lines):
        fence = FENCE.match(lines[index])
        if not fence:
            index += 1
            continue
        indent, info, start = len(fence.group(1)), fence.group(2).strip(), index
        body: List[str] = []
        index += 1
        while index < len(lines) and lines[index].strip() != "```":
            line = lines[index]
            body.append(line[min(indent, len(line) - len(line.lstrip(" "))) :])
            index += 1
        assert index < len(lines), f"{path}:{start + 1}: a code block is not closed"
        index += 1
        yield start + 1, info, "\n".join(body) + "\n"


def relative(path: Path) -> str:
    return str(path.relative_to(REPOSITORY))


def python_blocks(path: Path) -> List[Tuple[int, str, str]]:
    return [block for block in blocks(path) if block[1] in PYTHON_INFO]


def shrunk(code: str) -> str:
    """``runs=N`` (a literal) as ``runs=min(N, RUNS_CAP)``."""

    def cap(match: "re.Match[str]") -> str:
        return f"{match.group(1)}{min(int(match.group(2).replace('_', '')), RUNS_CAP)}"

    return re.sub(r"(\bruns\s*=\s*)([0-9][0-9_]*)\b", cap, code)


def stand_in_cluster_modules(started: list) -> Dict[str, types.ModuleType]:
    """``dask_jobqueue`` and ``dask_kubernetes.operator`` with a local cluster's
    stand-ins for their cluster classes; each cluster started is appended to
    ``started``."""
    from distributed import LocalCluster

    class StandInCluster(LocalCluster):
        """One in-process worker thread; takes the real cluster's arguments."""

        def __init__(self, *args, **kwargs):
            self.doc_block_arguments = (args, kwargs)
            super().__init__(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=":0")
            started.append(self)

        def scale(self, *args, **kwargs):  # the jobs or pods a real cluster would start
            return None

    jobqueue = types.ModuleType("dask_jobqueue")
    jobqueue.SLURMCluster = jobqueue.PBSCluster = StandInCluster
    kubernetes = types.ModuleType("dask_kubernetes")
    operator = types.ModuleType("dask_kubernetes.operator")
    operator.KubeCluster = StandInCluster
    kubernetes.operator = operator
    return {"dask_jobqueue": jobqueue, "dask_kubernetes": kubernetes, "dask_kubernetes.operator": operator}


def compiled(path: Path, line: int, code: str):
    """``code`` compiled as the document's own lines: a traceback names the document and
    the line of the document."""
    return compile("\n" * line + code, relative(path), "exec")


def run_script(path: Path, line: int, code: str, folder: Path) -> None:
    saved = folder / f"{path.stem}-{line}.py"
    saved.write_text("\n" * line + code, encoding="utf-8")
    environment = dict(os.environ, MPLBACKEND="Agg")
    environment.pop("DISPLAY", None)
    result = subprocess.run(
        [sys.executable, str(saved)],
        cwd=folder,
        env=environment,
        capture_output=True,
        text=True,
        timeout=600,
    )
    if result.returncode != 0:
        pytest.fail(
            f"{relative(path)}:{line}: the ```python block, run as a script ({saved}), "
            f"failed ({result.returncode}):\n{result.stderr[-3000:]}",
            pytrace=False,
        )


def test_every_python_block_is_found():
    """The documents hold python blocks, and each python block's info string is one of
    PYTHON_INFO (a ```py or ```python3 block would not be run)."""
    found = [(path, line) for path in DOCUMENTS for line, _, _ in python_blocks(path)]
    assert len(found) >= 3, found
    for path in DOCUMENTS:
        for line, info, _ in blocks(path):
            if info.split(" ")[0] in ("py", "python3", "pycon", "ipython"):
                pytest.fail(f"{relative(path)}:{line}: ```{info}: write ```python (or ```text)", pytrace=False)


@pytest.mark.parametrize(
    "path",
    [path for path in DOCUMENTS if python_blocks(path)],
    ids=lambda path: relative(path),
)
def test_the_python_blocks_run(path, tmp_path, monkeypatch):
    (tmp_path / "scenarios").symlink_to(REPOSITORY / "scenarios")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    clusters: list = []
    for name, module in stand_in_cluster_modules(clusters).items():
        monkeypatch.setitem(sys.modules, name, module)
    namespace = {"__name__": "deckland_doc_blocks"}
    try:
        run_blocks(path, namespace, tmp_path)
    finally:
        for cluster in clusters:  # the blocks leave them open, as a session would
            try:
                cluster.close()
            except TimeoutError:
                # The stand-in's event-loop thread did not stop within distributed's 10 s
                # (a loaded machine): housekeeping of the test's own stand-in, not a fault
                # of the document; the daemon thread ends with the process.
                pass


def run_blocks(path: Path, namespace: dict, folder: Path) -> None:
    for line, info, code in python_blocks(path):
        code = shrunk(code)
        if info == "python synopsis":
            for name, value in SYNOPSIS_NAMES.items():
                namespace.setdefault(name, value)
        failure = None
        try:
            exec(compiled(path, line, code), namespace)
        except Exception as error:  # noqa: BLE001 - any failure of a block is reported
            failure = f"{type(error).__name__}: {error}\n{traceback.format_exc()}"
        if failure is not None:
            pytest.fail(f"{relative(path)}:{line}: the ```{info} block fails: {failure}", pytrace=False)
        if 'if __name__ == "__main__":' in code:
            run_script(path, line, code, folder)
