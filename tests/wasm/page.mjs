// The course pages without a browser: every shipped interactive example
// written with -f html, its engine (the page's own script, CurvefigPage
// left out) run by node at the defaults; the figure's SVG, drawn by the
// WebAssembly module (label places and ink measured by the same code as
// in the tool, render/backends/measure.c) with the SVG writer, must
// look as the native SVG of `curvefig render -f svg` does, compared by
// `curvefig compare` (the pixel suite's comparator, 144 dpi) with no bad
// pixel: the same layout, labels in the same places, the same glyphs.
// The same at two slider values the defaults never showed, against
// `curvefig live --once VALUES`: its labels are composed in the page from
// the characters' glyph data (and a 3D figure turned by 40 and 15
// degrees, against `live --once` with that "@view:NAME").  Then twenty
// runs with a slider moving: the time of one run (median, the page's
// redraw after an input), printed; ten more turning a 3D figure.  Last,
// tests/wasm/kerning.lua, whose text has kerned pairs (AV, To, ...): its
// glyph data must carry their kerns (K lines), and its page composed at
// another value must match the native SVG with no bad pixel (without the
// kerns, a label 11 pt wide is off by a pixel or more at 144 dpi).
//   node page.mjs CURVEFIG SOURCE_DIR
import { execFileSync, spawnSync } from 'child_process';
import { mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync }
  from 'fs';
import { tmpdir } from 'os';
import { join } from 'path';
import './node-worker.mjs';

const [tool, src] = process.argv.slice(2);
const dir = mkdtempSync(join(tmpdir(), 'cf-page-'));
let failures = 0;

