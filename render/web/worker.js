// The Web Worker of a course page (html.js starts it, from this text and
// wasm.js's): it holds curvefig's WebAssembly module, so that a script
// that runs too long blocks this worker, never the page, and the page can
// end it (terminate) at its time limit and start a fresh one.
//   page -> worker  { id, init: { module, glyphs, script, name,
//                     memory, instructions } }   then { id, values }
//   worker -> page  { id, ok: true } or { id, error } for the init;
//                   { id, started: true }, then { id, json, ms } (ms: the
//                   run's time in the module) or { id, error } for a run
(function () {
  'use strict';
  var w = null, page = null;

  function put(text) {
    var b = new TextEncoder().encode(text);
    var p = w.exports.malloc(b.length + 1);
    if (p === 0) throw new Error('curvefig: out of memory in the page');
    w.memory().set(b, p);
    w.memory()[p + b.length] = 0;
    return { p: p, n: b.length };
  }

  function init(id, data) {
    page = data;
    curvefigWasm(data.module).then(function (mod) {
      w = mod;
      var g = put(data.glyphs), r = w.exports.cf_wasm_glyphs(g.p, g.n);
      w.exports.free(g.p);
      if (r !== 0)
        throw new Error('curvefig: the glyph data of this page is damaged '
                        + '(line ' + r + ')');
      postMessage({ id: id, ok: true });
    }).catch(function (e) {
      postMessage({ id: id, error: String(e && e.message || e) });
    });
  }

  function run(id, values) {
    postMessage({ id: id, started: true });
    try {
      var code = put(page.script), name = put(page.name);
      var vals = put(JSON.stringify(values || {}));
      var t0 = performance.now();
      var st = w.exports.cf_wasm_run(code.p, name.p, vals.p,
                                     page.memory || 0,
                                     page.instructions || 0);
      var ms = performance.now() - t0;
      [code, name, vals].forEach(function (x) { w.exports.free(x.p); });
      if (st !== 0) throw new Error('curvefig: out of memory in the page');
      postMessage({ id: id, json: w.string(w.exports.cf_wasm_json()),
                   ms: ms });
    } catch (e) {
      postMessage({ id: id, error: String(e && e.message || e) });
    }
  }

  self.onmessage = function (ev) {
    var m = ev.data;
    if (m.init) init(m.id, m.init);
    else run(m.id, m.values);
  };
})();
