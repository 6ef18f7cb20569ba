"""Figures: scripts of the figure language run in the renderer.

A Figure writes its calls as a script of the language (docs/language.md),
one statement a line, and renders it with the same sandbox, layout and
writers as `curvefig render`; so a figure made in Python is the figure the
tool makes of that script, byte for byte, and `fig.script()` is that
script.  render_script() runs a script of one's own.
"""

import json
import os
import re
import sys
import tempfile

from . import _core
from .lua import CURVES, Lua, literal

FORMATS = ("svg", "pdf", "ps", "eps", "png", "pgf")
_WHERE = re.compile(r"^(?P<chunk>[^\n]*?):(?P<line>\d+):")
# an element's script line inside a message: "label 2 "P" (line 5) lies"
_LINE = re.compile(r"\(line (\d+)([,)])")


def _module_path():
    """The course page's WebAssembly module, installed beside the
    package."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)),
                        "curvefig.wasm")


def have_html():
    """True when the course page of -f html can be written: the module
    was built with the WebAssembly module of the course pages."""
    return _core.have_html() and os.path.isfile(_module_path())


def _write_atomic(path, data):
    """data to path through a temporary file renamed over it: a failure
    leaves no half file."""
    path = os.fspath(path)
    d = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=d, prefix=".curvefig-")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


class _Rendered:
    """What Figure and ScriptFigure share: rendering one figure of a script
    to bytes, the notebook's display methods, saving."""

    dpi = 150

    def _source(self):
        raise NotImplementedError

    def _chunk(self):
        return "figure"

    def _fail(self, err):
        raise err

    def _lines_named(self, msg):
        """msg with the script lines it names where they were written."""
        return msg

    def _run(self, params=None):
        if params is None:
            params = getattr(self, "_default_params", None)
        code, index_name = self._source()
        key = (code, json.dumps(params, sort_keys=True) if params else None)
        cache = getattr(self, "_cache", None)
        if cache is not None and cache[0] == key:
            return cache[1], cache[2]
        try:
            s = _core.Script(code, self._chunk(),
                             json.dumps(params) if params else None)
        except ValueError as e:
            self._fail(e)
        names = [n for n, _ in s.figures]
        if index_name not in names:
            raise ValueError("the script made no figure named %r (it made "
                             "%s)" % (index_name, ", ".join(names) or "none"))
        i = names.index(index_name)
        if s.output:
            sys.stdout.write(s.output)
        self._cache = (key, s, i)
        return s, i

    def render(self, format="svg", dpi=None, tight=False, padding=0.0,
               step=0, params=None):
        """The figure as bytes in one format: svg, pdf, ps, eps, png, pgf."""
        s, i = self._run(params)
        try:
            return s.render(i, format, self.dpi if dpi is None else dpi,
                            tight, padding, step)
        except ValueError as e:
            raise ValueError(self._lines_named(str(e))) from None

    def params(self):
        """The sliders and point lists the figure's script declares, as
        dicts (kind, name, min, max, step, default, ...)."""
        s, _ = self._run()
        return s.params

    def html(self):
        """The course page of the figure (curvefig render -f html): one
        self-contained HTML file whose sliders and points work without a
        server.  Needs a module built with the WebAssembly module."""
        if not have_html():
            raise RuntimeError(
                "html: this curvefig was built without the WebAssembly "
                "module of the course pages (emscripten and Lua's source: "
                "see docs/python.md)")
        code, name = self._source()
        s, i = self._run()
        with tempfile.TemporaryDirectory(prefix="curvefig-") as d:
            script = os.path.join(d, self._file_name())
            page = os.path.join(d, name + ".html")
            with open(script, "w", encoding="utf-8") as f:
                f.write(code)
            s.html(i, script, page, _module_path())
            with open(page, encoding="utf-8") as f:
                return f.read()

    def _file_name(self):
        return "figure.lua"

    def save(self, path, format=None, **options):
        """Write the figure to path; the format from the extension (svg,
        pdf, ps, eps, png, pgf, or html for the course page) unless given."""
        fmt = format or os.path.splitext(os.fspath(path))[1][1:].lower()
        if fmt == "tex":
            fmt = "pgf"
        if fmt == "html":
            data = self.html().encode("utf-8")
        elif fmt in FORMATS:
            data = self.render(fmt, **options)
        else:
            raise ValueError("save: unknown format %r of %s; the formats are "
                             "%s and html" % (fmt, path, ", ".join(FORMATS)))
        _write_atomic(path, data)

    # ---- Jupyter ----------------------------------------------------------

    def _repr_svg_(self):
        return self.render("svg").decode("utf-8")

    def _repr_png_(self):
        return self.render("png")

    def _repr_html_(self):
        """The interactive page, for a figure with sliders or draggable
        points, in an iframe (its script and style kept apart from the
        notebook's); None otherwise, so that the SVG is shown."""
        if not have_html() or not self.params():
            return None
        import html as _html
        page = self.html()
        # the frame as high as the figure (its SVG's height in pt, 4/3 px
        # each) and the page's controls below it
        m = re.search(rb'<svg[^>]*height="([0-9.]+)pt"', self.render("svg"))
        height = int(float(m.group(1)) * 4 / 3) + 160 if m else 640
        return ('<iframe class="curvefig" sandbox="allow-scripts" '
                'style="width: 100%%; height: %dpx; border: none" '
                'srcdoc="%s"></iframe>' % (height,
                                           _html.escape(page, quote=True)))

    def widgets(self):
        """The figure with its parameters as ipywidgets (a slider per
        slider{}, x and y fields per point of a points{}), rendered again
        (natively, as SVG) at every change."""
        from .widgets import interact
        return interact(self)


