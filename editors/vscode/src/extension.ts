// Starts `ekb lsp` for environment knowledge bases, again when its settings change, and
// stops it with the extension.
import { workspace, ExtensionContext } from "vscode";
import {
  LanguageClient,
  LanguageClientOptions,
  ServerOptions,
  TransportKind,
} from "vscode-languageclient/node";

let client: LanguageClient | undefined;

/** A client for the server the settings name: `ekb.path`, with `ekb.args` before `lsp`. */
function createClient(): LanguageClient {
  const settings = workspace.getConfiguration("ekb");
  const command = settings.get<string>("path", "ekb");
  const args = [...settings.get<string[]>("args", []), "lsp"];
  // Over stdio the client adds `--stdio`, which `ekb lsp` accepts.
  const run = { command, args, transport: TransportKind.stdio };
  const serverOptions: ServerOptions = { run, debug: run };
  const clientOptions: LanguageClientOptions = {
    documentSelector: [{ language: "ekb" }],
  };
  return new LanguageClient("ekb", "ekb", serverOptions, clientOptions);
}

export async function activate(context: ExtensionContext): Promise<void> {
  context.subscriptions.push(
    workspace.onDidChangeConfiguration(async (change) => {
      if (change.affectsConfiguration("ekb.path") || change.affectsConfiguration("ekb.args")) {
        await client?.stop();
        client = createClient();
        await client.start();
      }
    }),
  );
  client = createClient();
  await client.start();
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
