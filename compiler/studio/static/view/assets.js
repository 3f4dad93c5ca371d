// What the view loads: the server's binary containers (cnlmc.backends.preview.web.pack:
// b"CNLV", uint32 header length, JSON header, 4-byte aligned arrays), named meshes and
// environments, and the float tables inline in a payload (base64 float32).

const DTYPES = { "<f4": Float32Array, "<u4": Uint32Array, "<f2": Uint16Array, "|u1": Uint8Array };

export function unpack(buffer) {
  const bytes = new Uint8Array(buffer);
  const magic = String.fromCharCode(...bytes.slice(0, 4));
  if (magic !== "CNLV") throw new Error("view: not a cnlmc view container");
  const length = new DataView(buffer).getUint32(4, true);
  const header = JSON.parse(new TextDecoder().decode(bytes.slice(8, 8 + length)));
  const base = 8 + length;
  const arrays = {};
  for (const [name, spec] of Object.entries(header.arrays)) {
    const Kind = DTYPES[spec.dtype];
    if (!Kind) throw new Error(`view: unknown dtype ${spec.dtype}`);
    const count = spec.shape.reduce((a, b) => a * b, 1);
    arrays[name] = new Kind(buffer, base + spec.offset, count);
  }
  delete header.arrays;
  return { header, arrays };
}

export async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`view: ${url}: ${response.status} ${response.statusText}`);
  return response.arrayBuffer();
}

export async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`view: ${url}: ${response.status} ${response.statusText}`);
  return response.text();
}

export function decodeFloats(base64) {
  const raw = atob(base64);
  const bytes = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; i++) bytes[i] = raw.charCodeAt(i);
  return new Float32Array(bytes.buffer);
}

// A mesh as the view draws it: 11 floats a vertex (position, normal, tangent, uv), triangles,
// bounds, bounding sphere (the glass's second interface) and whether it is closed.
export function meshFromContainer(buffer) {
  const { header, arrays } = unpack(buffer);
  return { ...header, vertices: arrays.vertices, indices: arrays.indices };
}

// An environment from the server: the image, the preview's prefiltered levels 1..5 and its
// irradiance map (float16 RGBA), made by the preview's own passes.
export function environmentFromContainer(buffer) {
  const { header, arrays } = unpack(buffer);
  const levels = [];
  for (let k = 1; arrays[`level${k}`]; k++) levels.push(arrays[`level${k}`]);
  return { ...header, image: arrays.image, levels, irradiance: arrays.irradiance };
}
