// Tests the TextMate grammar (editors/vscode/syntaxes/sled.tmLanguage.json) with the tokenizer
// VS Code itself uses (vscode-textmate on the Oniguruma regex engine, from npm):
//   1. every .sled file of the repository tokenizes, and each file that sled parses without a
//      syntax error ends with the grammar back at its top level (every block closed) and has no
//      token scoped `invalid`;
//   2. the scopes of a few files match their snapshots in editors/tests/snapshots/ (rewrite them
//      with SLED_UPDATE_SNAPSHOTS=1 and review the diff).
//
//   node editors/tests/textmate_test.mjs --sled build/compiler/driver/sled
// Exit status: 0 all passed, 1 a failure, 77 skipped (the npm packages are not installed: run
// `npm ci --prefix editors/tests`, as scripts/setup.sh does).
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..', '..');
const require = createRequire(import.meta.url);

let vsctm, oniguruma;
try {
  vsctm = require('vscode-textmate');
  oniguruma = require('vscode-oniguruma');
} catch {
  console.log('textmate_test: vscode-textmate or vscode-oniguruma is not installed ' +
              '(npm ci --prefix editors/tests); skipped');
  process.exit(77);
}

const sledIndex = process.argv.indexOf('--sled');
const sled = sledIndex > 0 ? process.argv[sledIndex + 1] : null;

const wasm = readFileSync(join(dirname(require.resolve('vscode-oniguruma')), 'onig.wasm'));
await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
const registry = new vsctm.Registry({
  onigLib: Promise.resolve({
    createOnigScanner: (sources) => new oniguruma.OnigScanner(sources),
    createOnigString: (text) => new oniguruma.OnigString(text),
  }),
  loadGrammar: async (scopeName) => {
    if (scopeName !== 'source.sled') return null;
    const path = join(root, 'editors', 'vscode', 'syntaxes', 'sled.tmLanguage.json');
    return vsctm.parseRawGrammar(readFileSync(path, 'utf8'), path);
  },
});
const grammar = await registry.loadGrammar('source.sled');

function tokenize(text) {
  let stack = vsctm.INITIAL;
  const lines = [];
  for (const line of text.split('\n')) {
    const result = grammar.tokenizeLine(line, stack);
    lines.push({ line, tokens: result.tokens });
    stack = result.ruleStack;
  }
  return { lines, depth: stack.depth };
}

// Every .sled file git knows of.
const files = execFileSync('git', ['ls-files', '*.sled'], { cwd: root, encoding: 'utf8' })
  .split('\n').filter((file) => file.length > 0);

// Whether sled reports a syntax error (E01xx) for a file: such files may leave blocks open.
function hasSyntaxErrors(file) {
  if (!sled) return /(^|\/)fail_/.test(file);
  const run = spawnSync(sled, ['check', '--diagnostics=compact', '--no-lints', file],
                        { cwd: root, encoding: 'utf8' });
  return /error\[E01\d\d\]/.test(run.stderr);
}

let passed = 0;
let failed = 0;
function check(ok, what) {
  if (ok) {
    passed += 1;
  } else {
    failed += 1;
    console.log(`FAILED: ${what}`);
  }
}

for (const file of files) {
  const { lines, depth } = tokenize(readFileSync(join(root, file), 'utf8'));
  if (hasSyntaxErrors(file)) {
    passed += 1;  // tokenized without an exception is all that is asked of a broken file
    continue;
  }
  check(depth === 1, `${file}: the grammar ends ${depth - 1} level(s) deep (a block not closed)`);
  const invalid = [];
  lines.forEach(({ line, tokens }, index) => {
    for (const token of tokens) {
      if (token.scopes.some((scope) => scope.startsWith('invalid'))) {
        invalid.push(`${index + 1}:${token.startIndex + 1} ${line.slice(token.startIndex, token.endIndex)}`);
      }
    }
  });
  check(invalid.length === 0, `${file}: invalid tokens at ${invalid.join(', ')}`);
}

// Snapshots: each token with the scopes under the file's own (source.sled is left out).
const snapshotted = ['examples/frontal_sled.sled', 'stdlib/humans/male50.sled',
                     'examples/pedestrian.sled'];
const update = process.env.SLED_UPDATE_SNAPSHOTS === '1';
mkdirSync(join(here, 'snapshots'), { recursive: true });
for (const file of snapshotted) {
  const { lines } = tokenize(readFileSync(join(root, file), 'utf8'));
  let text = '';
  lines.forEach(({ line, tokens }, index) => {
    for (const token of tokens) {
      const piece = line.slice(token.startIndex, token.endIndex);
      if (piece.trim() === '') continue;
      const scopes = token.scopes.slice(1).join(' ');
      text += `${index + 1}:${token.startIndex + 1} ${JSON.stringify(piece)} ${scopes}\n`;
    }
  });
  const snapshot = join(here, 'snapshots', `${file.replaceAll('/', '_')}.scopes`);
  if (update || !existsSync(snapshot)) {
    writeFileSync(snapshot, text);
    console.log(`wrote ${relative(root, snapshot)}`);
    passed += 1;
    continue;
  }
  const expected = readFileSync(snapshot, 'utf8');
  if (expected === text) {
    passed += 1;
  } else {
    const want = expected.split('\n');
    const got = text.split('\n');
    const at = want.findIndex((line, i) => line !== got[i]);
    check(false, `${file}: scopes differ from ${relative(root, snapshot)} first at\n` +
                 `  expected: ${want[at]}\n  actual:   ${got[at]}\n` +
                 '  (SLED_UPDATE_SNAPSHOTS=1 rewrites the snapshots; review the diff)');
  }
}

console.log(`textmate: ${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
