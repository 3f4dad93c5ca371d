// The studio page: the editor, the live view, refinement and history, exports, AR.
// Everything the language knows comes from the server (the engine the CLI and the language
// server use); this file only wires the page together.
import { MaterialView } from "./view/view.js";
import { Trace } from "./view/trace.js";
import { PayloadParts } from "./parts.js";
import { Connection } from "./connection.js";
import { Editor } from "./editor.js";
import { Microphone } from "./speech.js";
import { Problem, showChips, showExports, showHistory, showMaterials, showNotes, thumbnail } from "./panels.js";

// The canvas's drawing buffer follows its size on the page (CSS pixels x devicePixelRatio), at most
// the 512² the page lays it out at on a desktop (the sphere is tessellated for it; a software
// renderer's frame costs its pixels): a narrower window draws no pixels the screen does not show.
const MAX_CANVAS = 512;
const MIN_CANVAS = 64;
const THUMBNAIL_WAIT_MS = 2000; // our choice: a history thumbnail waits for an idle moment at most this long
// `fn` when the page is idle (at most THUMBNAIL_WAIT_MS later); a browser without
// requestIdleCallback (Safari) runs it after the current work
const whenIdle = (fn) =>
  window.requestIdleCallback ? requestIdleCallback(fn, { timeout: THUMBNAIL_WAIT_MS }) : setTimeout(fn, 0);
const $ = (id) => document.getElementById(id);
const problem = new Problem($("problem"));
const status = document.body.dataset; // what the page is doing, for people and for the tests
status.shown = "0";
status.analyses = "0";
status.heard = "0";

function fail(error) {
  problem.show(error instanceof Error ? error.message : String(error));
}
window.addEventListener("error", (event) => fail(event.message));
window.addEventListener("unhandledrejection", (event) => fail(event.reason));

function socketUrl() {
  const token = new URLSearchParams(location.search).get("token");
  const scheme = location.protocol === "https:" ? "wss:" : "ws:";
  return `${scheme}//${location.host}/ws${token ? `?token=${encodeURIComponent(token)}` : ""}`;
}

class Studio {
  constructor(connection, hello) {
    this.connection = connection;
    this.hello = hello;
    this.changes = 0; // changes typed: each edit is numbered in the trace (view/trace.js)
    this.editing = false; // an edit is on its way to the server and back
    this.editAgain = false; // the text changed meanwhile: send it when the answer comes
    this.fresh = false; // the next edit asks for every payload part again (parts.js)
    this.trace = new Trace();
    this.parts = new PayloadParts(hello.parts_kept);
    this.pictures = new Map(); // history step id -> the thumbnail of the frame drawn for it
    this.pendingThumbnail = null;
    this.canvas = $("view");
    this.view = new MaterialView(this.canvas, { dataUrl: hello.data_url, filesUrl: hello.files_url, trace: this.trace });
    this.canvas.addEventListener("frame", (event) => this.framed(event.detail));
    new ResizeObserver(() => this.fitCanvas()).observe(this.canvas);
    this.editor = new Editor($("editor"), {
      onChange: () => this.changed(),
      ask: (op, fields) => connection.request(op, fields),
    });
    connection.on("chips", (message) => {
      if (message.text === this.editor.text) showChips($("chips"), message.words, (word) => this.refine(word));
    });
    connection.on("closed", () => fail("the studio's server stopped: start `cnlmc serve` again and reload"));
    showExports($("exports"), hello.exports, (kind, button) => this.export(kind, button));
    this.wireControls();
    this.editor.setText(hello.text || "");
    this.edit();
  }

  fitCanvas() {
    const shown = Math.round(this.canvas.clientWidth * (window.devicePixelRatio || 1));
    if (shown <= 0) return; // not laid out (hidden)
    const side = Math.min(MAX_CANVAS, Math.max(MIN_CANVAS, shown));
    if (side === this.canvas.width && side === this.canvas.height) return;
    this.canvas.width = this.canvas.height = side; // clears it: drawn again
    this.view.ready.then(() => {
      if (this.canvas.width !== side) return; // resized again meanwhile: that one draws
      this.view.draw();
      this.canvas.dataset.side = String(side); // drawn at this size (the tests wait on it)
    });
  }

