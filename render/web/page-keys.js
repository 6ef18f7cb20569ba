// The keyboard for the draggable points of the interactive page (page.js,
// whose header describes the DOM): a handle is a slider of two
// coordinates.
//
// Every handle takes the focus (Tab), role slider, its name and
// coordinates as aria-valuetext ("P_1: x 2.5, y 3"); the arrow keys move
// it by a step, Shift by ten, and the figures run again as after a drag;
// div#cf-announce (aria-live) says the point's new place.  A step is the
// grid of a point on a grid, else the power of ten of data units that is
// 1 to 10 bp in the figure (0.1 on a figure of 3 cm per unit); a point
// on a line moves along it.
//
// CurvefigKeys(host) appends div#cf-announce to host.root and returns
// what page.js calls: keyboardHandle(circle, fig, svg, handle) for every
// handle drawn, focusedHandle() before the figures are drawn again and
// refocus(f) after.  host gives:
//   root, figures  the page's root and its div#cf-figures
//   el(tag, attrs, text)   an element
//   values()       the values the next run sends (changed in place)
//   paramNamed(name)       a declaration of the last good reply
//   toSvg(fig, x, y), toData(fig, sx, sy)   data <-> SVG units
//   inView(svg, u) SVG point u kept inside svg's view
//   constrain(p, x, y), roundPoint(fig, d)  a point as a drag leaves it
//   place(circle, x, y)    a handle (and its ring) moved
//   request()      run the script again
function CurvefigKeys(host) {
  'use strict';
  var root = host.root, figures = host.figures, el = host.el;
  var paramNamed = host.paramNamed, toSvg = host.toSvg;
  var toData = host.toData, inView = host.inView;
  var constrain = host.constrain, roundPoint = host.roundPoint;
  var place = host.place, request = host.request;

  var announce = el('div', { id: 'cf-announce', class: 'cf-sr',
                             role: 'status', 'aria-live': 'polite' });
  root.appendChild(announce);

  var arrows = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1],
                 ArrowDown: [0, -1] };

  function num(v) {
    return String(Number(Number(v).toFixed(10)));
  }

  function pointText(param, index, d) {
    return param + '_' + index + ': x ' + num(d[0]) + ', y ' + num(d[1]);
  }

  function keyStep(p, fig, axis) {
    if (p.constrain && p.constrain.grid) return p.constrain.grid;
    var m = fig.to_svg;
    var bp = axis ? Math.hypot(m[2], m[3]) : Math.hypot(m[0], m[1]);
    return Math.pow(10, Math.ceil(Math.log10(1 / bp) - 1e-9));
  }

  // Point d of parameter p moved one key press in direction dir (times k).
  function stepPoint(p, fig, d, dir, k) {
    var c = p.constrain;
    if (c && c.line) {
      var a = c.line[0], b = c.line[1];
      var len = Math.hypot(b[0] - a[0], b[1] - a[1]);
      var u = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
      var dot = dir[0] * u[0] + dir[1] * u[1];
      var sign = dot > 1e-9 ? 1 : dot < -1e-9 ? -1 : dir[0] + dir[1];
      var s = k * keyStep(p, fig, 0);
      return [d[0] + sign * s * u[0], d[1] + sign * s * u[1]];
    }
    return [d[0] + dir[0] * k * keyStep(p, fig, 0),
            d[1] + dir[1] * k * keyStep(p, fig, 1)];
  }

  function keyboardHandle(c, fig, svg, h) {
    var values = host.values();
    var d = values[h.param] && values[h.param][h.index] || [h.x, h.y];
    c.setAttribute('tabindex', '0');
    c.setAttribute('role', 'slider');
    c.setAttribute('aria-roledescription', 'draggable point');
    c.setAttribute('aria-label', h.param + '_' + h.index);
    c.setAttribute('aria-valuenow', num(d[0]));
    c.setAttribute('aria-valuetext', pointText(h.param, h.index, d));
    c.setAttribute('aria-keyshortcuts',
                   'ArrowLeft ArrowRight ArrowUp ArrowDown');
    c.addEventListener('keydown', function (ev) {
      var values = host.values();
      var dir = arrows[ev.key], p = paramNamed(h.param);
      if (!dir || !p || !values[h.param] || ev.altKey || ev.ctrlKey ||
          ev.metaKey) return;
      ev.preventDefault();
      var q = stepPoint(p, fig, values[h.param][h.index], dir,
                        ev.shiftKey ? 10 : 1);
      var s = toSvg(fig, q[0], q[1]);
      var u = inView(svg, { x: s[0], y: s[1] });
      q = toData(fig, u.x, u.y);
      q = constrain(p, q[0], q[1]);
      if (!(p.constrain && p.constrain.grid)) q = roundPoint(fig, q);
      s = toSvg(fig, q[0], q[1]);
      place(c, s[0], s[1]);
      values[h.param][h.index] = q;
      c.setAttribute('aria-valuenow', num(q[0]));
      c.setAttribute('aria-valuetext', pointText(h.param, h.index, q));
      announce.textContent = pointText(h.param, h.index, q);
      request();
    });
  }

  // The handle that has the focus, as [param, index], or null; after the
  // figures are drawn again, its new circle takes the focus back.
  function focusedHandle() {
    var a = document.activeElement;
    return a && a.classList && a.classList.contains('cf-handle') &&
      figures.contains(a) ? [a.getAttribute('data-param'),
                             a.getAttribute('data-index')] : null;
  }

  function refocus(f) {
    if (!f) return;
    var c = figures.querySelector('[id="cf-handle-' + f[0] + '-' + f[1] +
                                  '"]');
    if (c) c.focus({ preventScroll: true });
  }

  return { keyboardHandle: keyboardHandle, focusedHandle: focusedHandle,
           refocus: refocus };
}
