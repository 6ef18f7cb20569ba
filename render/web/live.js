// The engine of the live server's page (render/tool/live-server.c): a run
// is a POST of the values to ./run; watch() long-polls ./wait and calls
// back when the script file was saved.
function CurvefigLiveEngine() {
  'use strict';
  var base = location.pathname.replace(/[^/]*$/, '');
  this.run = function (values) {
    return fetch(base + 'run', {
      method: 'POST',
      headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify(values),
    }).then(function (r) {
      if (r.headers.get('Content-Type') !== 'application/json') {
        return r.text().then(function (t) {
          throw new Error('HTTP ' + r.status + ': ' + t);
        });
      }
      return r.json();
    });
  };
  this.watch = function (changed) {
    var version = null;
    function poll() {
      fetch(base + 'wait' + (version === null ? '' :
                             '?v=' + encodeURIComponent(version)))
        .then(function (r) { return r.json(); })
        .then(function (j) {
          if (version !== null && j.version !== version) changed();
          version = j.version;
          poll();
        }, function () { setTimeout(poll, 1000); });
    }
    poll();
  };
}
