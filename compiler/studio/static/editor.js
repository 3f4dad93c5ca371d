// The CodeMirror 6 editor, with the language features the server computes (the language
// server's own functions): diagnostics and their quick fixes, semantic colouring, colour swatches,
// completion and hover. Positions arrive as LSP positions (line, UTF-16 column).
import {
  EditorState, StateEffect, StateField, EditorView, Decoration, WidgetType, keymap,
  hoverTooltip, lineNumbers, highlightActiveLine, drawSelection, defaultKeymap, history, historyKeymap,
  autocompletion, acceptCompletion, closeCompletion, moveCompletionSelection, startCompletion, lintGutter,
  setDiagnostics,
} from "./vendor/codemirror.js";
import { markdownNodes } from "./markdown.js";

const SEVERITIES = { 1: "error", 2: "warning", 3: "info", 4: "hint" };
const setDecorations = StateEffect.define();
// Completion keys: Tab takes the selected word, the arrows choose, Escape closes, Ctrl-Space opens.
const COMPLETION_KEYS = [
  { key: "Tab", run: acceptCompletion },
  { key: "ArrowDown", run: moveCompletionSelection(true) },
  { key: "ArrowUp", run: moveCompletionSelection(false) },
  { key: "PageDown", run: moveCompletionSelection(true, "page") },
  { key: "PageUp", run: moveCompletionSelection(false, "page") },
  { key: "Escape", run: closeCompletion },
  { key: "Ctrl-Space", run: startCompletion },
];

// Semantic tokens and swatches, replaced whole on every analysis.
const decorations = StateField.define({
  create: () => Decoration.none,
  update(value, transaction) {
    let next = value.map(transaction.changes);
    for (const effect of transaction.effects) if (effect.is(setDecorations)) next = effect.value;
    return next;
  },
  provide: (field) => EditorView.decorations.from(field),
});

class Swatch extends WidgetType {
  constructor(css) {
    super();
    this.css = css;
  }
  eq(other) {
    return other.css === this.css;
  }
  toDOM() {
    const span = document.createElement("span");
    span.className = "swatch";
    span.style.background = this.css;
    return span;
  }
}

export function offsetOf(doc, position) {
  const line = Math.min(position.line + 1, doc.lines);
  const info = doc.line(line);
  return Math.min(info.from + position.character, info.to);
}

function positionOf(doc, offset) {
  const line = doc.lineAt(offset);
  return { line: line.number - 1, character: offset - line.from };
}

function cssColour(colour) {
  const byte = (c) => Math.round(Math.max(0, Math.min(1, c)) * 255);
  return `rgb(${byte(colour.red)}, ${byte(colour.green)}, ${byte(colour.blue)})`;
}

export class Editor {
  // onChange(text): the document changed by typing; ask(op, fields): a request to the server.
  constructor(parent, { onChange, ask }) {
    this.ask = ask;
    this.quiet = false;
    this.view = new EditorView({
      parent,
      state: EditorState.create({
        doc: "",
        extensions: [
          lineNumbers(),
          history(),
          drawSelection(),
          highlightActiveLine(),
          lintGutter(),
          decorations,
          EditorView.lineWrapping,
          autocompletion({
            override: [(context) => this.complete(context)],
            activateOnTyping: true,
            defaultKeymap: false, // Enter ends the line: a phrase typed and Enter never picks another word
          }),
          hoverTooltip((view, pos) => this.hover(view, pos), { hoverTime: 250 }),
          keymap.of([...COMPLETION_KEYS, ...historyKeymap, ...defaultKeymap]),
          EditorView.updateListener.of((update) => {
            if (update.docChanged && !this.quiet) onChange(update.state.doc.toString());
          }),
        ],
      }),
    });
  }

  get text() {
    return this.view.state.doc.toString();
  }

  // Replace the whole text (a refinement, undo or redo from the server) without echoing it back.
  setText(text) {
    if (text === this.text) return;
    this.quiet = true;
    try {
      this.view.dispatch({ changes: { from: 0, to: this.view.state.doc.length, insert: text } });
    } finally {
      this.quiet = false;
    }
  }

  // An analysis of `text`: applied only while the editor still holds that text.
  show(analysis, text) {
    if (text !== this.text) return false;
    const doc = this.view.state.doc;
    const diagnostics = analysis.diagnostics.map((d) => this.diagnostic(doc, d));
    this.view.dispatch(setDiagnostics(this.view.state, diagnostics));
    this.view.dispatch({ effects: setDecorations.of(this.decorationSet(doc, analysis)) });
    return true;
  }

  diagnostic(doc, d) {
    const from = offsetOf(doc, d.range.start);
    const to = Math.max(from, offsetOf(doc, d.range.end));
    const hints = (d.relatedInformation || []).map((r) => r.message);
    return {
      from,
      to,
      severity: SEVERITIES[d.severity] || "info",
      source: d.code ? `cnlmc ${d.code}` : "cnlmc",
      message: [d.message, ...hints].join("\n"),
      actions: (d.fixes || []).map((fix) => ({
        name: fix.title,
        apply: (view) => {
          const changes = fix.edits.map((e) => ({
            from: offsetOf(view.state.doc, e.range.start),
            to: offsetOf(view.state.doc, e.range.end),
            insert: e.text,
          }));
          view.dispatch({ changes });
        },
      })),
    };
  }

  decorationSet(doc, analysis) {
    const marks = [];
    for (const [line, start, length, type] of analysis.tokens) {
      const from = offsetOf(doc, { line, character: start });
      const to = offsetOf(doc, { line, character: start + length });
      if (to > from) marks.push({ from, to, deco: Decoration.mark({ class: `tok-${analysis.token_types[type]}` }) });
    }
    for (const c of analysis.colours) {
      const at = offsetOf(doc, c.range.start);
      marks.push({ from: at, to: at, deco: Decoration.widget({ widget: new Swatch(cssColour(c.color)), side: -1 }) });
    }
    return Decoration.set(marks.map((m) => m.deco.range(m.from, m.to)), true);
  }

  async complete(context) {
    const text = context.state.doc.toString();
    const where = positionOf(context.state.doc, context.pos);
    const word = context.matchBefore(/[\p{L}][\p{L}\p{N}'’\-]*$/u);
    if (!word && !context.explicit && !/\s$/.test(text.slice(0, context.pos))) return null;
    const answer = await this.ask("complete", { text, ...where });
    if (text !== this.text || answer.items.length === 0) return null;
    const from = word ? word.from : context.pos;
    return {
      from,
      options: answer.items.map((item) => ({
        label: item.label,
        detail: item.detail,
        type: item.kind,
        boost: -Number.parseInt(item.sort, 10) || 0,
        info: item.doc ? () => docNode(item.doc) : undefined,
      })),
      // a list cut at the server's limit is asked for again as letters are typed
      validFor: answer.complete ? /^[\p{L}][\p{L}\p{N}'’\-]*$/u : undefined,
    };
  }

  async hover(view, pos) {
    const text = view.state.doc.toString();
    const answer = await this.ask("hover", { text, ...positionOf(view.state.doc, pos) });
    if (!answer.markdown || text !== this.text) return null;
    const from = answer.range ? offsetOf(view.state.doc, answer.range.start) : pos;
    const to = answer.range ? offsetOf(view.state.doc, answer.range.end) : pos;
    return { pos: from, end: to, above: true, create: () => ({ dom: docNode(answer.markdown) }) };
  }
}

function docNode(markdown) {
  const div = document.createElement("div");
  div.className = "hover-doc";
  div.append(...markdownNodes(markdown));
  return div;
}
