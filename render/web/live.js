// The engine of the live server's page (render/tool/live-server.c): a run
// is a POST of the values to ./run; watch() long-polls ./wait and calls
// back when the script file was saved; reload(values) reloads the page
// (the same address, so the same token) and keeps the values for it in
// sessionStorage, where saved() takes them back once.
function CurvefigLiveEngine() {
  'use strict';
  var base = location.pathname.replace(/[^/]*$/, '');
  var key = 'curvefig-values:' + base;
  this.saved = function () {
    var text = null, v = null;
    try {
      text = sessionStorage.getItem(key);
      sessionStorage.removeItem(key);
      v = text === null ? null : JSON.parse(text);
    } catch (e) {
      v = null;   // storage refused, or not JSON: the defaults
    }
    return v !== null && typeof v === 'object' && !Array.isArray(v) ? v : {};
  };
  this.reload = function (values) {
    try {
      sessionStorage.setItem(key, JSON.stringify(values));
    } catch (e) {
      // no storage: the reloaded page starts from the defaults
    }
    location.reload();
  };
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
