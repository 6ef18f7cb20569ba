"""Sliders as ipywidgets: a figure's slider{} parameters bound to
FloatSliders, the figure rendered again (natively, SVG) at each change."""


def interact(fig):
    """A VBox of one FloatSlider per slider{} of fig's script and the
    figure below them."""
    try:
        import ipywidgets as w
    except ImportError as e:
        raise RuntimeError("widgets: ipywidgets is not installed (Debian: "
                           "python3-ipywidgets)") from e
    sliders = []
    for p in fig.params():
        if p["kind"] != "slider":
            continue
        step = p["step"] or (p["max"] - p["min"]) / 1000.0
        sliders.append(w.FloatSlider(value=p["value"], min=p["min"],
                                     max=p["max"], step=step,
                                     description=p["label"],
                                     continuous_update=True))
    view = w.HTML(fig.render("svg").decode("utf-8"))

    def update(_change=None):
        values = {s.description: s.value for s in sliders}
        names = {p["label"]: p["name"] for p in fig.params()
                 if p["kind"] == "slider"}
        params = {names[k]: v for k, v in values.items()}
        view.value = fig.render("svg", params=params).decode("utf-8")

    for s in sliders:
        s.observe(update, names="value")
    box = w.VBox(sliders + [view])
    box.update = update
    return box
