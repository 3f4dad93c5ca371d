// The studio's WebSocket: requests {op, seq, ...} answered by {op, seq, ...}; messages the
// server sends unasked (chips) go to the listeners registered with on(op, fn).

export class Connection {
  constructor(url) {
    this.url = url;
    this.seq = 0;
    this.waiting = new Map(); // seq -> {resolve, reject}
    this.listeners = new Map(); // op -> [fn]
    this.opened = new Promise((resolve, reject) => {
      this.socket = new WebSocket(url);
      this.socket.addEventListener("message", (event) => {
        const arrived = performance.now();
        this.receive(JSON.parse(event.data), { arrived, chars: event.data.length });
      });
      this.socket.addEventListener("error", () => reject(new Error("the studio's server cannot be reached")));
      this.socket.addEventListener("close", () => this.closed());
      this.hello = new Promise((ready) => this.on("hello", ready));
      this.socket.addEventListener("open", () => resolve());
    });
  }

  on(op, fn) {
    if (!this.listeners.has(op)) this.listeners.set(op, []);
    this.listeners.get(op).push(fn);
  }

  request(op, fields = {}) {
    const seq = ++this.seq;
    return new Promise((resolve, reject) => {
      this.waiting.set(seq, { resolve, reject });
      this.socket.send(JSON.stringify({ op, seq, ...fields }));
    });
  }

  send(op, fields = {}) {
    if (this.socket.readyState === WebSocket.OPEN) this.socket.send(JSON.stringify({ op, ...fields }));
  }

  // An answer resolves its request with the message, when it arrived and was parsed
  // (performance.now(): `arrived`, `parsed`) and its length (`chars`), for the page's trace.
  receive(message, { arrived, chars }) {
    const pending = message.seq != null ? this.waiting.get(message.seq) : undefined;
    if (pending) {
      this.waiting.delete(message.seq);
      if (message.op === "error") pending.reject(new Error(message.message));
      else pending.resolve(Object.assign(message, { arrived, chars, parsed: performance.now() }));
      return;
    }
    for (const fn of this.listeners.get(message.op) || []) fn(message);
  }

  closed() {
    for (const { reject } of this.waiting.values()) reject(new Error("the studio's server stopped"));
    this.waiting.clear();
    for (const fn of this.listeners.get("closed") || []) fn();
  }
}
