// The preview's camera (backends/preview/camera.py: framing_camera, look_at, perspective) as
// row-major 4x4 matrices (arrays of 16 numbers), and an orbit around the framed object.

const DEG = Math.PI / 180;

function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function unit(a) { const n = Math.hypot(a[0], a[1], a[2]); return [a[0] / n, a[1] / n, a[2] / n]; }
function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

export function lookAt(eye, target, up = [0, 1, 0]) {
  const f = unit(sub(target, eye));
  const s = unit(cross(f, up));
  const u = cross(s, f);
  return [
    s[0], s[1], s[2], -dot(s, eye),
    u[0], u[1], u[2], -dot(u, eye),
    -f[0], -f[1], -f[2], dot(f, eye),
    0, 0, 0, 1,
  ];
}

export function perspective(fovY, aspect, near, far) {
  const f = 1 / Math.tan((fovY * DEG) / 2);
  return [
    f / aspect, 0, 0, 0,
    0, f, 0, 0,
    0, 0, (far + near) / (near - far), (2 * far * near) / (near - far),
    0, 0, -1, 0,
  ];
}

export function multiply(a, b) {
  const out = new Array(16).fill(0);
  for (let r = 0; r < 4; r++) for (let c = 0; c < 4; c++) {
    let s = 0;
    for (let k = 0; k < 4; k++) s += a[r * 4 + k] * b[k * 4 + c];
    out[r * 4 + c] = s;
  }
  return out;
}

// Inverse of a row-major 4x4 (Gauss-Jordan with partial pivoting).
export function invert(m) {
  const a = [];
  for (let r = 0; r < 4; r++) a.push([...m.slice(r * 4, r * 4 + 4), ...[0, 1, 2, 3].map((c) => (c === r ? 1 : 0))]);
  for (let c = 0; c < 4; c++) {
    let p = c;
    for (let r = c + 1; r < 4; r++) if (Math.abs(a[r][c]) > Math.abs(a[p][c])) p = r;
    [a[c], a[p]] = [a[p], a[c]];
    const d = a[c][c];
    for (let k = 0; k < 8; k++) a[c][k] /= d;
    for (let r = 0; r < 4; r++) if (r !== c) {
      const f = a[r][c];
      for (let k = 0; k < 8; k++) a[r][k] -= f * a[c][k];
    }
  }
  return a.flatMap((row) => row.slice(4));
}

// The orbit: azimuth and elevation (degrees) around the framed bounding sphere, and a zoom.
export class Orbit {
  constructor() {
    this.azimuth = 0;
    this.elevation = 18; // camera.framing_camera's default
    this.zoom = 1;
    this.fovY = 30;
    this.margin = 1.08;
  }

  // {eye, viewProjection} for the box [lo, hi] seen in a viewport of this aspect (framing_camera).
  camera(lo, hi, aspect) {
    const centre = [0, 1, 2].map((i) => (lo[i] + hi[i]) / 2);
    const radius = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2;
    let half = (this.fovY * DEG) / 2;
    if (aspect < 1) half = Math.atan(Math.tan(half) * aspect);
    const distance = ((radius * this.margin) / Math.sin(half)) * this.zoom;
    const el = this.elevation * DEG, az = this.azimuth * DEG;
    const dir = [Math.cos(el) * Math.sin(az), Math.sin(el), Math.cos(el) * Math.cos(az)];
    const eye = centre.map((c, i) => c + dir[i] * distance);
    const viewProjection = multiply(perspective(this.fovY, aspect, 0.05, 100), lookAt(eye, centre));
    return { eye, viewProjection };
  }

  // Mouse drag turns, the wheel zooms; `changed()` is called to redraw.
  attach(canvas, changed) {
    let last = null;
    canvas.addEventListener("pointerdown", (e) => { last = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
    canvas.addEventListener("pointerup", () => { last = null; });
    canvas.addEventListener("pointermove", (e) => {
      if (!last) return;
      this.azimuth -= (e.clientX - last[0]) * 0.4;
      this.elevation = Math.min(85, Math.max(-85, this.elevation + (e.clientY - last[1]) * 0.4));
      last = [e.clientX, e.clientY];
      changed();
    });
    canvas.addEventListener("wheel", (e) => {
      e.preventDefault();
      this.zoom = Math.min(4, Math.max(0.4, this.zoom * Math.exp(e.deltaY * 0.001)));
      changed();
    }, { passive: false });
  }
}
