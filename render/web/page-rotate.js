// Turning a 3D figure of the interactive page (page.js, whose header
// describes the DOM): dragging a 3D figure's background (not a handle)
// turns it, as do the arrow keys when its box has the focus (a key held
// down, repeating, turns it as a drag does: drafts, then the exact run
// when the key goes up); a double click or its button.cf-view-reset goes
// back to the script's view.  The
// angles turned to are kept in page.js's views (figure name -> [azimuth,
// elevation]), which every run sends as "@view:NAME" (render/lua/
// params.h); viewsLua() writes them as Lua comments under the values.
//
// CurvefigRotate(host) listens on host.figures and the window and
// returns what page.js calls: markRotatable(box, fig) as a 3D figure is
// drawn, viewsLua(), rotating() (a figure is being dragged round, or
// turned by a held key).  host
// gives:
//   figures        div#cf-figures
//   el(tag, attrs, text)   an element
//   views()        the turned views (page.js's object, changed in place)
//   lastFigures()  the figures of the last reply shown
//   drag()         the handle being dragged, or null
//   request()      run the script again with the values and views
//   moves          the names of the pointer's move events to listen to
//   hold(), release()   keep the figures' layout while a move goes on,
//                  and let it go
function CurvefigRotate(host) {
  'use strict';
  var figures = host.figures, el = host.el, request = host.request;
  var hold = host.hold, release = host.release;

  var DEG_PER_PX = 0.4;  // a drag across a figure turns it about half round
  var KEY_DEG = 5;       // an arrow key; 15 with Shift
  var rot = null;        // { name, x, y, az, el }: a background dragged
  var lastDown = null;   // the last press on a background, for double clicks
  var held = null;       // the arrow key held down, repeating, on a figure

  function figureNamed(name) {
    return (host.lastFigures() || []).find(function (f) {
      return f.name === name;
    });
  }

  // "@view:NAME" must fit a parameter's name (63 bytes).
  function turnable(fig) {
    return fig && fig.view && new TextEncoder().encode('@view:' +
                                                       fig.name).length < 64;
  }

  function viewOf(fig) {
    return host.views()[fig.name] || fig.view;
  }

  // The figure turned to azimuth az and elevation el (degrees): the
  // elevation kept in [-90, 90], the azimuth in [-180, 180), both to a
  // tenth of a degree.
  function turn(name, az, elev) {
    az = ((az + 180) % 360 + 360) % 360 - 180;
    elev = Math.min(90, Math.max(-90, elev));
    var v = [Math.round(az * 10) / 10, Math.round(elev * 10) / 10];
    var views = host.views(), old = views[name];
    if (old && old[0] === v[0] && old[1] === v[1]) return;
    views[name] = v;
    request();
  }

  function resetView(name) {
    var views = host.views();
    if (!(name in views)) return;
    delete views[name];
    request();
  }

  function markRotatable(box, fig) {
    box.classList.add('cf-3d');
    if (rot && rot.name === fig.name) box.classList.add('cf-rotating');
    box.setAttribute('data-view', JSON.stringify(fig.view));
    if (!turnable(fig)) return;
    box.setAttribute('tabindex', '0');
    box.setAttribute('title', 'Drag to turn the figure; double click: ' +
                     'the script\'s view');
    if (host.views()[fig.name]) {
      var b = el('button', { class: 'cf-view-reset', type: 'button',
                             title: 'Back to the script\'s view' },
                 'Reset view');
      b.addEventListener('click', function () {
        box.focus({ preventScroll: true });   // the button goes with the turn
        resetView(fig.name);
      });
      box.appendChild(b);
    }
  }

  function figureBox(target) {
    var box = target && target.closest ? target.closest('.cf-figure') : null;
    return box && box.classList.contains('cf-3d') ? box : null;
  }

  // A drag that starts on a 3D figure's background (not on a handle, which
  // takes its own pointerdown first, nor on a button) turns the figure.
  function rotateStart(ev) {
    var t = ev.target, box = figureBox(t), fig;
    if (host.drag() || rot || !box ||
        (ev.pointerType === 'mouse' && ev.button !== 0) ||
        t.closest('button') || (t.classList &&
                                t.classList.contains('cf-handle')))
      return;
    fig = figureNamed(box.id.slice(10));
    if (!turnable(fig)) return;
    ev.preventDefault();      // (which keeps the click from focusing it,
    box.focus({ preventScroll: true });   // and the browser's dblclick)
    var now = performance.now(), last = lastDown;
    lastDown = { name: fig.name, t: now, x: ev.clientX, y: ev.clientY };
    if (last && last.name === fig.name && now - last.t < 500 &&
        Math.hypot(ev.clientX - last.x, ev.clientY - last.y) < 8) {
      lastDown = null;        // a double click: the script's view
      resetView(fig.name);
      return;
    }
    figures.setPointerCapture(ev.pointerId);
    hold();                   // it turns in place; released, it is fitted
    var v = viewOf(fig);
    rot = { name: fig.name, x: ev.clientX, y: ev.clientY, az: v[0],
            el: v[1] };
    box.classList.add('cf-rotating');
  }

  function rotateMove(ev) {
    if (!rot) return;
    // dragged right the front turns right; dragged down, seen from higher
    turn(rot.name, rot.az - (ev.clientX - rot.x) * DEG_PER_PX,
         rot.el + (ev.clientY - rot.y) * DEG_PER_PX);
  }

  function rotateEnd() {
    if (!rot) return;
    document.querySelectorAll('.cf-rotating').forEach(function (b) {
      b.classList.remove('cf-rotating');
    });
    rot = null;
    release();
  }

  function rotateKey(ev) {
    var box = ev.target;
    if (!box.classList || !box.classList.contains('cf-figure') ||
        !box.classList.contains('cf-3d') || host.drag() || rot)
      return;     // a handle with the focus takes its keys itself
    var fig = figureNamed(box.id.slice(10)), k = ev.shiftKey ? 3 : 1;
    var d = { ArrowLeft: [k, 0], ArrowRight: [-k, 0], ArrowUp: [0, -k],
              ArrowDown: [0, k] }[ev.key];
    if (!d || !turnable(fig)) return;
    ev.preventDefault();
    // a key held down repeats: its turns are a move (drafts, the layout
    // held) until it goes up; a single press is an exact run at once
    if (ev.repeat && held === null) {
      held = ev.key;
      hold();
    }
    var v = viewOf(fig);
    turn(fig.name, v[0] + d[0] * KEY_DEG, v[1] + d[1] * KEY_DEG);
  }

  // The held key went up (or the window lost the focus, where its going
  // up is not seen; not the figure's focusout: a redraw replaces the
  // figure's box and focuses the new one): the exact run.
  function keyEnd(ev) {
    if (held === null || (ev.type === 'keyup' && ev.key !== held)) return;
    held = null;
    release();
  }

  figures.addEventListener('pointerdown', rotateStart);
  host.moves.forEach(function (t) {    // (turn() runs nothing twice)
    window.addEventListener(t, rotateMove);
  });
  window.addEventListener('pointerup', rotateEnd);
  window.addEventListener('pointercancel', rotateEnd);
  figures.addEventListener('keydown', rotateKey);
  figures.addEventListener('keyup', keyEnd);
  window.addEventListener('blur', keyEnd);   // the key goes up elsewhere

  // The rotated views as Lua comments under the values, to paste into
  // figure{ view = ... }.
  function viewsLua() {
    var views = host.views();
    return Object.keys(views).map(function (name) {
      return '-- ' + name + ': view = { ' + views[name].join(', ') + ' }\n';
    }).join('');
  }

  return { markRotatable: markRotatable, viewsLua: viewsLua,
           rotating: function () {
             return rot !== null || held !== null;
           } };
}
