// The hidden lines of the course page's module, byte for byte: the 3D
// example figures/interactive/surface-patch.lua written with -f html, its
// engine (the page's own script) run by node at its defaults and at 48
// views and values (azimuth every 30 degrees, four elevations, u and v
// moved), exact runs; every path of the native drawing (`curvefig live
// --once` with the same values) must be in the module's drawing in the
// same place with the same bytes: the surface's lines, their hidden
// pieces and silhouette (computed by the module's own hidden-line core,
// compiled with wasm SIMD: render/web/meson.build) and the arrow.  The
// module draws its labels' glyphs as paths of their own, after the
// drawing's; the native SVG's glyphs are symbols in its <defs>, left out.
//   node hidden-bytes.mjs CURVEFIG SOURCE_DIR
import { execFileSync } from 'child_process';
import { mkdtempSync, readFileSync, rmSync } from 'fs';
import { tmpdir } from 'os';
import { join } from 'path';
import './node-worker.mjs';  // the page's Web Worker, in this thread

const [tool, src] = process.argv.slice(2);
const dir = mkdtempSync(join(tmpdir(), 'cf-hidden-bytes-'));
const script = join(src, 'figures', 'interactive', 'surface-patch.lua');
execFileSync(tool, ['render', script, '-f', 'html', '-o', dir]);
const html = readFileSync(join(dir, 'surface-patch.html'), 'utf8');
rmSync(dir, { recursive: true });
const js = html.slice(html.indexOf('<script>') + 8, html.lastIndexOf('</script>'))
  .replace(/CurvefigPage\(document\.getElementById\('curvefig'\), /,
           'catchEngine(');
let engine = null;
new Function('catchEngine', js)((e) => { engine = e; });

const paths = (svg) => svg.replace(/<defs>[\s\S]*?<\/defs>/g, '')
  .match(/<path[^>]*>/g) || [];
const cases = [{}];
for (let az = -180; az < 180; az += 30)
  for (const el of [-50, -10, 28, 60])
    cases.push({ '@view:surface-patch': [[az, el]],
                 u: +(((az + 180) % 97) / 97).toFixed(2),
                 v: +(((el + 90) % 41) / 41).toFixed(2) });
let failures = 0, dashed = 0;
for (const v of cases) {
  const r = await engine.run(v);
  const native = JSON.parse(execFileSync(tool, ['live', script, '--once',
                                                 JSON.stringify(v)]));
  if (r.error !== null || native.error !== null) {
    console.error('FAIL at ' + JSON.stringify(v) + ': ' +
                  JSON.stringify(r.error || native.error));
    failures++;
    continue;
  }
  const pw = paths(r.figures[0].svg), pn = paths(native.figures[0].svg);
  const at = pn.findIndex((p, i) => p !== pw[i]);
  // (not vacuous: the surface's lines and their dashed hidden pieces)
  if (pn.length < 4 || at >= 0) {
    console.error('FAIL at ' + JSON.stringify(v) + ': ' +
                  (at >= 0 ? 'path ' + at + ' differs:\n  module ' +
                   String(pw[at]).slice(0, 200) + '\n  native ' +
                   pn[at].slice(0, 200)
                           : 'only ' + pn.length + ' paths'));
    failures++;
  }
  dashed += pn.some((p) => p.includes('stroke-dasharray'));
}
console.log((failures ? 'FAIL ' : 'ok   ') + cases.length + ' views and ' +
            'values: the module\'s drawing has the native paths, byte for ' +
            'byte (' + dashed + ' with hidden lines), ' + failures +
            ' differ');
process.exit(failures || dashed < cases.length / 4 ? 1 : 0);
