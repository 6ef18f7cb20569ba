"""Figures: every format, the notebook's display methods, the same bytes
as the tool on the same script, scripts with sliders and their values."""

import os
import subprocess

import numpy as np
import pytest

import curvefig
from conftest import QUARTIC, tool

SOURCE = os.environ.get("CURVEFIG_SOURCE",
                        os.path.join(os.path.dirname(__file__), "..", ".."))
DECASTELJAU = os.path.join(SOURCE, "figures", "interactive", "decasteljau.lua")

MAGIC = {"svg": b"<?xml", "pdf": b"%PDF-", "ps": b"%!PS-Adobe",
         "eps": b"%!PS-Adobe", "png": b"\x89PNG\r\n\x1a\n",
         "pgf": b"%"}


def quartic_figure():
    c = curvefig.Bezier(QUARTIC)
    f = curvefig.Figure("quartic", width="8cm", height="8cm",
                        caption="A quartic Bézier curve")
    f.hull(c)
    f.polygon(c, labels="P_%d", label_place=["nw", "s", "se", "e", "e"])
    f.curve(c)
    f.points(c.eval(0.5), labels="c(1/2)", label_place="nw")
    return f


@pytest.mark.parametrize("fmt", sorted(MAGIC))
def test_formats(fmt, tmp_path):
    f = quartic_figure()
    data = f.render(fmt)
    assert data.startswith(MAGIC[fmt])
    f.save(tmp_path / ("q." + fmt))
    assert (tmp_path / ("q." + fmt)).read_bytes() == data
    if fmt == "pgf":
        assert b"\\begin{pgfpicture}" in data


def test_repr(tmp_path):
    f = quartic_figure()
    svg = f._repr_svg_()
    assert svg.startswith("<?xml") and "<svg" in svg
    assert f._repr_png_().startswith(MAGIC["png"])
    # no sliders: no interactive page, the notebook shows the SVG
    assert f._repr_html_() is None


def test_same_bytes_as_the_tool(tmp_path):
    """The Figure is a script of the language: the tool renders that
    script to the same SVG, byte for byte."""
    f = quartic_figure()
    script = tmp_path / "quartic.lua"
    script.write_text(f.script())
    subprocess.run([tool(), "render", str(script), "-f", "svg,png", "-o",
                    str(tmp_path)], check=True, capture_output=True)
    assert (tmp_path / "quartic.svg").read_bytes() == f.render("svg")
    assert (tmp_path / "quartic.png").read_bytes() == f.render("png")


def test_script_values_and_panels():
    c = curvefig.Bezier(QUARTIC)
    f = curvefig.Figure("panels", width="8cm", height="10cm")
    top, bottom = f.panels(rows=2, cols=1, share_x=True)
    top.curve(c)
    bottom.bernstein(4, 2)
    t = f.slider("t", min=0, max=1, default=0.25)
    top.decasteljau(c, t)
    assert "slider" in f.script() and "f:panels" in f.script()
    assert f.render("svg").startswith(b"<?xml")
    p = f.params()
    assert p[0]["kind"] == "slider" and p[0]["value"] == 0.25
    moved = f.render("svg", params={"t": 0.75})
    assert moved != f.render("svg")


def test_render_script_with_sliders():
    figs = curvefig.render_script(DECASTELJAU)
    assert [g.name for g in figs] == ["decasteljau"]
    g = figs[0]
    kinds = {p["name"]: p["kind"] for p in g.params()}
    assert kinds == {"P": "points", "t": "slider"}
    P = [p for p in g.params() if p["name"] == "P"][0]
    assert P["default"].shape == (5, 2)
    a = g.render("svg")
    b = g.render("svg", params={"t": 0.5})
    assert a != b and b"t = 0.50" not in a
    text = curvefig.render_script(open(DECASTELJAU).read())
    assert text[0].render("svg") == a
    given = curvefig.render_script(DECASTELJAU, params={"t": 0.5})[0]
    assert given.render("svg") == b


def test_interactive_page():
    g = curvefig.render_script(DECASTELJAU)[0]
    if not curvefig.have_html():
        with pytest.raises(RuntimeError, match="WebAssembly"):
            g.html()
        assert g._repr_html_() is None
        pytest.skip("the module was built without the WebAssembly module "
                    "(-Dwasm=disabled)")
    page = g.html()
    assert page.startswith("<!DOCTYPE html>") and "CurvefigWasmEngine" in page
    frame = g._repr_html_()
    assert frame.startswith("<iframe") and "CurvefigWasmEngine" in frame


