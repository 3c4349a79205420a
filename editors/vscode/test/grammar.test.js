// The TextMate grammar, tokenized as VS Code tokenizes it (vscode-textmate, Oniguruma):
// keys, ids, numbers, placeholders and comments each get their scope.
const test = require("node:test");
const assert = require("node:assert");
const fs = require("node:fs");
const path = require("node:path");
const textmate = require("vscode-textmate");
const oniguruma = require("vscode-oniguruma");

const wasm = fs.readFileSync(require.resolve("vscode-oniguruma/release/onig.wasm")).buffer;
const onigLib = oniguruma.loadWASM(wasm).then(() => ({
  createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
  createOnigString: (text) => new oniguruma.OnigString(text),
}));
const registry = new textmate.Registry({
  onigLib,
  loadGrammar: async () =>
    textmate.parseRawGrammar(
      fs.readFileSync(path.join(__dirname, "..", "syntaxes", "ekb.tmLanguage.json"), "utf8"),
      "ekb.tmLanguage.json",
    ),
});

/** Each token of `line` that has a scope of ours, as `text=scope`. */
async function tokens(line) {
  const grammar = await registry.loadGrammar("source.ekb");
  const { tokens } = grammar.tokenizeLine(line, textmate.INITIAL);
  return tokens
    .map((t) => [line.slice(t.startIndex, t.endIndex), t.scopes.filter((s) => s !== "source.ekb").pop()])
    .filter(([, scope]) => scope)
    .map(([text, scope]) => `${text}=${scope}`);
}

test("a location's line: key, id, text", async () => {
  assert.deepStrictEqual(await tokens("robotLocationDescription      4 Roomba"), [
    "robotLocationDescription=keyword.other.key.ekb",
    "4=variable.other.constant.id.ekb",
    "Roomba=string.unquoted.text.ekb",
  ]);
});

test("placeholders stand out from messages", async () => {
  assert.deepStrictEqual(await tokens("preGestureMessageIsiZulu      1 No message in isiZulu"), [
    "preGestureMessageIsiZulu=keyword.other.key.ekb",
    "1=variable.other.constant.id.ekb",
    "No message in isiZulu=markup.italic.placeholder.ekb",
  ]);
});

test("numbers, and what is not one", async () => {
  assert.deepStrictEqual(await tokens("robotLocationPose 2 2.6 -8.1 8,1"), [
    "robotLocationPose=keyword.other.key.ekb",
    "2=variable.other.constant.id.ekb",
    "2.6=constant.numeric.ekb",
    "-8.1=constant.numeric.ekb",
    "8,1=invalid.illegal.number.ekb",
  ]);
});

test("the tour: its count and its stops", async () => {
  assert.deepStrictEqual(await tokens("tourSpecification 3 1, 4 2"), [
    "tourSpecification=keyword.other.key.tour.ekb",
    "3=constant.numeric.count.ekb",
    "1=variable.other.constant.id.ekb",
    ",=punctuation.separator.ekb",
    "4=variable.other.constant.id.ekb",
    "2=variable.other.constant.id.ekb",
  ]);
});

test("comments, suppression comments and unknown keys", async () => {
  assert.deepStrictEqual(await tokens("# a note"), ["#=punctuation.definition.comment.ekb", " a note=comment.line.number-sign.ekb"]);
  const suppression = await tokens("# ekb: ignore[key-case]");
  assert.ok(suppression.includes("key-case=entity.name.tag.rule.ekb"), suppression);
  assert.deepStrictEqual(await tokens("postGestureMessageenglish 4 Hi"), ["postGestureMessageenglish=invalid.illegal.key.ekb"]);
  assert.deepStrictEqual((await tokens("gestureArm 3 left"))[2], "left=constant.language.arm.ekb");
});
