// The WebAssembly module (render/web) against the native core: the same
// cases (Example 5.4.1's rational Bézier curve with unequal weights, the
// cubic B-spline of Marková's sample, knot insertion in it) asked of both,
// answers equal to the last bit; then scripts run inside the module:
// Lua's errors (WebAssembly exceptions caught by lua_pcall) with their
// lines, the module usable after each, the sandbox's libraries only, a
// slider's value reaching the script.
//   node core.mjs MODULE.wasm CORE-VALUES-EXECUTABLE LOADER.js
import { execFileSync } from 'child_process';
import { readFileSync } from 'fs';
import { createRequire } from 'module';

const [wasmPath, nativeExe, loaderPath] = process.argv.slice(2);
const curvefigWasm = createRequire(import.meta.url)(loaderPath);
const w = await curvefigWasm(readFileSync(wasmPath));
const e = w.exports;
let failures = 0;
function check(ok, what) {
  if (!ok) {
    failures++;
    console.error('FAIL: ' + what);
  }
}

const P = [[-10, 0], [-3, 7], [1.1, -7.2], [4.3, -8.5], [-16, 12],
           [-2.1, 1.7], [-8.2, 1.4], [12.2, 5.4]];
const weights = [1, 5, 1, 30, 1, 1, 100, 2];
const ts = Array.from({ length: 21 }, (_, k) => k / 20).concat([0.3, 0.7071]);
const U = [0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1];
const Q = [[3, 1], [3.75, 2], [5, 3], [4, 4], [3, 3], [2, 4], [1, 3],
           [2.25, 2]];
const flat = (a) => a.flat();
const list = (a) => [a.length].concat(a).join(' ');

// the wasm side: each case through the exported C API
function wasmBezier(points, ws, t) {
  const pp = w.doubles(flat(points)), wp = w.doubles(ws);
  const outp = e.malloc(4), res = e.malloc(16);
  check(e.cf_bezier_create(2, ws.length - 1, pp, wp, outp, 0) === 0,
        'cf_bezier_create in wasm');
  const c = new Uint32Array(e.memory.buffer, outp, 1)[0];
  const rows = t.map((x) => {
    check(e.cf_bezier_eval(c, x, res) === 0, 'cf_bezier_eval ' + x);
    return Array.from(w.f64().subarray(res / 8, res / 8 + 2));
  });
  e.cf_bezier_destroy(c);
  [pp, wp, outp, res].forEach((p) => e.free(p));
  return rows;
}
function wasmBspline(deg, knots, points, f) {
  const kp = w.doubles(knots), pp = w.doubles(flat(points));
  const outp = e.malloc(4);
  check(e.cf_bspline_create(2, deg, kp, knots.length, pp, points.length, 0,
                            outp, 0) === 0, 'cf_bspline_create in wasm');
  const c = new Uint32Array(e.memory.buffer, outp, 1)[0];
  const rows = f(c);
  e.cf_bspline_destroy(c);
  [kp, pp, outp].forEach((p) => e.free(p));
  return rows;
}
function wasmEval(c, us) {
  const res = e.malloc(16);
  const rows = us.map((u) => {
    check(e.cf_bspline_eval(c, u, res) === 0, 'cf_bspline_eval ' + u);
    return Array.from(w.f64().subarray(res / 8, res / 8 + 2));
  });
  e.free(res);
  return rows;
}
function wasmInsert(c, u) {
  const outp = e.malloc(4);
  check(e.cf_bspline_insert_knot(c, u, 1, outp, 0, 0) === 0,
        'cf_bspline_insert_knot ' + u);
  const d = new Uint32Array(e.memory.buffer, outp, 1)[0];
  const n = e.cf_bspline_count(d), q = e.malloc(16 * n);
  e.cf_bspline_get_points(d, q);
  const row = Array.from(w.f64().subarray(q / 8, q / 8 + 2 * n));
  e.cf_bspline_destroy(d);
  e.free(q);
  e.free(outp);
  return [row];
}

