// The engine of a course page (curvefig render -f html): the figure
// script runs in the page, in curvefig's WebAssembly module (wasm.js
// loads it), with the glyph data measured when the page was written.
// data: { wasm: base64 of the module, script: the script's text, name:
// its file name, glyphs: the glyph data, figure: the figure this page
// shows }.  run(values) answers as the live server does, with the figures
// but this one left out.
function CurvefigWasmEngine(data) {
  'use strict';
  var bin = atob(data.wasm), bytes = new Uint8Array(bin.length);
  for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  function put(w, text) {
    var b = new TextEncoder().encode(text);
    var p = w.exports.malloc(b.length + 1);
    if (p === 0) throw new Error('curvefig: out of memory in the page');
    w.memory().set(b, p);
    w.memory()[p + b.length] = 0;
    return { p: p, n: b.length };
  }
  var ready = curvefigWasm(bytes).then(function (w) {
    var g = put(w, data.glyphs), r = w.exports.cf_wasm_glyphs(g.p, g.n);
    w.exports.free(g.p);
    if (r !== 0)
      throw new Error('curvefig: the glyph data of this page is damaged '
                      + '(line ' + r + ')');
    return w;
  });
  this.run = function (values) {
    return ready.then(function (w) {
      var code = put(w, data.script), name = put(w, data.name);
      var vals = put(w, JSON.stringify(values || {}));
      var st = w.exports.cf_wasm_run(code.p, name.p, vals.p);
      [code, name, vals].forEach(function (x) { w.exports.free(x.p); });
      if (st !== 0) throw new Error('curvefig: out of memory in the page');
      var reply = JSON.parse(w.string(w.exports.cf_wasm_json()));
      if (reply.figures)
        reply.figures = reply.figures.filter(function (f) {
          return f.name === data.figure;
        });
      return reply;
    });
  };
}
