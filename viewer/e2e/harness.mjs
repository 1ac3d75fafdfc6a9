// What the end-to-end scripts share: their options, and checks that print one line each and end
// with "N passed, M failed" and the exit status.
import { mkdirSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const repository = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');

export function option(name, fallback) {
  const k = process.argv.indexOf(name);
  return k >= 0 && k + 1 < process.argv.length ? process.argv[k + 1] : fallback;
}

// --datomsim PATH (or DATOMSIM), --shots DIR (or DATOMSIM_SHOTS; made if missing) and
// --viewer-js FILE (or DATOMSIM_VIEWER_JS).
export function commonOptions() {
  const shots = resolve(option('--shots', process.env.DATOMSIM_SHOTS || '/tmp/viewer-shots'));
  mkdirSync(shots, { recursive: true });
  return {
    datomsim: option('--datomsim', process.env.DATOMSIM),
    shots,
    givenBundle: option('--viewer-js', process.env.DATOMSIM_VIEWER_JS),
  };
}

let passed = 0;
let failed = 0;

// Each line gives the check's time, to show where an end-to-end run's minutes go.
export async function check(name, body) {
  const started = performance.now();
  const took = () => `(${((performance.now() - started) / 1000).toFixed(1)} s)`;
  try {
    await body();
    ++passed;
    console.log(`ok - ${name} ${took()}`);
  } catch (error) {
    ++failed;
    console.log(`not ok - ${name} ${took()}\n  ${String(error.stack || error).split('\n').join('\n  ')}`);
  }
}

export function assert(condition, message) {
  if (!condition) throw new Error(message);
}

export function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed === 0 ? 0 : 1);
}