def test_widgets():
    pytest.importorskip("ipywidgets")
    g = curvefig.render_script(DECASTELJAU)[0]
    box = g.widgets()
    slider = box.children[0]
    assert slider.description == "t" and slider.value == 0.75
    before = box.children[-1].value
    slider.value = 0.25
    assert box.children[-1].value != before
    assert box.children[-1].value.startswith("<?xml")
    # the points of points{}: a row (x, y) each; moving P_2 renders what
    # the script gives with that point moved, byte for byte
    rows = box.children[1:-1]
    assert len(rows) == 5
    x2, y2 = rows[2].children
    assert (x2.value, y2.value) == (3.0, 0.0)
    y2.value = 2.5
    P = [[0, 5], [1, -1], [3, 2.5], [4, 3], [6, 10]]
    direct = curvefig.render_script(DECASTELJAU, params={"t": 0.25, "P": P})
    assert box.children[-1].value == direct[0].render("svg").decode("utf-8")
    assert box.values() == {"t": 0.25, "P": P}


def test_print_output(capsys):
    curvefig.render_script('print("hello from Lua")\n')
    assert capsys.readouterr().out == "hello from Lua\n"


def test_lua_literals():
    from curvefig.lua import literal
    assert literal(0.1) == "0.1"
    assert literal(np.float64(1e-300)) == "1e-300"
    assert literal([1, 2.5, "a\"b\n"]) == '{1, 2.5, "a\\"b\\n"}'
    assert literal({"end": 1, "x": True}) == '{ ["end"] = 1, x = true }'
    s = curvefig.BSpline(2, None, [[0, 0], [1, 1], [2, 0]], weights=[1, 2, 1])
    assert literal(s).startswith("bspline{ degree = 2, knots = {0.0, 0.0, "
                                 "0.0, 1.0, 1.0, 1.0}")
    assert "weights = {1.0, 2.0, 1.0}" in literal(s)


def test_interactive_page_in_a_browser(tmp_path):
    """The notebook's _repr_html_ (the course page in a sandboxed iframe)
    draws the figure in a real browser, its WebAssembly module running in
    the frame, and moving the slider draws it again."""
    if not curvefig.have_html():
        pytest.skip("the module was built without the WebAssembly module")
    webdriver = pytest.importorskip("selenium.webdriver")
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    if not (os.path.exists("/usr/bin/chromium") and
            os.path.exists("/usr/bin/chromedriver")):
        pytest.skip("no chromium and chromedriver")
    g = curvefig.render_script(DECASTELJAU)[0]
    page = tmp_path / "notebook.html"
    page.write_text("<!DOCTYPE html><html><body><div class='output'>%s"
                    "</div></body></html>" % g._repr_html_())
    opts = webdriver.ChromeOptions()
    opts.binary_location = "/usr/bin/chromium"
    for a in ("--headless", "--no-sandbox", "--disable-gpu",
              "--disable-dev-shm-usage"):
        opts.add_argument(a)
    # the browser without the sanitizers' runtimes the interpreter may
    # have preloaded (python/tests/meson.build)
    preload = os.environ.pop("LD_PRELOAD", None)
    try:
        drv = webdriver.Chrome(service=Service("/usr/bin/chromedriver"),
                               options=opts)
    finally:
        if preload is not None:
            os.environ["LD_PRELOAD"] = preload
    try:
        drv.set_page_load_timeout(60)
        drv.get("file://%s" % page)
        drv.switch_to.frame(drv.find_element(By.TAG_NAME, "iframe"))
        from selenium.webdriver.support.ui import WebDriverWait

        from selenium.common.exceptions import StaleElementReferenceException

        def figure_svg(d):
            # a redraw replaces the figure's svg: one found just before it
            # may be gone when it is read, so look again
            try:
                e = d.find_elements(By.CSS_SELECTOR,
                                    '[id="cf-figure-decasteljau"] svg')
                return e[0].get_attribute("outerHTML") if e else False
            except StaleElementReferenceException:
                return False

        first = WebDriverWait(drv, 60).until(figure_svg)
        slider = drv.find_element(By.CSS_SELECTOR, "input[type=range]")
        slider.send_keys(Keys.HOME)
        WebDriverWait(drv, 60).until(
            lambda d: figure_svg(d) and figure_svg(d) != first)
        errors = [e for e in drv.get_log("browser")
                  if e.get("level") == "SEVERE"]
        assert not errors, errors
    finally:
        drv.quit()
