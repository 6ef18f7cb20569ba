// The engine of a course page (curvefig render -f html): the figure
// script runs in the page, in curvefig's WebAssembly module, inside a Web
// Worker (worker.js, with wasm.js's loader), with the glyph data measured
// when the page was written.  A run that takes longer than the page's
// time limit is stopped: the worker is terminated, the reply is the
// error, and the next run on that lane starts a fresh worker; the tab
// stays responsive throughout.
// Two lanes (this.lanes): two workers, instances of the one compiled
// module, one for the exact runs and one for the drafts ("@draft": 1 in
// the values), so that the page can start an exact run while a draft is
// still under way (page.js, request()) instead of waiting for the draft,
// and the exact runs keep one instance to themselves (as warm as a page
// without drafts).  The exact lane starts with the first run, the draft
// lane with the first draft or earlier through warm() (page.js calls it
// when the page is idle after an exact run slow enough for drafts, and
// when a drag that draws drafts begins, so that its instance and glyph
// data are ready by the drag's first move).  A page whose figure's runs
// are quick has one instance; one that draws drafts, two (each with its
// own memory, up to data.memory MiB).
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
  var next = 1;
  // a lane: { worker, ready: Promise of its init, waiting: id -> f };
  // lanes[0] the exact runs', lanes[1] the drafts'.
  var lanes = [];
  this.lanes = 2;

  function start(lane) {
    var w = new Worker(source);
    lane.worker = w;
    lane.waiting = {};
    w.onmessage = function (ev) {
      var f = lane.waiting[ev.data.id];
      if (f) f(ev.data);
    };
    lane.ready = module.then(function (m) {
      return ask(lane, { init: { module: m, glyphs: data.glyphs,
                                 script: data.script, name: data.name,
                                 memory: data.memory || 0,
                                 instructions: data.instructions || 0 } });
    });
  }

  function newLane() {
    var lane = { worker: null, ready: null, waiting: {} };
    lanes.push(lane);
    start(lane);
    return lane;
  }

  // Send msg to the lane's worker; a Promise of its answer.
  function ask(lane, msg, started) {
    return new Promise(function (resolve, reject) {
      var id = next++;
      msg.id = id;
      lane.waiting[id] = function (m) {
        if (m.started) {
          if (started) started();
          return;
        }
        delete lane.waiting[id];
        if (m.error !== undefined) reject(new Error(m.error));
        else resolve(m);
      };
      lane.worker.postMessage(msg);
    });
  }

  function stopped() {
    return { params: [], figures: [], lua: '',
             error: { line: 0, message: data.name + ': the script exceeded '
                      + 'the time limit of ' + data.timeout + ' s (the '
                      + 'page stopped it)' } };
  }

  // The lane of a run: the exact lane (lanes[0]) or the draft lane.
  function laneOf(draft) {
    if (lanes.length === 0) newLane();
    if (draft && lanes.length < 2) newLane();
    return lanes[draft ? 1 : 0];
  }

  // The draft lane started now (if it is not yet), its init off the path
  // of the first draft.
  this.warm = function () {
    laneOf(true);
  };

  this.run = function (values) {
    var lane = laneOf(!!(values && values['@draft']));
    if (lane.worker === null) start(lane);
    var w = lane.worker;
    return lane.ready.then(function () {
      return new Promise(function (resolve, reject) {
        var timer = null;
        ask(lane, { values: values || {} }, function () {
          timer = setTimeout(function () {
            w.terminate();
            if (lane.worker === w) {
              // the runs queued behind it on this worker are lost with
              // it: they answer as stopped too
              var rest = lane.waiting;
              lane.worker = null;
              lane.waiting = {};
              Object.keys(rest).forEach(function (id) {
                rest[id]({ json: null, stopped: true });
              });
            }
            resolve(stopped());
          }, data.timeout * 1000);
        }).then(function (m) {
          clearTimeout(timer);
          if (m.stopped) return resolve(stopped());
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
