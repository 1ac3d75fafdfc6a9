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

export async function check(name, body) {
  try {
    await body();
    ++passed;
    console.log(`ok - ${name}`);
  } catch (error) {
    ++failed;
    console.log(`not ok - ${name}\n  ${String(error.stack || error).split('\n').join('\n  ')}`);
  }
}

export function assert(condition, message) {
  if (!condition) throw new Error(message);
}

export function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed === 0 ? 0 : 1);
}