  // A change typed: sent at once when no edit is on its way (no debounce to wait out), else when
  // that one's answer comes (the newest text only: a burst of keys costs one analysis per answer).
  changed() {
    this.changes += 1;
    this.trace.mark("change", this.changes);
    this.editSoon();
  }

  editSoon() {
    if (this.editing) this.editAgain = true;
    else this.edit();
  }

  async edit() {
    this.editing = true;
    try {
      do {
        this.editAgain = false;
        const text = this.editor.text;
        const number = this.changes;
        const fields = this.fresh ? { text, fresh: true } : { text };
        this.fresh = false;
        this.trace.mark("send", number);
        const analysis = await this.ask("edit", fields);
        this.trace.mark("message", number, { startTime: analysis.arrived, chars: analysis.chars });
        this.trace.mark("parsed", number, { startTime: analysis.parsed, server: analysis.timing });
        if (analysis.op !== "skipped" && !this.editAgain) this.apply(analysis, text, number);
      } while (this.editAgain);
    } catch (error) {
      fail(error);
    } finally {
      this.editing = false;
    }
  }

  // A request whose answer may be an analysis: its payloads are made whole from the parts this page
  // holds (null when it lacks one), here, in the order the answers arrive (as the server counts them).
  async ask(op, fields = {}) {
    const answer = await this.connection.request(op, fields);
    if (answer.payloads) answer.payloads = this.parts.complete(answer.payloads);
    return answer;
  }

  async apply(analysis, text, number = null) {
    if (analysis.text !== undefined) {
      this.editor.setText(analysis.text);
      text = analysis.text;
    }
    if (!this.editor.show(analysis, text)) return; // typed on since: the next analysis comes
    if (analysis.payloads === null) {
      this.fresh = true; // a part this page no longer holds: ask for them all
      this.editSoon();
      return;
    }
    status.analyses = String(Number(status.analyses) + 1);
    problem.clear();
    showMaterials($("materials"), analysis.materials);
    const more = $("not-shown");
    more.hidden = !analysis.not_shown;
    more.textContent = analysis.not_shown ? `${analysis.not_shown} more not shown in the view` : "";
    this.showHistory(analysis.history);
    if (!analysis.ok || analysis.payloads.length === 0) return;
    if (analysis.recorded) this.pendingThumbnail = analysis.history.steps[analysis.history.at].id;
    this.trace.mark("applied", number);
    await this.view.show(analysis.payloads, { edit: number });
    if (text === this.editor.text) status.shown = String(Number(status.shown) + 1);
  }

  showHistory(history) {
    const kept = new Set(history.steps.map((step) => step.id));
    for (const id of this.pictures.keys()) if (!kept.has(id)) this.pictures.delete(id);
    showHistory($("history"), history, this.pictures);
    $("undo").disabled = !history.can_undo;
    $("redo").disabled = !history.can_redo;
  }

  // The thumbnail of a new history step: its full frame, taken when the page is idle (off the
  // path from a keystroke to its picture).
  framed(detail) {
    $("frame-time").textContent = `${detail.ms.toFixed(1)} ms a frame`;
    if (this.pendingThumbnail === null || detail.scale !== 1) return;
    const id = this.pendingThumbnail;
    const shown = this.view.shows;
    this.pendingThumbnail = null;
    whenIdle(() => {
      if (this.view.shows !== shown) return; // another material is on the canvas by now
      const image = thumbnail(this.canvas);
      this.pictures.set(id, image);
      const item = $("history").querySelector(`li[data-step="${id}"] img`);
      if (item) item.src = image;
    });
  }

  async refine(words) {
    try {
      this.apply(await this.ask("refine", { words }), this.editor.text);
      $("refine").value = "";
    } catch (error) {
      fail(error);
    }
  }

