// The patch evaluator of the hidden-line core, bit for bit in the module
// and natively: tests/wasm/vpatch-bits.c compiled both ways (meson.build),
// the native program's output and the WebAssembly one's (run here through
// node's WASI) must be the same lines.
//   node vpatch-bits.mjs NATIVE_PROGRAM PROGRAM.wasm
import { execFileSync } from 'child_process';
import { mkdtempSync, readFileSync, rmSync, openSync, closeSync } from 'fs';
import { tmpdir } from 'os';
import { join } from 'path';
import { WASI } from 'wasi';

const [nativeProgram, wasmProgram] = process.argv.slice(2);
const native = execFileSync(nativeProgram, { maxBuffer: 64 << 20 })
  .toString().split('\n');
const dir = mkdtempSync(join(tmpdir(), 'cf-vpatch-bits-'));
const outPath = join(dir, 'out.txt');
const fd = openSync(outPath, 'w');
const wasi = new WASI({ version: 'preview1', args: [], env: {}, stdout: fd,
                        returnOnExit: true });
const mod = await WebAssembly.compile(readFileSync(wasmProgram));
const inst = await WebAssembly.instantiate(mod, wasi.getImportObject());
const status = wasi.start(inst);
closeSync(fd);
const wasm = readFileSync(outPath, 'utf8').split('\n');
rmSync(dir, { recursive: true });
const at = native.findIndex((l, i) => l !== wasm[i]);
const cases = native.filter((l) => l !== '').length;
if (status !== 0 || cases < 6000 || at >= 0 || wasm.length !== native.length) {
  console.error('FAIL: exit status ' + status + ', ' + cases + ' cases' +
                (at >= 0 ? ', first difference at case ' + at + ':\n  native ' +
                 native[at].slice(0, 160) + '\n  module ' +
                 String(wasm[at]).slice(0, 160) : ''));
  process.exit(1);
}
console.log('ok   ' + cases + ' evaluations of patches: the module and the ' +
            'native build give the same bits');
