// Small geometry helpers of the viewer (typed arrays, no allocation per vertex).

/** Area-weighted vertex normals of an indexed triangle mesh into `normals`. */
export function computeVertexNormals(positions, indices, normals) {
  normals.fill(0);
  for (let f = 0; f < indices.length; f += 3) {
    const a = indices[f] * 3, b = indices[f + 1] * 3, c = indices[f + 2] * 3;
    const ux = positions[b] - positions[a], uy = positions[b + 1] - positions[a + 1],
      uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a], vy = positions[c + 1] - positions[a + 1],
      vz = positions[c + 2] - positions[a + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    normals[a] += nx; normals[a + 1] += ny; normals[a + 2] += nz;
    normals[b] += nx; normals[b + 1] += ny; normals[b + 2] += nz;
    normals[c] += nx; normals[c + 1] += ny; normals[c + 2] += nz;
  }
  for (let i = 0; i < normals.length; i += 3) {
    const length = Math.hypot(normals[i], normals[i + 1], normals[i + 2]);
    if (length > 0) {
      normals[i] /= length; normals[i + 1] /= length; normals[i + 2] /= length;
    }
  }
}

/** Position of vertex `v` at `u` in [0, 1] between `x0` and `x1` (x1 alone if no x0). */
export function interpolated(x0, x1, v, u, out = [0, 0, 0]) {
  for (let c = 0; c < 3; ++c) {
    const end = x1[3 * v + c];
    out[c] = x0 ? x0[3 * v + c] + u * (end - x0[3 * v + c]) : end;
  }
  return out;
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const clamp01 = (x) => Math.min(1, Math.max(0, x));

/** Midpoint of the closest points of segments p0p1 and q0q1 (where two edges touch). */
export function segmentContactPoint(p0, p1, q0, q1) {
  const d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
  const a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  let s = 0, t = 0;
  if (a <= 1e-30 && e <= 1e-30) {
    s = t = 0;
  } else if (a <= 1e-30) {
    t = clamp01(f / e);
  } else {
    const c = dot(d1, r);
    if (e <= 1e-30) {
      s = clamp01(-c / a);
    } else {
      const b = dot(d1, d2), denominator = a * e - b * b;
      s = denominator > 1e-30 * a * e ? clamp01((b * f - c * e) / denominator) : 0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0; s = clamp01(-c / a);
      } else if (t > 1) {
        t = 1; s = clamp01((b - c) / a);
      }
    }
  }
  const result = [0, 0, 0];
  for (let i = 0; i < 3; ++i) result[i] = 0.5 * (p0[i] + s * d1[i] + q0[i] + t * d2[i]);
  return result;
}
