// The sled extension for VS Code: the TextMate grammar (package.json) for highlighting, and
// `sled lsp` as the language server for everything else (docs/editors.md).
'use strict';

const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const settings = vscode.workspace.getConfiguration('sled');
  const args = ['lsp'];
  const stdlib = settings.get('stdlib');
  if (stdlib) args.push('--stdlib', stdlib);
  const server = { command: settings.get('path') || 'sled', args };
  client = new LanguageClient(
    'sled',
    'sled',
    { run: server, debug: server },
    {
      documentSelector: [{ scheme: 'file', language: 'sled' }, { scheme: 'untitled', language: 'sled' }],
      initializationOptions: stdlib ? { stdlib } : {},
    },
  );
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (event.affectsConfiguration('sled')) {
        vscode.window.showInformationMessage('sled: reload the window to apply the new settings.');
      }
    }),
  );
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
