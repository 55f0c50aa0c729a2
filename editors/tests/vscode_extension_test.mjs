// Tests the wiring of the VS Code extension (editors/vscode): package.json declares the language,
// the grammar and the settings, and activate() starts `sled lsp` through vscode-languageclient
// with the settings applied. VS Code itself and vscode-languageclient are replaced by stand-ins
// that record what the extension asks of them.
//
//   node editors/tests/vscode_extension_test.mjs
import Module, { createRequire } from 'node:module';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const extension = join(here, '..', 'vscode');
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

const manifest = JSON.parse(readFileSync(join(extension, 'package.json'), 'utf8'));
const language = manifest.contributes.languages.find((entry) => entry.id === 'sled');
check(language && language.extensions.includes('.sled'), 'package.json declares .sled files');
const grammar = manifest.contributes.grammars.find((entry) => entry.language === 'sled');
check(grammar && grammar.scopeName === 'source.sled' && existsSync(join(extension, grammar.path)),
      'package.json points at the TextMate grammar');
check(existsSync(join(extension, language.configuration)), 'the language configuration exists');
check(existsSync(join(extension, manifest.main)), 'the extension\'s main file exists');

// Stand-ins for the modules VS Code provides.
const started = [];
let settings = {};
const stubs = {
  vscode: {
    workspace: {
      getConfiguration: () => ({ get: (key) => settings[key] }),
      onDidChangeConfiguration: () => ({ dispose() {} }),
    },
    window: { showInformationMessage() {} },
  },
  'vscode-languageclient/node': {
    LanguageClient: class {
      constructor(id, name, server, client) {
        Object.assign(this, { id, name, server, client });
      }
      start() {
        started.push(this);
        return Promise.resolve();
      }
      stop() {
        return Promise.resolve();
      }
    },
  },
};
const resolve = Module._resolveFilename;
Module._resolveFilename = function (request, ...rest) {
  return request in stubs ? request : resolve.call(this, request, ...rest);
};
for (const [name, exports] of Object.entries(stubs)) {
  Module._cache[name] = { id: name, filename: name, loaded: true, exports };
}
const require = createRequire(import.meta.url);
const { activate, deactivate } = require(join(extension, manifest.main));

const context = { subscriptions: [] };
await activate(context);
let client = started.at(-1);
check(client.server.run.command === 'sled' && client.server.run.args.join(' ') === 'lsp',
      `activate starts \`sled lsp\` (got ${JSON.stringify(client.server.run)})`);
check(client.client.documentSelector.some((selector) => selector.language === 'sled'),
      'the client serves sled documents');

settings = { path: '/opt/sled/bin/sled', stdlib: '/opt/sled/stdlib' };
await activate({ subscriptions: [] });
client = started.at(-1);
check(client.server.run.command === '/opt/sled/bin/sled' &&
      client.server.run.args.join(' ') === 'lsp --stdlib /opt/sled/stdlib' &&
      client.client.initializationOptions.stdlib === '/opt/sled/stdlib',
      `the settings sled.path and sled.stdlib apply (got ${JSON.stringify(client.server.run)})`);
await deactivate();

console.log(`vscode extension: ${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
