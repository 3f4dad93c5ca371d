// Dropped files: a mesh (Wavefront OBJ, or binary glTF .glb: the first mesh's triangle
// primitives) and an environment (Radiance .hdr, RGBE run-length encoded). A mesh is fitted as
// the preview fits one (backends/preview/meshes.fit: unit bounding sphere about the box centre,
// standing on y = 0); missing normals are the faces' area-weighted sum, missing UVs spherical,
// tangents follow +U (Gram-Schmidt against the normal).

function fitted(positions, normals, uvs, indices) {
  const n = positions.length / 3;
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < n; i++) for (let k = 0; k < 3; k++) {
    lo[k] = Math.min(lo[k], positions[3 * i + k]);
    hi[k] = Math.max(hi[k], positions[3 * i + k]);
  }
  const c = lo.map((l, k) => (l + hi[k]) / 2);
  let r = 0;
  for (let i = 0; i < n; i++) {
    r = Math.max(r, Math.hypot(positions[3 * i] - c[0], positions[3 * i + 1] - c[1], positions[3 * i + 2] - c[2]));
  }
  r = r || 1;
  const pos = new Float32Array(positions.length);
  for (let i = 0; i < n; i++) for (let k = 0; k < 3; k++) pos[3 * i + k] = (positions[3 * i + k] - c[k]) / r;
  const floor = (lo[1] - c[1]) / r;
  for (let i = 0; i < n; i++) pos[3 * i + 1] -= floor;
  normals = normals || faceNormals(pos, indices);
  uvs = uvs || sphericalUvs(pos);
  const tangents = uvTangents(pos, normals, uvs, indices);
  const vertices = new Float32Array(n * 11);
  for (let i = 0; i < n; i++) {
    vertices.set(pos.subarray(3 * i, 3 * i + 3), 11 * i);
    vertices.set(normals.subarray(3 * i, 3 * i + 3), 11 * i + 3);
    vertices.set(tangents.subarray(3 * i, 3 * i + 3), 11 * i + 6);
    vertices.set(uvs.subarray(2 * i, 2 * i + 2), 11 * i + 9);
  }
  const blo = [0, 1, 2].map((k) => (lo[k] - c[k]) / r - (k === 1 ? floor : 0));
  const bhi = [0, 1, 2].map((k) => (hi[k] - c[k]) / r - (k === 1 ? floor : 0));
  const centre = [(blo[0] + bhi[0]) / 2, (blo[1] + bhi[1]) / 2, (blo[2] + bhi[2]) / 2];
  return { vertices, indices, lo: blo, hi: bhi, centre, radius: 1, closed: false };
}

function faceNormals(pos, indices) {
  const out = new Float32Array(pos.length);
  for (let t = 0; t < indices.length; t += 3) {
    const [a, b, c] = [indices[t], indices[t + 1], indices[t + 2]];
    const e1 = [0, 1, 2].map((k) => pos[3 * b + k] - pos[3 * a + k]);
    const e2 = [0, 1, 2].map((k) => pos[3 * c + k] - pos[3 * a + k]);
    const f = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    for (const v of [a, b, c]) for (let k = 0; k < 3; k++) out[3 * v + k] += f[k];
  }
  return normalizeAll(out);
}

function normalizeAll(v) {
  for (let i = 0; i < v.length; i += 3) {
    const len = Math.hypot(v[i], v[i + 1], v[i + 2]) || 1;
    v[i] /= len; v[i + 1] /= len; v[i + 2] /= len;
  }
  return v;
}

function sphericalUvs(pos) {
  const n = pos.length / 3, out = new Float32Array(2 * n);
  for (let i = 0; i < n; i++) {
    const len = Math.hypot(pos[3 * i], pos[3 * i + 1] - 0.5, pos[3 * i + 2]) || 1;
    out[2 * i] = 0.5 + Math.atan2(pos[3 * i], pos[3 * i + 2]) / (2 * Math.PI);
    out[2 * i + 1] = Math.acos(Math.max(-1, Math.min(1, (pos[3 * i + 1] - 0.5) / len))) / Math.PI;
  }
  return out;
}