// the engine of a page: its script, the call of CurvefigPage at its end
// made to hand over the engine instead
function engineOf(html) {
  const js = html.slice(html.indexOf('<script>') + 8,
                        html.lastIndexOf('</script>'))
    .replace(/CurvefigPage\(document\.getElementById\('curvefig'\), /,
             'catchEngine(');
  let engine = null;
  new Function('catchEngine', js)((e) => { engine = e; });
  return engine;
}

const examples = readdirSync(join(src, 'figures', 'interactive'))
  .filter((f) => f.endsWith('.lua')).sort();
for (const file of examples) {
  const name = file.slice(0, -4), script = join(src, 'figures',
                                                  'interactive', file);
  execFileSync(tool, ['render', script, '-f', 'html,svg', '-o', dir]);
  const engine = engineOf(readFileSync(join(dir, name + '.html'), 'utf8'));
  const reply = await engine.run({});
  if (reply.error !== null || reply.figures.length !== 1) {
    console.error('FAIL ' + name + ': ' + JSON.stringify(reply.error));
    failures++;
    continue;
  }
  writeFileSync(join(dir, name + '-wasm.svg'), reply.figures[0].svg);
  const cmp = spawnSync(tool, ['compare', join(dir, name + '-wasm.svg'),
                               join(dir, name + '.svg'), '--max-bad', '0']);
  const verdict = (cmp.stdout.toString() + cmp.stderr.toString()).trim()
    .split('\n').pop();
  console.log((cmp.status === 0 ? 'ok   ' : 'FAIL ') + name + ': ' + verdict);
  if (cmp.status !== 0)
    failures++;
  const slider = reply.params.find((p) => p.kind === 'slider');
  // values the defaults never showed: labels composed in the page, and
  // placed automatically in the page as in the tool (rational-5.4.1's
  // numbers: no place is pinned), so no pixel may differ; a 3D figure
  // also turned (the page's "@view:NAME"), its hidden lines computed
  // again by the module
  const view = reply.figures[0].view;
  const cases = [0.37, 0.81].map((at) => ({
    [slider.name]: +(slider.min + at * (slider.max - slider.min)).toFixed(2),
  }));
  if (view)
    cases.push({ ['@view:' + name]: [[view[0] + 40, view[1] + 15]] });
  for (const moved of cases) {
    const there = await engine.run(moved);
    const native = JSON.parse(execFileSync(tool, ['live', script, '--once',
                                                   JSON.stringify(moved)]));
    const nfig = native.figures.find((f) => f.name === name);
    writeFileSync(join(dir, name + '-moved-wasm.svg'), there.figures[0].svg);
    writeFileSync(join(dir, name + '-moved.svg'), nfig.svg);
    const cmp2 = spawnSync(tool, ['compare',
                                  join(dir, name + '-moved-wasm.svg'),
                                  join(dir, name + '-moved.svg'),
                                  '--max-bad', '0']);
    const verdict2 = (cmp2.stdout.toString() + cmp2.stderr.toString())
      .trim().split('\n').pop();
    console.log((cmp2.status === 0 ? 'ok   ' : 'FAIL ') + name + ' at '
                + JSON.stringify(moved) + ': ' + verdict2);
    if (cmp2.status !== 0)
      failures++;
  }
  const times = [];
  for (let k = 0; k < 20; k++) {
    const v = {};
    v[slider.name] = slider.min + (slider.max - slider.min) * (k + 0.5) / 20;
    const t0 = performance.now();
    const r = await engine.run(v);
    times.push(performance.now() - t0);
    if (r.error !== null) {
      console.error('FAIL ' + name + ' at ' + JSON.stringify(v) + ': '
                    + JSON.stringify(r.error));
      failures++;
      break;
    }
  }
  times.sort((a, b) => a - b);
  console.log('     ' + name + ': a run in the page ' +
              times[10].toFixed(0) + ' ms median, ' +
              times[18].toFixed(0) + ' ms 95th percentile (' +
              slider.name + ' over its range)');
  if (view) {
    const turns = [];
    for (let k = 0; k < 10; k++) {
      const t0 = performance.now();
      await engine.run({ ['@view:' + name]: [[view[0] + 9 * k, view[1]]] });
      turns.push(performance.now() - t0);
    }
    turns.sort((a, b) => a - b);
    console.log('     ' + name + ': a run in the page turned ' +
                turns[5].toFixed(0) + ' ms median, ' + turns[9].toFixed(0) +
                ' ms slowest (azimuth in steps of 9 degrees)');
  }
}
{
  const script = join(src, 'tests', 'wasm', 'kerning.lua');
  execFileSync(tool, ['render', script, '-f', 'html,svg', '-o', dir]);
  const html = readFileSync(join(dir, 'kerning.html'), 'utf8');
  // A V in the text's description: moved together (a negative kern)
  const av = /\\nK (\d+) 65 86 (-[0-9.e-]+)/.exec(html);
  console.log((av ? 'ok   ' : 'FAIL ') + 'kerning: the glyph data kern A V'
              + (av ? ' by ' + av[2] + ' per bp' : ''));
  if (!av)
    failures++;
  const engine = engineOf(html);
  for (const v of [{}, { t: 0.37 }, { t: 0.91 }]) {
    const r = await engine.run(v);
    const native = JSON.parse(execFileSync(tool, ['live', script, '--once',
                                                   JSON.stringify(v)]));
    writeFileSync(join(dir, 'kerning-wasm.svg'), r.figures[0].svg);
    writeFileSync(join(dir, 'kerning-native.svg'), native.figures[0].svg);
    const c = spawnSync(tool, ['compare', join(dir, 'kerning-wasm.svg'),
                               join(dir, 'kerning-native.svg'),
                               '--max-bad', '0']);
    const verdict = (c.stdout.toString() + c.stderr.toString()).trim()
      .split('\n').pop();
    console.log((c.status === 0 ? 'ok   ' : 'FAIL ') + 'kerning at '
                + JSON.stringify(v) + ': ' + verdict);
    if (c.status !== 0)
      failures++;
  }
}
rmSync(dir, { recursive: true });
process.exit(failures ? 1 : 0);
