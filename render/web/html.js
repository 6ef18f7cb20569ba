// The engine of a course page (curvefig render -f html): the figure
// script runs in the page, in curvefig's WebAssembly module, inside a Web
// Worker (worker.js, with wasm.js's loader), with the glyph data measured
// when the page was written.  A run that takes longer than the page's
// time limit is stopped: the worker is terminated, the reply is the
// error, and the next run starts a fresh worker; the tab stays
// responsive throughout.
// data: { wasm: base64 of the module, worker: the worker's source,
// script: the script's text, name: its file name, glyphs: the glyph data,
// figure: the figure this page shows, timeout: the time limit of a run in
// seconds, memory: MiB, instructions: the sandbox's limits (0: its
// defaults) }.  run(values) answers as the live server does, with the
// figures but this one left out, and the run's time in the module (ms).
function CurvefigWasmEngine(data) {
  'use strict';
  var bin = atob(data.wasm), bytes = new Uint8Array(bin.length);
  for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  var module = WebAssembly.compile(bytes);   // once, for every worker
  var source = URL.createObjectURL(new Blob([data.worker],
                                            { type: 'text/javascript' }));
  var worker = null, ready = null, next = 1, waiting = {};

  function start() {
    var w = new Worker(source);
    worker = w;
    waiting = {};
    w.onmessage = function (ev) {
      var f = waiting[ev.data.id];
      if (f) f(ev.data);
    };
    ready = module.then(function (m) {
      return ask(w, { init: { module: m, glyphs: data.glyphs,
                              script: data.script, name: data.name,
                              memory: data.memory || 0,
                              instructions: data.instructions || 0 } });
    });
  }

  // Send msg to the worker; a Promise of its answer.
  function ask(w, msg, started) {
    return new Promise(function (resolve, reject) {
      var id = next++;
      msg.id = id;
      waiting[id] = function (m) {
        if (m.started) {
          if (started) started();
          return;
        }
        delete waiting[id];
        if (m.error !== undefined) reject(new Error(m.error));
        else resolve(m);
      };
      w.postMessage(msg);
    });
  }

  function stopped() {
    return { params: [], figures: [], lua: '',
             error: { line: 0, message: data.name + ': the script exceeded '
                      + 'the time limit of ' + data.timeout + ' s (the '
                      + 'page stopped it)' } };
  }

  this.run = function (values) {
    if (worker === null) start();
    var w = worker;
    return ready.then(function () {
      return new Promise(function (resolve, reject) {
        var timer = null;
        ask(w, { values: values || {} }, function () {
          timer = setTimeout(function () {
            w.terminate();
            if (worker === w) worker = null;
            resolve(stopped());
          }, data.timeout * 1000);
        }).then(function (m) {
          clearTimeout(timer);
          var reply = JSON.parse(m.json);
          reply.ms = m.ms;
          if (reply.figures)
            reply.figures = reply.figures.filter(function (f) {
              return f.name === data.figure;
            });
          resolve(reply);
        }, function (e) {
          clearTimeout(timer);
          reject(e);
        });
      });
    });
  };
}
