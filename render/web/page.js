// The page of an interactive curvefig figure: sliders, draggable points,
// the figures as SVG, the script's error, the current values as Lua.
//
// CurvefigPage(root, engine) builds it in root; engine.run(values)
// returns a Promise of the JSON of one run (render/lua/interactive.h),
// values = { t: 0.75, P: [[x, y], ...] }.  The live server's engine POSTs
// to the server (live.js); the page of -f html computes in WebAssembly.
// An engine may have watch(callback), called when the script was saved:
// the page runs the script again; when that run succeeds and the engine
// has reload(values), the page is reloaded through it (new or removed
// sliders come with the new page), else the reply is shown in place (a
// script that fails keeps the drawing, faded, under its error).  An
// engine's saved() gives the values to start from (those of the page
// before the reload), else the defaults.
//
// Two parts live in files of their own, included in the page before this
// one: turning a 3D figure (page-rotate.js, CurvefigRotate) and the
// keyboard for the handles (page-keys.js, CurvefigKeys); each is given
// what it needs from here explicitly.
//
// The DOM, the same for every engine (the browser tests rely on it):
//   #cf-controls           one .cf-slider per slider:
//     input#cf-slider-NAME (type range, data-param NAME), output#cf-value-NAME
//   #cf-figures            div.cf-figure#cf-figure-NAME per figure, holding
//                          its <svg>, in which circle.cf-handle#cf-handle-P-I
//                          (data-param, data-index) are the draggable points
//                          (an invisible disc that takes the pointer) and
//                          circle.cf-ring their visible rings, smaller than
//                          a label's distance from its point;
//                          its data-to-svg: the map data -> SVG units (JSON);
//                          a handle takes the focus (tabindex 0, role
//                          slider, aria-valuetext "P_1: x 2.5, y 3") and
//                          the arrow keys (Shift: ten steps; page-keys.js)
//   div#cf-announce        aria-live: the place of a point the keys moved
// A slider's label is typeset from the label syntax (P_0, w_{1}, \omega,
// $...$): italic letters, upright digits, sub- and superscripts, Greek.
// Values are rounded: a slider's to its step's decimals (the engine does
// the same), a dragged point's to the figure's resolution (a tenth of a
// bp, in data units' decimals), a grid's to the grid's decimals.  A
// dragged handle stays inside the figure's view.  While a slider or a
// handle is moved, every figure keeps the map (and view) it had when the
// move began, so that the drawing stands still under the pointer
// (an automatic legend finding another place would shift it); released,
// the figures show their own layout again.  scale = "log" sliders move
// by ratios (the range input holds log10 of the value).
// A 3D figure (its reply has a view) is div.cf-figure.cf-3d, with
// data-view="[azimuth, elevation]" (the view it is drawn in) and
// tabindex 0: dragging its background (not a handle) turns it, as do the
// arrow keys when it has the focus; the page sends the angles with the
// values as "@view:NAME": [[azimuth, elevation]] (render/lua/params.h)
// and the script runs again in that view; a double click or its
// button.cf-view-reset goes back to the script's view (page-rotate.js).
// A 2D figure ignores drags of its background.
//   pre#cf-error           the script's error (hidden when there is none)
//   pre#cf-lua             the values as Lua, button#cf-copy, button#cf-reset
//   root.dataset.runs      the number of replies shown so far;
//   root.dataset.busy      "1" while a run is under way (one whose reply
//                          will be shown: not a stale draft, request());
//   root.dataset.draft     "1" while the drawing shown is a draft;
//   root.dataset.runMs     the engine's time of the last run (ms), when
//                          the engine tells it (the course page's does)
//   root.dataset.draftAfterMs  DRAFT_AFTER_MS (below)
//   root.dataset.exactMs   the time of the last exact run, from the request
//                          to the reply (ms)
// Drafts: while the pointer drags a slider, a point or a 3D figure whose
// last exact run took more than DRAFT_AFTER_MS, each run is sent with
// "@draft": 1 and the script runs with looser tolerances (render/lua/
// params.h; docs/interactive.md, "Drafts"); when the pointer is released
// the exact run follows.  A key press runs exactly, as does a drag of a
// figure whose runs are quick (a draft would gain nothing there).
function CurvefigPage(root, engine) {
  'use strict';
  var svgNS = 'http://www.w3.org/2000/svg';
  var values = engine.saved ? engine.saved() : {};  // what the next run sends
  var views = takeViews(values);  // figure name -> [az, el] turned to
  var reloadOnGood = false; // the script was saved: reload once it runs
  var params = [];          // the declarations of the last good reply
  var signature = null;     // of the declarations, to rebuild on a change
  var inFlight = false, pending = false, runs = 0;
  var running = [];         // the runs under way (request())
  var sentSeq = 0, shownSeq = 0;   // the last run sent, the last shown
  var lanes = engine.lanes || 1;   // runs the engine takes at once
  var sliding = false;      // the pointer holds a slider
  var draftShown = false;   // the drawing shown (or under way) is a draft
  // exact runs quicker than a frame (60 Hz): no drafts (docs/
  // interactive.md, "Drafts")
  var DRAFT_AFTER_MS = 16;
  root.dataset.draftAfterMs = String(DRAFT_AFTER_MS);
  var exactMs = 0;          // the last exact run's time
  var drag = null;          // { param, index, fig, svg, circle }
  var lastFigures = null;   // of the last reply shown

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // The rotated views among saved values (the page before a reload).
  function takeViews(v) {
    var out = {};
    Object.keys(v).forEach(function (k) {
      if (k.indexOf('@view:') === 0) {
        var a = v[k] && v[k][0];
        if (a && isFinite(a[0]) && isFinite(a[1]))
          out[k.slice(6)] = [Number(a[0]), Number(a[1])];
        delete v[k];
      }
    });
    return out;
  }

  // The values with the rotated views (what a run is sent).
  function withViews(v) {
    var out = JSON.parse(JSON.stringify(v));
    Object.keys(views).forEach(function (name) {
      out['@view:' + name] = [views[name]];
    });
    return out;
  }

  root.classList.add('cf-page');
  var controls = el('div', { id: 'cf-controls' });
  var figures = el('div', { id: 'cf-figures' });
  var error = el('pre', { id: 'cf-error', hidden: '' });
  var side = el('div', { id: 'cf-side' });
  var lua = el('pre', { id: 'cf-lua' });
  var buttons = el('div', { class: 'cf-buttons' });
  var copy = el('button', { id: 'cf-copy', type: 'button' }, 'Copy values');
  var reset = el('button', { id: 'cf-reset', type: 'button' }, 'Reset');
  buttons.appendChild(copy);
  buttons.appendChild(reset);
  side.appendChild(controls);
  side.appendChild(buttons);
  side.appendChild(lua);
  root.appendChild(side);
  var main = el('div', { id: 'cf-main' });
  main.appendChild(error);
  main.appendChild(figures);
  root.appendChild(main);

  // The decimals x is written with (up to 12): 2 for 0.25.
  // (relative to x 10^k, as render/lua/params.c: 7 for 1e-7, not 0)
  function decimals(x) {
    for (var k = 0, p = 1; k < 12; k++, p *= 10)
      if (Math.abs(Math.round(x * p) - x * p) <= 1e-6 * Math.abs(x * p))
        return k;
    return 12;
  }

  function round(v, k) {
    var p = Math.pow(10, k), r = Math.round(v * p) / p;
    return isFinite(r) ? r : v;   // v * p beyond the largest double
  }

  // The decimals a slider's values are shown with: its step's (and its
  // min's); a continuous slider's, a thousandth of its range (of the
  // value, for a log slider).
  function sliderDecimals(p, v) {
    if (p.step > 0) return Math.max(decimals(p.step), decimals(p.min));
    var unit = p.scale === 'log' ? Math.abs(v) * Math.LN10 *
      (Math.log10(p.max) - Math.log10(p.min)) / 1000 : (p.max - p.min) / 1000;
    return Math.max(0, Math.min(12, Math.ceil(-Math.log10(unit))));
  }

  function fmt(p, v) {
    return String(round(v, sliderDecimals(p, v)));
  }

  function snap(p, v) {
    v = Math.min(p.max, Math.max(p.min, v));
    if (p.step > 0) {
      v = p.min + Math.round((v - p.min) / p.step) * p.step;
      if (v > p.max) v -= p.step;
    }
    return round(v, sliderDecimals(p, v));
  }

  // The range input's position of a value, and back.
  function toPos(p, v) {
    return p.scale === 'log' ? Math.log10(v) : v;
  }
  function fromPos(p, x) {
    return p.scale === 'log' ? Math.pow(10, x) : x;
  }

  // A point's coordinates rounded to a tenth of a bp of figure fig.
  function roundPoint(fig, d) {
    var m = fig.to_svg;
    var kx = Math.max(0, Math.ceil(Math.log10(10 * Math.hypot(m[0], m[1]))));
    var ky = Math.max(0, Math.ceil(Math.log10(10 * Math.hypot(m[2], m[3]))));
    return [round(d[0], Math.min(12, kx)), round(d[1], Math.min(12, ky))];
  }

  // The multiple of q nearest v, or v where v / q is beyond 2^53 or
  // overflows (a grid of 1e-320): as render/lua/params.c snaps.
  function nearestMultiple(v, q) {
    var k = v / q;
    return isFinite(k) && Math.abs(k) < 9007199254740992 ? Math.round(k) * q
                                                          : v;
  }

  function constrain(p, x, y) {
    var c = p.constrain;
    if (c && c.grid) {
      var k = decimals(c.grid);
      return [round(nearestMultiple(x, c.grid), k),
              round(nearestMultiple(y, c.grid), k)];
    }
    if (c && c.line) {
      var a = c.line[0], b = c.line[1], dx = b[0] - a[0], dy = b[1] - a[1];
      var t = ((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy);
      var q = [a[0] + t * dx, a[1] + t * dy];
      if (!(isFinite(q[0]) && isFinite(q[1]))) {
        // a line through points near the largest double: from its
        // midpoint along its direction scaled to 1 (params.c)
        var mx = 0.5 * a[0] + 0.5 * b[0], my = 0.5 * a[1] + 0.5 * b[1];
        var ux = 0.5 * b[0] - 0.5 * a[0], uy = 0.5 * b[1] - 0.5 * a[1];
        var m = Math.max(Math.abs(ux), Math.abs(uy));
        ux /= m;
        uy /= m;
        t = ((x - mx) * ux + (y - my) * uy) / (ux * ux + uy * uy);
        q = [mx + t * ux, my + t * uy];
      }
      return isFinite(q[0]) && isFinite(q[1]) ? q : [x, y];
    }
    return [x, y];
  }

  // ---- slider labels: the label syntax typeset -------------------------

  var symbols = {
    alpha: 'α', beta: 'β', gamma: 'γ', delta: 'δ', epsilon: 'ϵ',
    varepsilon: 'ε', zeta: 'ζ', eta: 'η', theta: 'θ', vartheta: 'ϑ',
    iota: 'ι', kappa: 'κ', lambda: 'λ', mu: 'μ', nu: 'ν', xi: 'ξ', pi: 'π',
    rho: 'ρ', sigma: 'σ', tau: 'τ', upsilon: 'υ', phi: 'ϕ', varphi: 'φ',
    chi: 'χ', psi: 'ψ', omega: 'ω', Gamma: 'Γ', Delta: 'Δ', Theta: 'Θ',
    Lambda: 'Λ', Xi: 'Ξ', Pi: 'Π', Sigma: 'Σ', Upsilon: 'Υ', Phi: 'Φ',
    Psi: 'Ψ', Omega: 'Ω', cdot: '⋅', ldots: '…', infty: '∞', le: '≤',
    ge: '≥', in: '∈', pm: '±', times: '×', ',': ' ', ';': ' ', quad: ' '
  };

  // Label text src typeset into a span.cf-math: letters (and lower-case
  // Greek) in italics, digits and the rest upright, _ and ^ as sub- and
  // superscripts of a {group} or one symbol, \text{...} upright, $ left
  // out.
  function typeset(src) {
    var i = 0;
    function atom(out, upright) {
      var c = src[i];
      if (c === '{') {
        i++;
        seq(out, upright, '}');
        i++;
        return;
      }
      if (c === '\\') {
        var m = /^\\([A-Za-z]+|.)/.exec(src.slice(i));
        var name = m ? m[1] : '';
        i += m ? m[0].length : 1;
        if (name === 'text' || name === 'mathrm') {
          while (src[i] === ' ') i++;
          atom(out, true);
          return;
        }
        var sym = symbols[name] !== undefined ? symbols[name] : name;
        var lower = /^[a-z]/.test(name) && /[α-ω]/.test(sym);
        out.appendChild(lower && !upright ? el('i', {}, sym)
                                          : document.createTextNode(sym));
        return;
      }
      i++;
      if (c === '$') return;
      if (/[A-Za-zα-ω]/.test(c) && !upright) out.appendChild(el('i', {}, c));
      else out.appendChild(document.createTextNode(c));
    }
    function seq(out, upright, end) {
      while (i < src.length && src[i] !== end) {
        var c = src[i];
        if ((c === '_' || c === '^') && i + 1 < src.length) {
          i++;
          var s = el(c === '_' ? 'sub' : 'sup');
          atom(s, upright);
          out.appendChild(s);
        } else if (c === ' ' && !upright) {
          i++;
        } else {
          atom(out, upright);
        }
      }
    }
    var span = el('span', { class: 'cf-math' });
    seq(span, false, undefined);
    return span;
  }

  function paramNamed(name) {
    for (var i = 0; i < params.length; i++)
      if (params[i].name === name) return params[i];
    return null;
  }

  // ---- the controls ----------------------------------------------------

  function buildControls(list) {
    controls.textContent = '';
    list.forEach(function (p) {
      if (p.kind === 'slider') {
        var row = el('div', { class: 'cf-slider' });
        var lab = el('label', { for: 'cf-slider-' + p.name });
        lab.appendChild(typeset(p.label));
        var lo = toPos(p, p.min), hi = toPos(p, p.max);
        var input = el('input', {
          type: 'range', id: 'cf-slider-' + p.name, 'data-param': p.name,
          'data-scale': p.scale || 'linear', min: lo, max: hi,
          step: p.step > 0 && p.scale !== 'log' ? p.step : (hi - lo) / 1000,
        });
        input.value = toPos(p, p.value);
        var out = el('output', { id: 'cf-value-' + p.name }, fmt(p, p.value));
        sliderA11y(input, p, fmt(p, p.value));
        input.addEventListener('input', function () {
          values[p.name] = snap(p, fromPos(p, Number(input.value)));
          out.textContent = fmt(p, values[p.name]);
          sliderA11y(input, p, out.textContent);
          hold();
          request();
        });
        input.addEventListener('change', release);
        input.addEventListener('pointerdown', function () {
          sliding = true;
        });
        row.appendChild(lab);
        row.appendChild(input);
        row.appendChild(out);
        controls.appendChild(row);
      } else {
        controls.appendChild(el('div', { class: 'cf-points' },
          'Drag the points ' + p.name + (p.constrain && p.constrain.grid ?
          ' (on a grid of ' + p.constrain.grid + ')' : p.constrain &&
          p.constrain.line ? ' (along a line)' : '') + '.'));
      }
    });
  }

  // ---- accessible names (docs/accessibility.md) ------------------------

  // A label's source as read aloud: P_0 "P sub 0", \omega_{1} "omega sub
  // 1", w^2 "w sup 2"; braces, dollars and backslashes dropped.
  function spoken(src) {
    return String(src).replace(/\\frac\{([^}]*)\}\{([^}]*)\}/g, '$1/$2')
      .replace(/\\(text|mathrm|mathbf|mathit|boldsymbol|operatorname)\b/g,
               '')
      .replace(/_/g, ' sub ').replace(/\^/g, ' sup ')
      .replace(/[{}$\\]/g, '').replace(/\s+/g, ' ').trim();
  }

  // A slider named by its label's text, its value said as shown (a log
  // slider's position is the value's logarithm).
  function sliderA11y(input, p, shown) {
    input.setAttribute('aria-label', spoken(p.label || p.name));
    input.setAttribute('aria-valuetext', shown);
  }

  // The SVG's aria-labelledby and aria-describedby, their ids prefixed as
  // uniqueIds prefixes the ids.
  function a11yIds(svg, pre) {
    return svg.replace(/aria-(labelledby|describedby)="([^"]*)"/g,
      function (all, which, ids) {
        return 'aria-' + which + '="' + ids.split(/\s+/).map(function (id) {
          return pre + id;
        }).join(' ') + '"';
      });
  }

  // A figure's box: a figure labelled by its SVG's title, and its long
  // description (the SVG's <desc>) in a details element below it, open
  // or closed as the reader left it.
  var descOpen = {};
  function describeFigure(box, svg, name) {
    var desc = svg && svg.querySelector('desc');
    var title = svg && svg.querySelector('title');
    box.setAttribute('role', 'figure');
    if (title && title.id) box.setAttribute('aria-labelledby', title.id);
    if (!desc || !desc.textContent) return;
    var details = el('details', { class: 'cf-description' });
    var summary = el('summary', {}, 'Description');
    var text = el('p', {}, desc.textContent);
    details.appendChild(summary);
    details.appendChild(text);
    if (descOpen[name]) details.open = true;
    details.addEventListener('toggle', function () {
      descOpen[name] = details.open;
    });
    box.appendChild(details);
  }

  // ---- the figures -----------------------------------------------------

  // The SVG of figure k with its ids made unique in the page (two figures
  // both define glyph0-1).
  function uniqueIds(svg, k) {
    var pre = 'cf' + k + '-';
    return a11yIds(svg, pre).replace(/<\?xml[^>]*\?>\s*/, '')
      .replace(/\bid="([^"]*)"/g, 'id="' + pre + '$1"')
      .replace(/href="#([^"]*)"/g, 'href="#' + pre + '$1"')
      .replace(/url\(#([^)]*)\)/g, 'url(#' + pre + '$1)');
  }

  function toData(fig, sx, sy) {
    var m = fig.to_svg, det = m[0] * m[3] - m[1] * m[2];
    var x = sx - m[4], y = sy - m[5];
    return [(m[3] * x - m[2] * y) / det, (-m[1] * x + m[0] * y) / det];
  }

  function toSvg(fig, x, y) {
    var m = fig.to_svg;
    return [m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]];
  }

  // ---- holding the layout still while something moves ------------------

  var held = null;   // figure name -> { m, vb, w, h } while a move goes on

  // A move began: every figure keeps the map and view it shows now (the
  // map its box was drawn with: a draft still held after a release, its
  // exact run under way, is drawn in the map of the move before).  A
  // drag that will draw drafts starts the engine's drafts' worker now, if
  // the page has not yet (request()).
  function hold() {
    if (engine.warm && exactMs > DRAFT_AFTER_MS) engine.warm();
    if (held || !lastFigures) return;
    held = {};
    figures.querySelectorAll('.cf-figure').forEach(function (box, k) {
      var svg = box.querySelector('svg'), f = lastFigures[k];
      if (!svg || !f) return;
      var m = JSON.parse(box.getAttribute('data-to-svg') || 'null');
      held[f.name] = { m: m || f.to_svg, vb: svg.getAttribute('viewBox'),
                       w: svg.getAttribute('width'),
                       h: svg.getAttribute('height') };
    });
  }

  // The move ended: the figures take their own layout again (and a
  // draft its exact run).
  function release() {
    exact();
    if (!held) return;
    held = null;
    if (!inFlight && !drag && lastFigures) showFigures(lastFigures);
  }

  // ---- drafts ----------------------------------------------------------

  // A drag under way: the runs it asks for are drafts.
  function drafting() {
    return exactMs > DRAFT_AFTER_MS &&
      (sliding || drag !== null || (rotate && rotate.rotating()));
  }

  // An exact run took ms (request to reply).
  function noteExact(ms) {
    exactMs = ms;
    root.dataset.exactMs = ms.toFixed(1);
  }

  // The drag ended: the exact run of the values, when a draft was asked
  // for since the last exact one.
  function exact() {
    if (draftShown && !drafting()) request();
  }

  // The affine map a o b^-1 (maps as [a b c d e f]: x' = a x + c y + e).
  function compose(a, b) {
    var det = b[0] * b[3] - b[1] * b[2];
    var i = [b[3] / det, -b[1] / det, -b[2] / det, b[0] / det,
             (b[2] * b[5] - b[3] * b[4]) / det,
             (b[1] * b[4] - b[0] * b[5]) / det];
    return [a[0] * i[0] + a[2] * i[1], a[1] * i[0] + a[3] * i[1],
            a[0] * i[2] + a[2] * i[3], a[1] * i[2] + a[3] * i[3],
            a[0] * i[4] + a[2] * i[5] + a[4],
            a[1] * i[4] + a[3] * i[5] + a[5]];
  }

  // Figure fig's drawing in svg moved onto the held map and view h: its
  // content in a group mapping its own map's SVG units onto h's.
  function align(svg, fig, h) {
    var g = document.createElementNS(svgNS, 'g');
    var t = compose(h.m, fig.to_svg);
    g.setAttribute('transform', 'matrix(' + t.join(' ') + ')');
    Array.prototype.slice.call(svg.childNodes).forEach(function (n) {
      if (n.nodeName !== 'defs' && n.nodeName !== 'title' &&
          n.nodeName !== 'desc')
        g.appendChild(n);
    });
    svg.appendChild(g);
    if (h.vb) svg.setAttribute('viewBox', h.vb);
    if (h.w) svg.setAttribute('width', h.w);
    if (h.h) svg.setAttribute('height', h.h);
    return Object.assign({}, fig, { to_svg: h.m });
  }

  // ---- drawing the figures ---------------------------------------------

  var HANDLE_R = 7;    // the disc that takes the pointer, SVG units (bp)
  var RING_R = 3.2;    // the ring shown: inside a label's 4 bp offset

  // Box fresh, built for a redraw, put in place of the box shown (the
  // same figure's): its attributes and content moved into it, so that the
  // element stays and keeps the keyboard's focus.  (A focused box taken
  // out of the document loses the focus, and focus() on the new one
  // recomputes the page's style and layout at once, a millisecond or two
  // of every turn by a key, which the frame then does again.)
  function adopt(box, fresh) {
    Array.prototype.slice.call(box.attributes).forEach(function (at) {
      if (!fresh.hasAttribute(at.name)) box.removeAttribute(at.name);
    });
    Array.prototype.forEach.call(fresh.attributes, function (at) {
      if (box.getAttribute(at.name) !== at.value)
        box.setAttribute(at.name, at.value);
    });
    box.textContent = '';
    while (fresh.firstChild) box.appendChild(fresh.firstChild);
  }

  function showFigures(list) {
    var a = document.activeElement;   // a figure keeps the keyboard focus
    var focusedBox = a && a.classList && a.classList.contains('cf-figure') &&
      figures.contains(a) ? a.id.slice(10) : null;
    var focused = keys.focusedHandle();      // ... or a handle
    // the same figures as shown (every redraw but the first and a
    // script's change): their boxes stay, their content is replaced
    var shown = figures.children;
    var same = shown.length === list.length && list.every(function (f, k) {
      return shown[k].id === 'cf-figure-' + f.name;
    });
    if (!same) figures.textContent = '';
    list.forEach(function (fig, k) {
      var box = el('div', { class: 'cf-figure', id: 'cf-figure-' + fig.name });
      box.innerHTML = uniqueIds(fig.svg, k);
      var svg = box.querySelector('svg');
      if (svg && held && held[fig.name]) fig = align(svg, fig, held[fig.name]);
      box.setAttribute('data-to-svg', JSON.stringify(fig.to_svg));
      if (svg && fig.caption && !svg.hasAttribute('aria-labelledby'))
        svg.setAttribute('aria-label', fig.caption);
      describeFigure(box, svg, fig.name);
      if (fig.view) rotate.markRotatable(box, fig);
      fig.handles.forEach(function (h) {
        var at = toSvg(fig, h.x, h.y);
        var ring = document.createElementNS(svgNS, 'circle');
        ring.setAttribute('class', 'cf-ring');
        ring.setAttribute('cx', at[0]);
        ring.setAttribute('cy', at[1]);
        ring.setAttribute('r', RING_R);
        var c = document.createElementNS(svgNS, 'circle');
        c.setAttribute('class', 'cf-handle');
        c.setAttribute('id', 'cf-handle-' + h.param + '-' + h.index);
        c.setAttribute('data-param', h.param);
        c.setAttribute('data-index', h.index);
        c.setAttribute('cx', at[0]);
        c.setAttribute('cy', at[1]);
        c.setAttribute('r', HANDLE_R);
        c.ring = ring;
        c.addEventListener('pointerdown', function (ev) {
          ev.preventDefault();
          c.setPointerCapture(ev.pointerId);
          hold();
          drag = { param: h.param, index: h.index, fig: fig, svg: svg,
                   circle: c };
          c.classList.add('cf-dragging');
        });
        keys.keyboardHandle(c, fig, svg, h);
        svg.appendChild(c);
        svg.appendChild(ring);
      });
      if (same) adopt(shown[k], box);
      else figures.appendChild(box);
    });
    if (focusedBox !== null) {
      var again = document.getElementById('cf-figure-' + focusedBox);
      if (again && again !== document.activeElement) again.focus();
    }
    keys.refocus(focused);
  }

  function place(circle, x, y) {
    circle.setAttribute('cx', x);
    circle.setAttribute('cy', y);
    if (circle.ring) {
      circle.ring.setAttribute('cx', x);
      circle.ring.setAttribute('cy', y);
    }
  }

  // SVG point u kept inside svg's view, a handle's ring whole.
  function inView(svg, u) {
    var vb = svg.viewBox && svg.viewBox.baseVal;
    if (!(vb && vb.width > 0 && vb.height > 0)) return u;
    var r = Math.min(RING_R + 1, vb.width / 2, vb.height / 2);
    return { x: Math.min(vb.x + vb.width - r, Math.max(vb.x + r, u.x)),
             y: Math.min(vb.y + vb.height - r, Math.max(vb.y + r, u.y)) };
  }

  function pointerMove(ev) {
    if (!drag) return;
    var svg = drag.svg, pt = svg.createSVGPoint();
    pt.x = ev.clientX;
    pt.y = ev.clientY;
    var u = inView(svg, pt.matrixTransform(svg.getScreenCTM().inverse()));
    var p = paramNamed(drag.param);
    var d = toData(drag.fig, u.x, u.y);
    d = constrain(p, d[0], d[1]);
    if (!(p.constrain && p.constrain.grid)) d = roundPoint(drag.fig, d);
    var s = toSvg(drag.fig, d[0], d[1]);
    place(drag.circle, s[0], s[1]);
    var old = values[drag.param][drag.index];
    if (old && old[0] === d[0] && old[1] === d[1]) return;  // (seen twice)
    values[drag.param][drag.index] = d;
    request();
  }

  // Released: the handles go where the last reply puts them (the map may
  // have moved with the margins while the point was dragged).  After a
  // draft the exact run is sent first and its reply draws them (as
  // release() does): the draft is not drawn again in its own layout
  // before the run is even sent.
  function pointerUp() {
    if (sliding) {
      sliding = false;
      exact();
    }
    if (!drag) return;
    drag.circle.classList.remove('cf-dragging');
    drag = null;
    held = null;
    exact();
    if (!inFlight && lastFigures) showFigures(lastFigures);
  }
  // The moves of a drag: 'pointermove', and 'pointerrawupdate' where the
  // browser has it (in a secure context: a file, localhost), which comes
  // as soon as the pointer moves, where 'pointermove' waits for the next
  // frame (on the course page's drags 4 ms at the median, up to 11, of
  // every move).  A move seen twice (its pointermove after its raw
  // update, at the same place) changes nothing and runs nothing.
  var MOVES = ['pointermove'].concat('onpointerrawupdate' in window ?
                                     ['pointerrawupdate'] : []);
  MOVES.forEach(function (t) {
    window.addEventListener(t, pointerMove);
  });
  window.addEventListener('pointerup', pointerUp);
  window.addEventListener('pointercancel', pointerUp);

  // ---- turning a 3D figure (page-rotate.js) ----------------------------

  var rotate = CurvefigRotate({
    figures: figures, el: el, request: request, hold: hold, release: release,
    moves: MOVES,
    views: function () { return views; },
    lastFigures: function () { return lastFigures; },
    drag: function () { return drag; }
  });

  // ---- the keyboard: a handle is a slider (page-keys.js) ---------------

  var keys = CurvefigKeys({
    root: root, figures: figures, el: el, paramNamed: paramNamed,
    toSvg: toSvg, toData: toData, inView: inView, constrain: constrain,
    roundPoint: roundPoint, place: place, request: request,
    values: function () { return values; }
  });

  // ---- runs ------------------------------------------------------------

  function show(reply, draft) {
    runs++;
    var sig = JSON.stringify(reply.params.map(function (p) {
      return [p.kind, p.name, p.label, p.min, p.max, p.step, p.default,
              p.figure, p.constrain];
    }));
    // on an error the controls stay as they were (the script may have
    // stopped before declaring some of them)
    if (reply.error === null) {
      if (sig !== signature && !drag) {
        signature = sig;
        params = reply.params;
        // the reply's values are the ones sent, clamped and snapped
        values = {};
        params.forEach(function (p) {
          values[p.name] = p.kind === 'slider' ? p.value :
            p.value.map(function (q) { return q.slice(); });
        });
        buildControls(params);
      } else {
        params = reply.params;
      }
    }
    if (reply.error) {
      error.textContent = reply.error.message;
      error.hidden = false;
      figures.classList.add('cf-stale');
    } else {
      error.hidden = true;
      error.textContent = '';
      figures.classList.remove('cf-stale');
      lastFigures = reply.figures;
      if (!drag) showFigures(reply.figures);
      else updateFigures(reply.figures);
      lua.textContent = reply.lua + rotate.viewsLua();
    }
    root.dataset.draft = draft ? '1' : '0';
    if (typeof reply.ms === 'number')
      root.dataset.runMs = reply.ms.toFixed(2);
    root.dataset.runs = String(runs);
  }

  // While a point is dragged, its circle stays under the pointer: the
  // drawing is replaced, the dragged handle kept.
  function updateFigures(list) {
    var keep = drag.circle;
    showFigures(list);
    var box = figures.querySelectorAll('.cf-figure')[
      list.findIndex(function (f) { return f.name === drag.fig.name; })];
    if (!box) return;
    var svg = box.querySelector('svg');
    var fresh = svg.querySelector('[id="cf-handle-' + drag.param + '-' +
                                  drag.index + '"]');
    if (fresh) place(fresh, keep.getAttribute('cx'), keep.getAttribute('cy'));
    list.forEach(function (f) {
      if (f.name === drag.fig.name)
        drag.fig = held && held[f.name] ?
          Object.assign({}, f, { to_svg: held[f.name].m }) : f;
    });
    drag.svg = svg;
    // the old circle, detached, lost the capture: the moves reach the
    // window's listener, which now moves the new one
    if (fresh) {
      fresh.classList.add('cf-dragging');
      drag.circle = fresh;
    }
  }

  // Runs under way: { seq, draft, stale } each.  A run goes out at once
  // when none is under way; otherwise it waits (pending) for the reply,
  // and goes with the latest values then -- except an exact run asked
  // for while only drafts are under way (the pointer released during a
  // drag) on an engine with two lanes (the course page's, html.js: one
  // worker for the exact runs, one for the drafts): it goes at once, and
  // the drafts under way are stale: their replies are dropped when they
  // come (older values, looser tolerances).  A draft waits for a stale
  // draft still under way (the draft lane is busy).  A reply is shown only
  // if no run sent after it has been shown: an older reply never replaces
  // a newer drawing.
  function live() {
    return running.filter(function (r) { return !r.stale; });
  }

  function request() {
    var now = live(), draft = drafting();
    var wait = now.length > 0 ?
      draft || lanes < 2 || !now.every(function (r) { return r.draft; }) :
      draft && running.length > 0;
    if (wait) {
      pending = true;
      root.dataset.busy = '1';   // (after a stale draft, none may be)
      return;
    }
    pending = false;
    root.dataset.busy = '1';
    var sent = withViews(values);
    if (draft) sent['@draft'] = 1;
    else running.forEach(function (r) { r.stale = true; });
    if (draft && engine.warm) engine.warm();
    var me = { seq: ++sentSeq, draft: draft, stale: false };
    running.push(me);
    inFlight = true;
    draftShown = draft;
    var reload = reloadOnGood;
    reloadOnGood = false;
    var t0 = performance.now();
    engine.run(sent).then(function (reply) {
      if (!draft) noteExact(performance.now() - t0);
      if (me.stale || me.seq < shownSeq) return;   // superseded
      shownSeq = me.seq;
      if (reload && reply.error === null && engine.reload) {
        pending = false;
        engine.reload(withViews(values));
        return;
      }
      show(reply, draft);
      // a figure whose runs take long enough for drafts: the drafts'
      // worker started once the page is idle, not at a drag's press
      // (its start, 50-250 ms, would hold up the drag's first moves)
      if (!draft && engine.warm && reply.ms > DRAFT_AFTER_MS)
        (window.requestIdleCallback || setTimeout)(engine.warm);
    }, function (err) {
      if (me.stale || me.seq < shownSeq) return;
      error.textContent = 'no answer: ' + err;
      error.hidden = false;
    }).catch(function (e) {
      // a reply the page could not draw: said, and the runs go on (the
      // bookkeeping below must run, or every later run would wait)
      error.textContent = 'the page could not draw the reply: ' + e;
      error.hidden = false;
      root.dataset.runs = String(runs);   // (a reply shown: its error)
      console.error(e);
    }).then(function () {
      running.splice(running.indexOf(me), 1);
      inFlight = live().length > 0;
      if (pending) request();
      if (!inFlight && !pending) root.dataset.busy = '0';
      // (busy: "1" while a run whose reply will be shown is under way or
      // waits; a stale draft still computing is not)
    });
  }

  copy.addEventListener('click', function () {
    if (navigator.clipboard) navigator.clipboard.writeText(lua.textContent);
  });
  reset.addEventListener('click', function () {
    values = {};
    views = {};
    signature = null;
    request();
  });
  if (engine.watch) {
    engine.watch(function () {
      reloadOnGood = true;
      request();
    });
  }
  request();
}