function uvTangents(pos, normals, uvs, indices) {
  const out = new Float32Array(pos.length);
  for (let t = 0; t < indices.length; t += 3) {
    const [a, b, c] = [indices[t], indices[t + 1], indices[t + 2]];
    const e1 = [0, 1, 2].map((k) => pos[3 * b + k] - pos[3 * a + k]);
    const e2 = [0, 1, 2].map((k) => pos[3 * c + k] - pos[3 * a + k]);
    const du1 = uvs[2 * b] - uvs[2 * a], dv1 = uvs[2 * b + 1] - uvs[2 * a + 1];
    const du2 = uvs[2 * c] - uvs[2 * a], dv2 = uvs[2 * c + 1] - uvs[2 * a + 1];
    const det = du1 * dv2 - du2 * dv1;
    if (Math.abs(det) < 1e-12) continue;
    for (const v of [a, b, c]) for (let k = 0; k < 3; k++) out[3 * v + k] += (e1[k] * dv2 - e2[k] * dv1) / det;
  }
  for (let i = 0; i < out.length; i += 3) {
    const nrm = normals.subarray(i, i + 3);
    const d = out[i] * nrm[0] + out[i + 1] * nrm[1] + out[i + 2] * nrm[2];
    for (let k = 0; k < 3; k++) out[i + k] -= nrm[k] * d;
    if (Math.hypot(out[i], out[i + 1], out[i + 2]) < 1e-8) {
      const other = Math.abs(nrm[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
      const dd = other[0] * nrm[0] + other[1] * nrm[1] + other[2] * nrm[2];
      for (let k = 0; k < 3; k++) out[i + k] = other[k] - nrm[k] * dd;
    }
  }
  return normalizeAll(out);
}

function parseObj(text) {
  const v = [], vt = [], vn = [], positions = [], uvs = [], normals = [], indices = [];
  const seen = new Map();
  let hasUv = true, hasNormal = true;
  const vertex = (token) => {
    if (seen.has(token)) return seen.get(token);
    const [pi, ti, ni] = token.split("/").map((s) => (s ? parseInt(s, 10) : 0));
    const p = (pi > 0 ? pi - 1 : v.length / 3 + pi) * 3;
    positions.push(v[p], v[p + 1], v[p + 2]);
    if (ti) { const t = (ti > 0 ? ti - 1 : vt.length / 2 + ti) * 2; uvs.push(vt[t], vt[t + 1]); } else hasUv = false;
    if (ni) { const q = (ni > 0 ? ni - 1 : vn.length / 3 + ni) * 3; normals.push(vn[q], vn[q + 1], vn[q + 2]); } else hasNormal = false;
    const index = positions.length / 3 - 1;
    seen.set(token, index);
    return index;
  };
  for (const line of text.split("\n")) {
    const parts = line.trim().split(/\s+/);
    if (parts[0] === "v") v.push(+parts[1], +parts[2], +parts[3]);
    else if (parts[0] === "vt") vt.push(+parts[1], +parts[2]);
    else if (parts[0] === "vn") vn.push(+parts[1], +parts[2], +parts[3]);
    else if (parts[0] === "f") {
      const face = parts.slice(1).map(vertex);
      for (let i = 1; i + 1 < face.length; i++) indices.push(face[0], face[i], face[i + 1]);
    }
  }
  if (!indices.length) throw new Error("view: the OBJ file has no faces");
  return fitted(new Float32Array(positions), hasNormal ? new Float32Array(normals) : null,
    hasUv ? new Float32Array(uvs) : null, new Uint32Array(indices));
}

function parseGlb(buffer) {
  const view = new DataView(buffer);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 20, jsonLength)));
  const binStart = 20 + jsonLength + 8;
  const read = (index, Kind, size) => {
    const acc = json.accessors[index], bv = json.bufferViews[acc.bufferView];
    const offset = binStart + (bv.byteOffset || 0) + (acc.byteOffset || 0);
    const stride = bv.byteStride || 0;
    const count = acc.count * size;
    if (!stride) return new Kind(buffer.slice(offset, offset + count * Kind.BYTES_PER_ELEMENT));
    const out = new Kind(count), step = stride / Kind.BYTES_PER_ELEMENT;
    const src = new Kind(buffer.slice(offset, offset + acc.count * stride));
    for (let i = 0; i < acc.count; i++) for (let k = 0; k < size; k++) out[i * size + k] = src[i * step + k];
    return out;
  };
  const indexKinds = { 5121: Uint8Array, 5123: Uint16Array, 5125: Uint32Array };
  const positions = [], normals = [], uvs = [], indices = [];
  let hasNormal = true, hasUv = true;
  for (const prim of json.meshes[0].primitives) {
    if ((prim.mode ?? 4) !== 4) continue;
    const base = positions.length / 3;
    const p = read(prim.attributes.POSITION, Float32Array, 3);
    positions.push(...p);
    if (prim.attributes.NORMAL !== undefined) normals.push(...read(prim.attributes.NORMAL, Float32Array, 3)); else hasNormal = false;
    if (prim.attributes.TEXCOORD_0 !== undefined) {
      const t = read(prim.attributes.TEXCOORD_0, Float32Array, 2);
      for (let i = 0; i < t.length; i += 2) uvs.push(t[i], 1 - t[i + 1]); // glTF v down -> the preview's v up
    } else hasUv = false;
    if (prim.indices !== undefined) {
      const kind = indexKinds[json.accessors[prim.indices].componentType];
      for (const i of read(prim.indices, kind, 1)) indices.push(base + i);
    } else for (let i = 0; i < p.length / 3; i++) indices.push(base + i);
  }
  if (!indices.length) throw new Error("view: the glTF file has no triangles");
  return fitted(new Float32Array(positions), hasNormal ? new Float32Array(normals) : null,
    hasUv ? new Float32Array(uvs) : null, new Uint32Array(indices));
}

