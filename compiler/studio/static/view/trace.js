// Where an edit's time goes: User Timing marks ("cnlmc:<stage>", detail {edit: its number, ...}),
// one per stage from the keystroke to the frame on screen. bench/studio.py reads them with
// performance.getEntriesByType("mark"); each costs a timestamp.
const MAX_MARKS = 600; // our choice: ~40 edits' worth of stages, far more than one measurement reads

export class Trace {
  constructor() {
    this.kept = 0;
    this.edit = null;
  }

  // Mark `stage` of edit number `edit` now, or at `startTime` (a performance.now() taken earlier);
  // `more`: what else the mark's detail holds. No edit number (a redraw no edit asked for): no mark.
  mark(stage, edit, { startTime = undefined, ...more } = {}) {
    if (edit === undefined || edit === null) return;
    if (edit !== this.edit && this.kept >= MAX_MARKS) {
      performance.clearMarks(); // only when a new edit begins: an edit's own marks stay together
      this.kept = 0;
    }
    this.edit = edit;
    this.kept++;
    const detail = { edit, ...more };
    performance.mark(`cnlmc:${stage}`, startTime === undefined ? { detail } : { detail, startTime });
  }
}

// The callback runs after the browser's next rendering update: what was drawn before this call
// has gone to the compositor (for a canvas: the frame is on its way to the screen).
export function afterPaint(callback) {
  requestAnimationFrame(() => setTimeout(callback, 0));
}
