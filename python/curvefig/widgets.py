"""A figure's parameters as ipywidgets: each slider{} a FloatSlider (a
FloatLogSlider for scale = "log"), each point of a points{} two FloatTexts
(x, y); the figure rendered again (natively, SVG) at each change, with the
values of every widget."""

import math


def _slider(w, p):
    if p.get("scale") == "log":
        return w.FloatLogSlider(value=p["value"], base=10,
                                min=math.log10(p["min"]),
                                max=math.log10(p["max"]),
                                step=(math.log10(p["max"])
                                      - math.log10(p["min"])) / 1000.0,
                                description=p["label"],
                                continuous_update=True)
    step = p["step"] or (p["max"] - p["min"]) / 1000.0
    return w.FloatSlider(value=p["value"], min=p["min"], max=p["max"],
                         step=step, description=p["label"],
                         continuous_update=True)


def interact(fig):
    """A VBox of the figure's parameter widgets and the figure below them:
    the sliders first, then a row (x, y) per point of each points{}."""
    try:
        import ipywidgets as w
    except ImportError as e:
        raise RuntimeError("widgets: ipywidgets is not installed (Debian: "
                           "python3-ipywidgets)") from e
    sliders = {}        # name -> widget
    points = {}         # name -> [(x widget, y widget), ...]
    slider_rows, point_rows = [], []
    for p in fig.params():
        if p["kind"] == "slider":
            sliders[p["name"]] = _slider(w, p)
            slider_rows.append(sliders[p["name"]])
        elif p["kind"] == "points":
            pairs = []
            for i, (x, y) in enumerate(p["value"].tolist()):
                pair = (w.FloatText(value=x, description="%s_%d x"
                                    % (p["name"], i)),
                        w.FloatText(value=y, description="y"))
                pairs.append(pair)
                point_rows.append(w.HBox(list(pair)))
            points[p["name"]] = pairs
    view = w.HTML(fig.render("svg").decode("utf-8"))

    def values():
        params = {name: s.value for name, s in sliders.items()}
        for name, pairs in points.items():
            params[name] = [[x.value, y.value] for x, y in pairs]
        return params

    def update(_change=None):
        view.value = fig.render("svg", params=values()).decode("utf-8")

    for s in sliders.values():
        s.observe(update, names="value")
    for pairs in points.values():
        for x, y in pairs:
            x.observe(update, names="value")
            y.observe(update, names="value")
    box = w.VBox(slider_rows + point_rows + [view])
    box.update = update
    box.values = values
    return box
