/*
 * The loader of curvefig's WebAssembly module (render/web): no
 * emscripten glue.  The module is standalone (WASI); what it imports is
 * provided here: the clock (Lua seeds its hashes with it), writes to
 * stdout/stderr (to the console), exit (an exception), and nothing else:
 * files and descriptors answer ENOSYS.  Lua's errors are WebAssembly
 * exceptions, caught inside the module, so no invoke_* trampolines.
 *
 * curvefigWasm(bytes) -> Promise of an object with
 *   exports        the module's functions (cf_bezier_eval, ...)
 *   memory()       the current memory as bytes (it may grow)
 *   f64()          the same as doubles
 *   cstring(str)   a NUL-terminated UTF-8 copy in the module's heap
 *                  (free it with exports.free)
 *   string(ptr)    the UTF-8 string at ptr
 *   doubles(arr)   a copy of numbers in the heap (exports.free it)
 */
(function (root) {
  'use strict';
  const ENOSYS = 52;

  function curvefigWasm(bytes) {
    let inst = null;
    const mem = () => new Uint8Array(inst.exports.memory.buffer);
    const view = () => new DataView(inst.exports.memory.buffer);
    const decoder = new TextDecoder();
    const out = { 1: '', 2: '' };
    const wasi = {
      clock_time_get(id, precision, ptr) {
        const ns = BigInt(Math.round(Date.now() * 1e6));
        view().setBigUint64(ptr, ns, true);
        return 0;
      },
      fd_write(fd, iovs, n, written) {
        const v = view();
        let total = 0;
        for (let i = 0; i < n; i++) {
          const p = v.getUint32(iovs + 8 * i, true);
          const len = v.getUint32(iovs + 8 * i + 4, true);
          const text = decoder.decode(mem().subarray(p, p + len));
          total += len;
          if (fd === 1 || fd === 2) {
            out[fd] += text;
            const lines = out[fd].split('\n');
            out[fd] = lines.pop();
            for (const line of lines)
              (fd === 2 ? console.error : console.log)(line);
          }
        }
        v.setUint32(written, total, true);
        return 0;
      },
      proc_exit(code) {
        throw new Error('curvefig wasm: exit(' + code + ')');
      },
      fd_read() { return ENOSYS; },
      fd_close() { return ENOSYS; },
      fd_seek() { return ENOSYS; },
    };
    const env = {
      emscripten_notify_memory_growth() {},
      __syscall_dup3() { return -ENOSYS; },
    };
    return WebAssembly.instantiate(bytes, {
      wasi_snapshot_preview1: wasi, env: env,
    }).then((r) => {
      inst = r.instance;
      const e = inst.exports;
      if (e._initialize)
        e._initialize();
      return {
        exports: e,
        memory: mem,
        f64: () => new Float64Array(e.memory.buffer),
        cstring(s) {
          const b = new TextEncoder().encode(s);
          const p = e.malloc(b.length + 1);
          if (p === 0)
            throw new Error('curvefig wasm: out of memory');
          mem().set(b, p);
          mem()[p + b.length] = 0;
          return p;
        },
        string(p) {
          const m = mem();
          let q = p;
          while (m[q] !== 0)
            q++;
          return decoder.decode(m.subarray(p, q));
        },
        doubles(a) {
          const p = e.malloc(8 * Math.max(a.length, 1));
          if (p === 0)
            throw new Error('curvefig wasm: out of memory');
          new Float64Array(e.memory.buffer, p, a.length).set(a);
          return p;
        },
      };
    });
  }

  if (typeof module !== 'undefined' && module.exports)
    module.exports = curvefigWasm;
  else
    root.curvefigWasm = curvefigWasm;
})(this);
