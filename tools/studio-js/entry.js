// What the studio's app.js takes from CodeMirror 6: bundled by build.mjs into one ES module
// (compiler/studio/static/vendor/codemirror.js), so the page loads nothing from a CDN.
export { EditorState, StateEffect, StateField, RangeSetBuilder } from "@codemirror/state";
export {
  EditorView,
  Decoration,
  ViewPlugin,
  WidgetType,
  keymap,
  hoverTooltip,
  lineNumbers,
  highlightActiveLine,
  drawSelection,
} from "@codemirror/view";
export { defaultKeymap, history, historyKeymap } from "@codemirror/commands";
export {
  autocompletion,
  acceptCompletion,
  closeCompletion,
  moveCompletionSelection,
  startCompletion,
} from "@codemirror/autocomplete";
export { linter, lintGutter, setDiagnostics, forceLinting, forEachDiagnostic } from "@codemirror/lint";
