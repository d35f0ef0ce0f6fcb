// Meshes and matrices of hexc edit's views. World space is z up; every mesh carries position, normal, tangent (w: the
// bitangent's sign, cross(N, T) * w along +v) and texture coordinate, as the vertex stage (templates/edit) reads them.

function mesh() {
  return { positions: [], normals: [], tangents: [], uvs: [], indices: [] };
}

function vertex(m, p, n, t, uv) {
  m.positions.push(...p);
  m.normals.push(...n);
  m.tangents.push(...t);
  m.uvs.push(...uv);
}

// The plane z = 0 from -extent to extent, uv = (x, y): tangent +x, bitangent +y.
export function plane(extent) {
  const m = mesh();
  for (const [x, y] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) vertex(m, [x * extent, y * extent, 0], [0, 0, 1], [1, 0, 0, 1], [x * extent, y * extent]);
  m.indices.push(0, 1, 2, 0, 2, 3);
  return m;
}

// The unit sphere; u runs 4 units around the equator and v 2 from pole to pole (v down, north first), so that a texel
// is about square at the equator.
export function sphere(rings = 48, segments = 96) {
  const m = mesh();
  for (let i = 0; i <= rings; ++i) {
    const v = i / rings, lat = Math.PI / 2 - v * Math.PI;
    for (let j = 0; j <= segments; ++j) {
      const u = j / segments, lon = u * 2 * Math.PI;
      const p = [Math.cos(lat) * Math.cos(lon), Math.cos(lat) * Math.sin(lon), Math.sin(lat)];
      // cross(N, T) points north, against +v: the sign is -1.
      vertex(m, p, p, [-Math.sin(lon), Math.cos(lon), 0, -1], [u * 4, v * 2]);
    }
  }
  for (let i = 0; i < rings; ++i)
    for (let j = 0; j < segments; ++j) {
      const a = i * (segments + 1) + j, b = a + segments + 1;
      m.indices.push(a, b, a + 1, a + 1, b, b + 1);
    }
  return m;
}

const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

// The cube from -1 to 1, each face's uv running 2 units along its tangent and bitangent.
export function cube() {
  const m = mesh();
  const faces = [[[1, 0, 0], [0, 1, 0]], [[-1, 0, 0], [0, -1, 0]], [[0, 1, 0], [-1, 0, 0]], [[0, -1, 0], [1, 0, 0]],
                 [[0, 0, 1], [1, 0, 0]], [[0, 0, -1], [-1, 0, 0]]];
  for (const [n, t] of faces) {
    const b = cross(n, t).map(c => -c);  // v runs down each face, as in a texture
    const base = m.positions.length / 3;
    for (const [s, r] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
      const p = [0, 1, 2].map(k => n[k] + s * t[k] + r * b[k]);
      vertex(m, p, n, [...t, Math.sign(dot(cross(n, t), b))], [s + 1, r + 1]);
    }
    m.indices.push(base, base + 1, base + 2, base, base + 2, base + 3);
  }
  return m;
}

// A full-screen rectangle for the texture-space view: position (u, v, 0), as `hexc render` shows a material.
export function flat(rect) {
  const m = mesh();
  const [u0, v0, u1, v1] = rect;
  for (const [u, v] of [[u0, v0], [u1, v0], [u1, v1], [u0, v1]]) vertex(m, [u, v, 0], [0, 0, 1], [1, 0, 0, 1], [u, v]);
  m.indices.push(0, 1, 2, 0, 2, 3);
  return m;
}

// Column-major 4x4 matrices, as WebGL takes them.
export function multiply(a, b) {
  const out = new Float32Array(16);
  for (let c = 0; c < 4; ++c)
    for (let r = 0; r < 4; ++r) {
      let s = 0;
      for (let k = 0; k < 4; ++k) s += a[k * 4 + r] * b[c * 4 + k];
      out[c * 4 + r] = s;
    }
  return out;
}

export function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2);
  return new Float32Array([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1, 0, 0, 2 * far * near / (near - far), 0]);
}

export function lookAt(eye, target, up) {
  const sub = (a, b) => a.map((x, i) => x - b[i]);
  const norm = a => { const l = Math.hypot(...a); return a.map(x => x / l); };
  const z = norm(sub(eye, target)), x = norm(cross(up, z)), y = cross(z, x);
  return new Float32Array([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0, -dot(x, eye), -dot(y, eye), -dot(z, eye), 1]);
}

// Maps the uv rectangle to the viewport with v0 on the top row, as `hexc render` does.
export function flatProjection(rect) {
  const [u0, v0, u1, v1] = rect;
  const sx = 2 / (u1 - u0), sy = -2 / (v1 - v0);
  return new Float32Array([sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, 1, 0, -1 - u0 * sx, 1 - v0 * sy, 0, 1]);
}

// The rotation (column-major 3x3) that turns direction `from` onto `to`, both unit vectors (Rodrigues).
export function rotationBetween(from, to) {
  const v = cross(from, to), c = dot(from, to);
  if (c < -0.999999) return new Float32Array([-1, 0, 0, 0, 1, 0, 0, 0, -1]);  // opposite: half a turn about y
  const k = 1 / (1 + c);
  const m = [[v[0] * v[0] * k + c, v[0] * v[1] * k - v[2], v[0] * v[2] * k + v[1]],
             [v[1] * v[0] * k + v[2], v[1] * v[1] * k + c, v[1] * v[2] * k - v[0]],
             [v[2] * v[0] * k - v[1], v[2] * v[1] * k + v[0], v[2] * v[2] * k + c]];
  return new Float32Array([m[0][0], m[1][0], m[2][0], m[0][1], m[1][1], m[2][1], m[0][2], m[1][2], m[2][2]]);
}
