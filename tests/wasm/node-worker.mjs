// The page runs its module in a Web Worker, which node has not: this one
// runs the worker's source (a blob: URL of the page) in this thread, its
// messages passed on asynchronously as a browser passes them.  Imported
// for its effect (globalThis.Worker) by page.mjs and hidden-bytes.mjs.
import { resolveObjectURL } from 'buffer';

globalThis.Worker = class {
  constructor(url) {
    this.onmessage = null;
    this.dead = false;
    const scope = { onmessage: null };
    const post = (m) => setImmediate(() => {
      if (!this.dead && this.onmessage) this.onmessage({ data: m });
    });
    this.scope = resolveObjectURL(url).text().then((code) => {
      new Function('self', 'postMessage', code)(scope, post);
      return scope;
    });
  }
  postMessage(m) {
    this.scope.then((scope) => setImmediate(() => scope.onmessage({ data: m })));
  }
  terminate() {
    this.dead = true;
  }
};
