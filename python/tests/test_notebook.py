"""The notebook of examples/ runs under nbclient with a kernel of this
Python and this build, and its outputs hold the figure's SVG and, in a
build with the WebAssembly module, the interactive page."""

import json
import os
import shutil
import sys

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

import curvefig  # noqa: E402

SOURCE = os.environ.get("CURVEFIG_SOURCE",
                        os.path.join(os.path.dirname(__file__), "..", ".."))


def test_notebook(tmp_path, monkeypatch):
    # a kernel of this interpreter (the kernelspec python3 names whatever
    # python3 is first on PATH), with this build's PYTHONPATH
    spec = tmp_path / "jupyter" / "kernels" / "curvefig-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f",
                 "{connection_file}"],
        "display_name": "curvefig test", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "runtime"))
    # run in a copy of examples/, so that the saved files land there
    work = tmp_path / "examples"
    work.mkdir()
    nb_path = os.path.join(SOURCE, "examples", "curvefig.ipynb")
    shutil.copy(nb_path, work)
    (tmp_path / "figures").symlink_to(os.path.join(SOURCE, "figures"))
    nb = nbformat.read(nb_path, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=120, kernel_name="curvefig-test",
        resources={"metadata": {"path": str(work)}})
    # Debian 12's nbclient 0.7 reads a widget's state from the message that
    # opens its comm (ipywidgets 7 and later); Debian's ipywidgets 6 sends
    # it in a later one, and the handler (which only keeps widget state for
    # the saved notebook) fails with KeyError 'state'
    client.comm_open_handlers.pop("jupyter.widget", None)
    client.execute()
    data = [o.get("data", {}) for c in nb.cells if c.cell_type == "code"
            for o in c.get("outputs", [])]
    svgs = [d["image/svg+xml"] for d in data if "image/svg+xml" in d]
    assert len(svgs) >= 3 and all("<svg" in s for s in svgs)
    assert (work / "quartic.pdf").read_bytes().startswith(b"%PDF-")
    widgets = [d for d in data if
               "application/vnd.jupyter.widget-view+json" in d]
    assert widgets, "the widgets cell shows no widget"
    pages = [d["text/html"] for d in data if "text/html" in d and
             "CurvefigWasmEngine" in d["text/html"]]
    if not curvefig.have_html():
        assert not pages
        pytest.skip("no interactive page: the module was built without "
                    "the WebAssembly module (-Dwasm=disabled)")
    assert len(pages) == 1 and pages[0].startswith("<iframe")
