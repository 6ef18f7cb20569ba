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
// The DOM, the same for every engine (the browser tests rely on it):
//   #cf-controls           one .cf-slider per slider:
//     input#cf-slider-NAME (type range, data-param NAME), output#cf-value-NAME
//   #cf-figures            div.cf-figure#cf-figure-NAME per figure, holding
//                          its <svg>, in which circle.cf-handle#cf-handle-P-I
//                          (data-param, data-index) are the draggable points;
//                          its data-to-svg: the map data -> SVG units (JSON)
//   pre#cf-error           the script's error (hidden when there is none)
//   pre#cf-lua             the values as Lua, button#cf-copy, button#cf-reset
//   root.dataset.runs      the number of replies shown so far;
//   root.dataset.busy      "1" while a run is under way
function CurvefigPage(root, engine) {
  'use strict';
  var svgNS = 'http://www.w3.org/2000/svg';
  var values = engine.saved ? engine.saved() : {};  // what the next run sends
  var reloadOnGood = false; // the script was saved: reload once it runs
  var params = [];          // the declarations of the last good reply
  var signature = null;     // of the declarations, to rebuild on a change
  var inFlight = false, pending = false, runs = 0;
  var drag = null;          // { param, index, fig, svg, circle }
  var lastFigures = null;   // of the last reply shown

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
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

  function fmt(v) {
    return String(Math.round(v * 1e6) / 1e6);
  }

  function snap(p, v) {
    v = Math.min(p.max, Math.max(p.min, v));
    if (p.step > 0) {
      v = p.min + Math.round((v - p.min) / p.step) * p.step;
      if (v > p.max) v -= p.step;
    }
    return v;
  }

  function constrain(p, x, y) {
    var c = p.constrain;
    if (c && c.grid) {
      return [Math.round(x / c.grid) * c.grid, Math.round(y / c.grid) * c.grid];
    }
    if (c && c.line) {
      var a = c.line[0], b = c.line[1], dx = b[0] - a[0], dy = b[1] - a[1];
      var t = ((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy);
      return [a[0] + t * dx, a[1] + t * dy];
    }
    return [x, y];
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
        var lab = el('label', { for: 'cf-slider-' + p.name }, p.label);
        var range = (p.max - p.min);
        var input = el('input', {
          type: 'range', id: 'cf-slider-' + p.name, 'data-param': p.name,
          min: p.min, max: p.max,
          step: p.step > 0 ? p.step : range / 1000,
        });
        input.value = p.value;
        var out = el('output', { id: 'cf-value-' + p.name }, fmt(p.value));
        input.addEventListener('input', function () {
          values[p.name] = snap(p, Number(input.value));
          out.textContent = fmt(values[p.name]);
          request();
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

  // ---- the figures -----------------------------------------------------

  // The SVG of figure k with its ids made unique in the page (two figures
  // both define glyph0-1).
  function uniqueIds(svg, k) {
    var pre = 'cf' + k + '-';
    return svg.replace(/<\?xml[^>]*\?>\s*/, '')
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

  function showFigures(list) {
    figures.textContent = '';
    list.forEach(function (fig, k) {
      var box = el('div', { class: 'cf-figure', id: 'cf-figure-' + fig.name,
                            'data-to-svg': JSON.stringify(fig.to_svg) });
      box.innerHTML = uniqueIds(fig.svg, k);
      var svg = box.querySelector('svg');
      if (svg && fig.caption) svg.setAttribute('aria-label', fig.caption);
      fig.handles.forEach(function (h) {
        var c = document.createElementNS(svgNS, 'circle');
        c.setAttribute('class', 'cf-handle');
        c.setAttribute('id', 'cf-handle-' + h.param + '-' + h.index);
        c.setAttribute('data-param', h.param);
        c.setAttribute('data-index', h.index);
        c.setAttribute('cx', h.sx);
        c.setAttribute('cy', h.sy);
        c.setAttribute('r', 6);
        c.addEventListener('pointerdown', function (ev) {
          ev.preventDefault();
          c.setPointerCapture(ev.pointerId);
          drag = { param: h.param, index: h.index, fig: fig, svg: svg,
                   circle: c };
          c.classList.add('cf-dragging');
        });
        svg.appendChild(c);
      });
      figures.appendChild(box);
    });
  }

  function pointerMove(ev) {
    if (!drag) return;
    var svg = drag.svg, pt = svg.createSVGPoint();
    pt.x = ev.clientX;
    pt.y = ev.clientY;
    var u = pt.matrixTransform(svg.getScreenCTM().inverse());
    var p = paramNamed(drag.param);
    var d = constrain(p, toData(drag.fig, u.x, u.y)[0],
                      toData(drag.fig, u.x, u.y)[1]);
    var s = toSvg(drag.fig, d[0], d[1]);
    drag.circle.setAttribute('cx', s[0]);
    drag.circle.setAttribute('cy', s[1]);
    values[drag.param][drag.index] = d;
    request();
  }

  // Released: the handles go where the last reply puts them (the map may
  // have moved with the margins while the point was dragged).
  function pointerUp() {
    if (!drag) return;
    drag.circle.classList.remove('cf-dragging');
    drag = null;
    if (!inFlight && lastFigures) showFigures(lastFigures);
  }
  window.addEventListener('pointermove', pointerMove);
  window.addEventListener('pointerup', pointerUp);
  window.addEventListener('pointercancel', pointerUp);

  // ---- runs ------------------------------------------------------------

  function show(reply) {
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
      lua.textContent = reply.lua;
    }
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
    if (fresh) {
      fresh.setAttribute('cx', keep.getAttribute('cx'));
      fresh.setAttribute('cy', keep.getAttribute('cy'));
    }
    list.forEach(function (f) {
      if (f.name === drag.fig.name) drag.fig = f;
    });
    drag.svg = svg;
    // the old circle, detached, lost the capture: the moves reach the
    // window's listener, which now moves the new one
    if (fresh) {
      fresh.classList.add('cf-dragging');
      drag.circle = fresh;
    }
  }

  function request() {
    if (inFlight) {
      pending = true;
      return;
    }
    inFlight = true;
    pending = false;
    root.dataset.busy = '1';
    var sent = JSON.parse(JSON.stringify(values));
    var reload = reloadOnGood;
    reloadOnGood = false;
    engine.run(sent).then(function (reply) {
      if (reload && reply.error === null && engine.reload) {
        pending = false;
        engine.reload(values);
        return;
      }
      show(reply);
    }, function (err) {
      error.textContent = 'no answer: ' + err;
      error.hidden = false;
    }).then(function () {
      inFlight = false;
      if (pending) request();
      else root.dataset.busy = '0';
    });
  }

  copy.addEventListener('click', function () {
    if (navigator.clipboard) navigator.clipboard.writeText(lua.textContent);
  });
  reset.addEventListener('click', function () {
    values = {};
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
