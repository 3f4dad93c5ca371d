// A minimal VS Code client for `cnlmc lsp`: a generic LSP client over stdio, nothing more.
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function settings() {
  const config = vscode.workspace.getConfiguration("cnlmc");
  return { inlayHints: config.get("inlayHints"), debounceMs: config.get("debounceMs") };
}

function activate(context) {
  const [command, ...args] = vscode.workspace.getConfiguration("cnlmc").get("server.command");
  client = new LanguageClient(
    "cnlmc",
    "cnlmc materials",
    { command, args },
    {
      documentSelector: [{ language: "cnl" }],
      initializationOptions: settings(),
      // sends workspace/didChangeConfiguration {settings: {cnlmc: {...}}} when settings change
      synchronize: { configurationSection: "cnlmc" },
    },
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