  // The microphone button: the first press records and streams the utterance to the server, the
  // second (or the length limit) sends its rest; the server applies it as `cnlmc listen` does and
  // says what it heard.
  async speak() {
    const button = $("speak");
    if (!this.microphone) {
      this.microphone = new Microphone(this.hello.speech.rate, this.hello.speech.max_seconds);
      this.microphone.onLimit = () => this.speak();
      // each part goes to the server while the person speaks (answered in order, before the `hear`)
      this.microphone.onChunk = (pcm) => this.ask("hear_chunk", { pcm }).catch(fail);
    }
    if (this.microphoneStarting) return; // a second press while the browser asks for the microphone
    if (!this.microphone.recording) {
      this.microphoneStarting = true;
      try {
        await this.microphone.start();
      } catch (error) {
        fail(`the microphone is not available: ${error.message || error}`);
        return;
      } finally {
        this.microphoneStarting = false;
      }
      button.setAttribute("aria-pressed", "true");
      button.textContent = "Stop";
      $("heard").textContent = "listening… press Stop when done";
      return;
    }
    button.setAttribute("aria-pressed", "false");
    button.textContent = "Speak";
    const pcm = this.microphone.stop();
    $("heard").textContent = "recognising…";
    try {
      const answer = await this.ask("hear", { pcm });
      $("heard").textContent = answer.message;
      if (answer.op === "analysis") await this.apply(answer, this.editor.text);
    } catch (error) {
      $("heard").textContent = "";
      fail(error);
    } finally {
      status.heard = String(Number(status.heard) + 1);
    }
  }

  async step(op) {
    try {
      this.apply(await this.ask(op), this.editor.text);
    } catch (error) {
      fail(error);
    }
  }

  async export(kind, button) {
    button.disabled = true;
    try {
      const answer = await this.connection.request("export", { key: kind.key, text: this.editor.text });
      showNotes($("notes"), answer.notes);
      const link = document.createElement("a");
      link.href = `${answer.url}?download=1`;
      link.download = answer.name;
      document.body.append(link);
      link.click();
      link.remove();
    } catch (error) {
      fail(error);
    } finally {
      button.disabled = false;
    }
  }

  async openAR() {
    const dialog = $("ar");
    dialog.showModal();
    try {
      const answer = await this.connection.request("ar_model", { text: this.editor.text });
      showNotes($("notes"), answer.notes);
      const model = $("model");
      model.setAttribute("ios-src", answer.usdz);
      model.setAttribute("src", answer.glb);
    } catch (error) {
      fail(error);
    }
  }

  async composite(file) {
    if (!file) return;
    try {
      const response = await fetch(`/ar-photo/${this.hello.session}`, {
        method: "POST",
        headers: { "Content-Type": file.type || "application/octet-stream" },
        body: file,
      });
      const answer = await response.json();
      if (answer.error) throw new Error(answer.error);
      const image = $("composite");
      image.src = answer.url;
      image.alt = "the material on the marker in your photo";
      image.hidden = false;
    } catch (error) {
      fail(error);
    }
  }

  wireControls() {
    $("refine-form").addEventListener("submit", (event) => {
      event.preventDefault();
      const words = $("refine").value.trim();
      if (words) this.refine(words);
    });
    $("undo").addEventListener("click", () => this.step("undo"));
    $("redo").addEventListener("click", () => this.step("redo"));
    $("speak").addEventListener("click", () => this.speak());
    $("mesh").addEventListener("change", (event) => this.view.setMesh(event.target.value).catch(fail));
    $("environment").addEventListener("change", (event) => this.view.setEnvironment(event.target.value).catch(fail));
    $("exposure").addEventListener("input", (event) => this.view.setExposure(Number(event.target.value)));
    $("ar-open").addEventListener("click", () => this.openAR());
    $("model").addEventListener("error", (event) => fail(`the AR model did not load (${event.detail?.type || "error"})`));
    $("photo").addEventListener("change", (event) => this.composite(event.target.files[0]));
    this.wireDrop($("stage"));
  }

  wireDrop(stage) {
    stage.addEventListener("dragover", (event) => {
      event.preventDefault();
      stage.classList.add("dropping");
    });
    stage.addEventListener("dragleave", () => stage.classList.remove("dropping"));
    stage.addEventListener("drop", async (event) => {
      event.preventDefault();
      stage.classList.remove("dropping");
      const file = event.dataTransfer.files[0];
      if (!file) return;
      try {
        if (/\.(hdr|exr)$/i.test(file.name)) await this.view.setEnvironment(file);
        else if (/\.(glb|gltf|obj)$/i.test(file.name)) await this.view.setMesh(await file.arrayBuffer());
        else throw new Error(`${file.name}: drop a .glb, .gltf or .obj mesh, or an .hdr or .exr environment`);
      } catch (error) {
        fail(error);
      }
    });
  }
}

async function start() {
  const connection = new Connection(socketUrl());
  await connection.opened;
  const hello = await connection.hello;
  new Studio(connection, hello); // eslint-disable-line no-new
  status.ready = "1";
}

start().catch(fail);
