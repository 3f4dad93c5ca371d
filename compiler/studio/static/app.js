// The studio page: the editor, the live view, refinement and history, exports, AR.
// Everything the language knows comes from the server (the engine the CLI and the language
// server use); this file only wires the page together.
import { MaterialView } from "./view/view.js";
import { Connection } from "./connection.js";
import { Editor } from "./editor.js";
import { Problem, showChips, showExports, showHistory, showMaterials, showNotes, thumbnail } from "./panels.js";

const EDIT_DELAY_MS = 60; // our choice: coalesces a burst of keys, below what a typist notices
const $ = (id) => document.getElementById(id);
const problem = new Problem($("problem"));
const status = document.body.dataset; // what the page is doing, for people and for the tests
status.shown = "0";
status.analyses = "0";

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
    this.editTimer = null;
    this.pendingThumbnail = null;
    this.canvas = $("view");
    this.view = new MaterialView(this.canvas, { dataUrl: hello.data_url, filesUrl: hello.files_url });
    this.canvas.addEventListener("frame", (event) => this.framed(event.detail));
    this.editor = new Editor($("editor"), {
      onChange: () => this.scheduleEdit(),
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

  scheduleEdit() {
    clearTimeout(this.editTimer);
    this.editTimer = setTimeout(() => this.edit(), EDIT_DELAY_MS);
  }

  async edit() {
    const text = this.editor.text;
    try {
      const analysis = await this.connection.request("edit", { text });
      if (analysis.op !== "skipped") this.apply(analysis, text); // a newer edit replaced it: its answer comes
    } catch (error) {
      fail(error);
    }
  }

  async apply(analysis, text) {
    if (analysis.text !== undefined) {
      this.editor.setText(analysis.text);
      text = analysis.text;
    }
    if (!this.editor.show(analysis, text)) return; // typed on since: the next analysis comes
    status.analyses = String(Number(status.analyses) + 1);
    problem.clear();
    showMaterials($("materials"), analysis.materials);
    const more = $("not-shown");
    more.hidden = !analysis.not_shown;
    more.textContent = analysis.not_shown ? `${analysis.not_shown} more not shown in the view` : "";
    showHistory($("history"), analysis.history);
    $("undo").disabled = !analysis.history.can_undo;
    $("redo").disabled = !analysis.history.can_redo;
    if (!analysis.ok || analysis.payloads.length === 0) return;
    if (analysis.recorded) this.pendingThumbnail = analysis.history.at;
    await this.view.show(analysis.payloads);
    if (text === this.editor.text) status.shown = String(Number(status.shown) + 1);
  }

  framed(detail) {
    $("frame-time").textContent = `${detail.ms.toFixed(1)} ms a frame`;
    if (this.pendingThumbnail === null) return;
    const index = this.pendingThumbnail;
    this.pendingThumbnail = null;
    const image = thumbnail(this.canvas);
    this.connection.send("thumbnail", { index, image });
    const item = $("history").children[index];
    if (item) item.querySelector("img").src = image;
  }

  async refine(words) {
    try {
      this.apply(await this.connection.request("refine", { words }), this.editor.text);
      $("refine").value = "";
    } catch (error) {
      fail(error);
    }
  }

  async step(op) {
    try {
      this.apply(await this.connection.request(op), this.editor.text);
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