const cases = [
  ['bezier ' + list(flat(P)) + ' ' + list(weights) + ' ' + list(ts),
   () => wasmBezier(P, weights, ts)],
  ['bezier ' + list(flat(P)) + ' ' + list(P.map(() => 1)) + ' ' + list(ts),
   () => wasmBezier(P, P.map(() => 1), ts)],
  ['bspline 3 ' + list(U) + ' ' + list(flat(Q)) + ' ' + list(ts),
   () => wasmBspline(3, U, Q, (c) => wasmEval(c, ts))],
  ...[0.5, 0.33, 0.25].map((u) => [
    'insert 3 ' + list(U) + ' ' + list(flat(Q)) + ' ' + u,
    () => wasmBspline(3, U, Q, (c) => wasmInsert(c, u))]),
];
const native = execFileSync(nativeExe, {
  input: cases.map((c) => c[0]).join('\n') + '\n',
}).toString().trim().split('\n').map((l) => l.split(' ').map(Number));
let row = 0, compared = 0;
for (const [text, run] of cases) {
  for (const got of run()) {
    const want = native[row++] || [];
    check(got.length === want.length && got.length > 0,
          text.split(' ')[0] + ': ' + got.length + ' numbers, native '
          + want.length);
    got.forEach((v, i) => {
      compared++;
      check(Object.is(v, want[i]), text.split(' ')[0] + ' row ' + row
            + ': wasm ' + v + ', native ' + want[i]);
    });
  }
}
check(row === native.length, 'rows: ' + row + ' of ' + native.length);
console.log(compared + ' numbers compared with the native core');

// Lua in the module, through the page's entry (cf_interactive_run)
function run(src, values) {
  const c = w.cstring(src), n = w.cstring('t.lua');
  const v = w.cstring(values || '');
  const st = e.cf_wasm_run(c, n, v);
  [c, n, v].forEach((p) => e.free(p));
  check(st === 0, 'cf_wasm_run status ' + st);
  return JSON.parse(w.string(e.cf_wasm_json()));
}
const luaCases = [
  ['error("boom")', 1, 'boom'],
  ['local t = nil\nreturn t.y', 2, 'attempt to index a nil value'],
  ['return (', 1, 'unexpected symbol near <eof>'],
  ['local function f(n) return f(n + 1) + 1 end\nf(1)', 1, 'stack overflow'],
  ['local x = 1\nlocal f = io.open', 2, "'io' is not available"],
  ['assert(string.format("%.3f", math.pi) == "3.142")\n'
   + 'assert(utf8.len("ωß") == 2 and table.concat({1, 2}) == "12")\n'
   + 'error("libraries ok")', 3, 'libraries ok'],
];
for (const [src, line, want] of luaCases) {
  const r = run(src);
  check(r.error !== null && r.error.message.includes(want),
        'lua error of ' + JSON.stringify(src) + ': ' + JSON.stringify(r.error));
  check(r.error !== null && r.error.line === line,
        'lua error line of ' + JSON.stringify(src) + ': '
        + JSON.stringify(r.error));
}
// a slider's value reaches the script; many errors in a row leave the
// module working, its memory bounded (the exceptions unwind, lua_close
// frees the states)
const slider = 'local t = slider{ name = "t", min = 0, max = 1, default = 0.25 }\n'
  + 'error("t=" .. t)';
check(run(slider).error.message.includes('t=0.25'), 'slider default');
check(run(slider, '{"t": 0.5}').error.message.includes('t=0.5'),
      'slider value');
const before = e.memory.buffer.byteLength;
for (let i = 0; i < 1000; i++)
  run('local t = {} for i = 1, 100 do t[i] = {i} end error("e" .. #t)');
check(run(slider, '{"t": 0.75}').error.message.includes('t=0.75'),
      'after 1000 errors');
check(e.memory.buffer.byteLength - before < (4 << 20),
      'memory grew by ' + (e.memory.buffer.byteLength - before));
console.log(luaCases.length + 1003 + ' Lua runs');
process.exit(failures ? 1 : 0);
