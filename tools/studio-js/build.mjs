// Builds the studio's vendored browser modules into compiler/studio/static/vendor/:
//   codemirror.js      CodeMirror 6 (entry.js's exports), bundled and minified by esbuild
//   model-viewer.js    <model-viewer>'s published self-contained bundle (it includes three.js and lit)
//   licenses/          the licence file of every package whose code is in those two files
// Run: npm ci && npm run build   (in tools/studio-js). The output is committed: CI does not rebuild it.
import { build } from "esbuild";
import { copyFileSync, mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const vendor = join(here, "..", "..", "compiler", "studio", "static", "vendor");
const licences = join(vendor, "licenses");

const CODEMIRROR_PACKAGES = [
  "@codemirror/autocomplete", "@codemirror/commands", "@codemirror/language", "@codemirror/lint",
  "@codemirror/state", "@codemirror/view", "@lezer/common", "@lezer/highlight", "@lezer/lr",
  "@marijn/find-cluster-break", "style-mod", "w3c-keyname", "crelt",
];
const MODEL_VIEWER_PACKAGES = [
  "@google/model-viewer", "three", "lit", "lit-html", "lit-element", "@lit/reactive-element",
];

function packageInfo(name) {
  const folder = join(here, "node_modules", name);
  const manifest = JSON.parse(readFileSync(join(folder, "package.json"), "utf8"));
  return { folder, version: manifest.version, license: manifest.license };
}

function copyLicences(names) {
  const rows = [];
  for (const name of names) {
    const info = packageInfo(name);
    const target = join(licences, name.replace("/", "__") + ".LICENSE.txt");
    copyFileSync(join(info.folder, "LICENSE"), target);
    rows.push(`${name}@${info.version} (${info.license})`);
  }
  return rows;
}

mkdirSync(licences, { recursive: true });
await build({
  entryPoints: [join(here, "entry.js")],
  bundle: true,
  format: "esm",
  minify: true,
  target: "es2020",
  legalComments: "none",
  outfile: join(vendor, "codemirror.js"),
});
copyFileSync(
  join(here, "node_modules", "@google", "model-viewer", "dist", "model-viewer.min.js"),
  join(vendor, "model-viewer.js"),
);
const listing = [
  "codemirror.js contains (MIT):",
  ...copyLicences(CODEMIRROR_PACKAGES).map((row) => "  " + row),
  "model-viewer.js contains:",
  ...copyLicences(MODEL_VIEWER_PACKAGES).map((row) => "  " + row),
  "Each package's licence is in licenses/<package>.LICENSE.txt ('/' written as '__').",
  "",
];
writeFileSync(join(vendor, "THIRD_PARTY.txt"), listing.join("\n"));