class Ref:
    """A value of the script: the result of a figure method or of a
    function of the language, usable as an argument of later calls, and
    whose methods are the language's (``ref.eval(t)`` writes
    ``R[k]:eval(t)``)."""

    def __init__(self, fig, code, count=None):
        self._fig = fig
        self._code = code
        self._count = count

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        return lambda *a, **kw: self._fig._call(self._code + ":" + name, a, kw)

    def __getitem__(self, k):
        if not isinstance(k, int) or k < 0:
            raise IndexError("a script value is indexed from 0")
        return Ref(self._fig, "%s[%d]" % (self._base(), k + 1))

    def __iter__(self):
        if self._count is None:
            raise TypeError("this value of the script has no known length; "
                            "index it: r[0], r[1], ...")
        return iter([self[k] for k in range(self._count)])

    def _base(self):
        return self._code[:-3] if self._code.endswith("[1]") else self._code

    def __repr__(self):
        return "<curvefig script value %s>" % self._code


class Figure(_Rendered):
    """A figure of the language: ``Figure(name, **options)`` is
    ``figure{ name = ..., ... }``, and every method of the language's
    figures (curve, polygon, hull, points, decasteljau, deboor, knots,
    basis, plot, label, legend, inset, panels, ...) is a method here, its
    positional arguments as in the language and its options as keyword
    arguments.  slider() and points() declare the interactive parameters.
    """

    def __init__(self, name="figure", **options):
        self._name = name
        self._lines = []
        self._where = []
        self._names = {}
        self._keep = []
        self._count = 0
        opts = {"name": name}
        opts.update(options)
        self._emit("local R = {}", None)
        self._emit("local f = figure(%s)" % literal(opts, "figure"),
                   self._caller())

    # ---- writing the script ----------------------------------------------

    @staticmethod
    def _caller():
        f = sys._getframe(2)
        here = os.path.dirname(os.path.abspath(__file__))
        while f is not None and os.path.dirname(
                os.path.abspath(f.f_code.co_filename)) == here:
            f = f.f_back
        return (f.f_code.co_filename, f.f_lineno) if f is not None else None

    def _emit(self, line, where):
        self._lines.append(line)
        self._where.append(where)
        self._cache = None

    def _ref(self, v):
        if isinstance(v, Ref):
            if v._fig is not self:
                raise ValueError("a value of another figure's script")
            return v._code
        if isinstance(v, CURVES):
            name = self._names.get(id(v))
            if name is None:
                self._count += 1
                name = "R[%d]" % self._count
                self._emit("%s = %s" % (name, literal(v, "figure")),
                           self._caller())
                self._names[id(v)] = name
                self._keep.append(v)
            return name
        return None

    def _call(self, target, args, kw, count=None):
        where = self._caller()
        method = target.rsplit(":", 1)[-1].rsplit(".", 1)[-1]
        parts = [literal(a, method, self._ref) for a in args]
        if kw:
            parts.append(literal(kw, method, self._ref))
        self._count += 1
        k = self._count
        self._emit("R[%d] = table.pack(%s(%s))" % (k, target,
                                                   ", ".join(parts)), where)
        return Ref(self, "R[%d][1]" % k, count)

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        return lambda *a, **kw: self._call("f:" + name, a, kw)

    def panels(self, **options):
        """f:panels{...}: the panels, one Figure-like value per cell."""
        n = int(options.get("rows", 1)) * int(options.get("cols", 1))
        return self._call("f:panels", (options,), {}, count=n)

    def slider(self, name, **options):
        """slider{ name = ..., min =, max =, default =, step =, label = }:
        a number of the script (a widget in the notebook)."""
        opts = {"name": name}
        opts.update(options)
        return self._call("slider", (opts,), {})

    def points_param(self, name, default, **options):
        """points{ name = ..., default = ... }: draggable points."""
        opts = {"name": name, "default": default}
        opts.update(options)
        return self._call("points", (opts,), {})

    def call(self, function, *args, **kw):
        """Any function of the language: ``f.call("interpolate", {...})``."""
        if not re.match(r"^[A-Za-z_][A-Za-z0-9_.]*$", function):
            raise ValueError("call: %r is not a function name" % function)
        return self._call(function, args, kw)

    def lua(self, code):
        """A statement of Lua written into the script as it is."""
        self._emit(code, self._caller())
        return self

    def script(self):
        """The figure's script (what `curvefig render` would take)."""
        return "\n".join(self._lines) + "\n"

    def _source(self):
        return self.script(), self._name

    def _chunk(self):
        return "figure " + self._name

    def _file_name(self):
        return self._name + ".lua"

    def _lines_named(self, msg):
        """An element's line of the generated script in msg ("label 2 "P"
        (line 5) lies ...") as the Python file and line that added it."""
        def where(m):
            line = int(m.group(1))
            if 1 <= line <= len(self._where) and self._where[line - 1]:
                fn, ln = self._where[line - 1]
                return "(%s, line %d%s" % (fn, ln, m.group(2))
            return m.group(0)
        return _LINE.sub(where, msg)

    def _fail(self, err):
        msg = str(err)
        m = _WHERE.match(msg)
        if m and m.group("chunk") == self._chunk():
            line = int(m.group("line"))
            if 1 <= line <= len(self._where) and self._where[line - 1]:
                fn, ln = self._where[line - 1]
                msg = "%s (%s, line %d: %s)" % (
                    msg, fn, ln, self._lines[line - 1][:200])
        raise ValueError(msg) from None

    def __repr__(self):
        return "<curvefig.Figure %r, %d statements>" % (self._name,
                                                        len(self._lines) - 2)


