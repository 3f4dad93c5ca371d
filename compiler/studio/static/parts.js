// The parts of view payloads this page has been sent (compiler/studio/payloads.py, SentParts): a
// payload's shader (vertex, fragment) and tables come once, then by key alone. Both sides keep the
// `size` most recently named parts, counted in the same order (every analysis, as it arrives), so
// they agree on what the page holds; a payload naming a part the page lacks asks for it again.

export class PayloadParts {
  constructor(size) {
    this.size = size;
    this.parts = new Map(); // key -> part, the most recently named last
  }

  // The payloads of an analysis made whole; null when one names a part this page does not hold
  // (then ask again with `fresh`: the server sends every part, and both sides start empty).
  complete(payloads) {
    let whole = true;
    const out = payloads.map((payload) => {
      if (payload.shader === undefined) return payload; // sent whole, without keys
      const source = payload.vertex === undefined ? undefined : { vertex: payload.vertex, fragment: payload.fragment };
      const shader = this.named(payload.shader, source);
      const tables = {};
      for (const [name, table] of Object.entries(payload.tables)) {
        const data = this.named(table.key, table.data);
        whole &&= data !== undefined;
        tables[name] = { ...table, data };
      }
      whole &&= shader !== undefined;
      return { ...payload, ...shader, tables };
    });
    if (!whole) this.parts.clear();
    return whole ? out : null;
  }

  // The part `key` (given now as `value`, or held from before), now the most recently named.
  named(key, value) {
    const part = value === undefined ? this.parts.get(key) : value;
    this.parts.delete(key);
    this.parts.set(key, part);
    while (this.parts.size > this.size) this.parts.delete(this.parts.keys().next().value);
    return part;
  }
}