// A dropped mesh file's bytes -> the view's mesh.
export function meshFromFile(buffer) {
  const head = new Uint8Array(buffer, 0, Math.min(4, buffer.byteLength));
  if (String.fromCharCode(...head) === "glTF") return parseGlb(buffer);
  const text = new TextDecoder().decode(buffer);
  if (text.trimStart().startsWith("{")) {
    throw new Error("view: a .gltf is not read here (its buffers are separate files): drop a .glb or an .obj");
  }
  return parseObj(text);
}

// A dropped Radiance .hdr (a File or ArrayBuffer) -> an environment like the named ones, with
// `like`'s key light and passes.
export async function environmentFromFile(file, like) {
  const buffer = file instanceof ArrayBuffer ? file : await file.arrayBuffer();
  const bytes = new Uint8Array(buffer);
  let pos = 0;
  const line = () => {
    let s = "";
    while (pos < bytes.length && bytes[pos] !== 10) s += String.fromCharCode(bytes[pos++]);
    pos++;
    return s;
  };
  if (!line().startsWith("#?")) throw new Error("view: only Radiance .hdr environments can be dropped here");
  let size = "";
  for (let l = line(); pos < bytes.length; l = line()) {
    if (/^[-+][YX] \d+ [-+][YX] \d+/.test(l)) { size = l; break; }
  }
  const m = size.match(/-Y (\d+) \+X (\d+)/);
  if (!m) throw new Error("view: this .hdr's orientation is not supported (-Y h +X w)");
  const height = +m[1], width = +m[2];
  const image = new Float32Array(width * height * 4);
  const scan = new Uint8Array(width * 4);
  for (let y = 0; y < height; y++) {
    if (bytes[pos] === 2 && bytes[pos + 1] === 2) {
      pos += 4;
      for (let c = 0; c < 4; c++) for (let x = 0; x < width;) {
        let count = bytes[pos++];
        if (count > 128) { count -= 128; const v = bytes[pos++]; while (count--) scan[4 * x++ + c] = v; }
        else while (count--) scan[4 * x++ + c] = bytes[pos++];
      }
    } else { scan.set(bytes.subarray(pos, pos + 4 * width)); pos += 4 * width; }
    for (let x = 0; x < width; x++) {
      const e = scan[4 * x + 3], f = e ? 2 ** (e - 136) : 0, o = 4 * (y * width + x);
      image[o] = scan[4 * x] * f; image[o + 1] = scan[4 * x + 1] * f; image[o + 2] = scan[4 * x + 2] * f; image[o + 3] = 1;
    }
  }
  return { ...like, name: file.name || "dropped", width, height, image };
}