class ScriptFigure(_Rendered):
    """One figure of a script run by render_script()."""

    def __init__(self, code, name, caption, chunk, path):
        self._code = code
        self.name = name
        self.caption = caption
        self._chunk_name = chunk
        self._path = path

    def _source(self):
        return self._code, self.name

    def _chunk(self):
        return self._chunk_name

    def _file_name(self):
        return os.path.basename(self._path) if self._path else "script.lua"

    def __repr__(self):
        return "<curvefig figure %r of %s>" % (self.name, self._chunk_name)


def render_script(script, params=None):
    """Run a figure script (a path, or the text of a script) and return its
    figures, in the order the script defined them.  params gives sliders
    and points values ({"t": 0.5, "P": [[0, 0], [1, 2]]}).  A script's
    error is a ValueError with its file and line."""
    path = None
    if isinstance(script, os.PathLike) or (
            isinstance(script, str) and "\n" not in script
            and script.endswith(".lua")):
        path = os.fspath(script)
        with open(path, encoding="utf-8") as f:
            code = f.read()
        chunk = path
    elif isinstance(script, str):
        code = script
        chunk = "script"
    else:
        raise TypeError("render_script: a path or the text of a script")
    s = _core.Script(code, chunk, json.dumps(params) if params else None)
    if s.output:
        sys.stdout.write(s.output)
    figs = []
    for name, caption in s.figures:
        f = ScriptFigure(code, name, caption, chunk, path)
        f._default_params = params
        figs.append(f)
    return figs
