// Bundles the viewer (src/main.js with three.js) into one script, dist/viewer.bundle.js, that
// `datomsim view` inlines into its HTML pages. Usage: node build.mjs [--outfile PATH] [--dev]
import { build } from 'esbuild';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
let outfile = resolve(here, 'dist/viewer.bundle.js');
let minify = true;
for (let k = 0; k < args.length; ++k) {
  if (args[k] === '--outfile' && k + 1 < args.length) outfile = resolve(args[++k]);
  else if (args[k] === '--dev') minify = false;
  else {
    console.error(`build.mjs: unknown argument ${args[k]}; usage: node build.mjs [--outfile PATH] [--dev]`);
    process.exit(2);
  }
}

await build({
  entryPoints: [resolve(here, 'src/main.js')],
  bundle: true,
  format: 'iife',
  platform: 'browser',
  target: ['es2020'],
  minify,
  legalComments: 'eof',
  // The bundle is inlined into a <script> element: esbuild escapes "</script" in strings.
  supported: { 'inline-script': true },
  outfile,
  logLevel: 'warning',
});
console.log(`viewer bundle: ${outfile}`);
