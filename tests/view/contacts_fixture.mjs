// Writes per-frame contact files (contacts_NNNN.json, clusters.json) into a `tailor
// simulate` output folder, in the format `tailor simulate` writes them (docs/viewer.md),
// for testing the viewer's overlays while the simulation does not write them yet. The
// contents are made up but valid: real face and vertex ids of the cloth, every frame's
// candidate faces different, a few vertex-face and edge-edge pairs, one observer.

import { readFileSync, writeFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';

const pad4 = (k) => String(k).padStart(4, '0');

function readObj(path) {
  const vertices = [], faces = [];
  for (const line of readFileSync(path, 'utf8').split('\n')) {
    const parts = line.trim().split(/\s+/);
    if (parts[0] === 'v') vertices.push(parts.slice(1, 4).map(Number));
    if (parts[0] === 'f') faces.push(parts.slice(1, 4).map((p) => Number(p.split('/')[0]) - 1));
  }
  return { vertices, faces };
}

/** Writes the fixture for frames 1.. of `dir`; returns the number of frames with contacts. */
export function writeContactsFixture(dir, { substeps = 5, clusters = 4 } = {}) {
  let frames = 0;
  while (existsSync(join(dir, `cloth_${pad4(frames)}.obj`))) ++frames;
  for (let k = 1; k < frames; ++k) {
    const { vertices, faces } = readObj(join(dir, `cloth_${pad4(k)}.obj`));
    const candidates = faces.map((_, f) => f).filter((f) => f % 4 === k % 4);
    const vertexFace = [0, 1, 2].map((i) => {
      const face = (37 * (k + i)) % faces.length;
      const vertex = [...Array(vertices.length).keys()].find((v) => !faces[face].includes(v) &&
        v >= (11 * i) % vertices.length);
      return [vertex, face, i % substeps, 0.25 * (i + 1)];
    });
    const edgeEdge = [1, 2].map((i) => {
      const [a0, a1] = faces[(53 * (k + i)) % faces.length].slice(0, 2).sort((x, y) => x - y);
      const [b0, b1] = faces[(97 * (k + i)) % faces.length].slice(1, 3).sort((x, y) => x - y);
      return [a0, a1, b0, b1, (k + i) % substeps, 0.5];
    });
    const center = [0, 1, 2].map((c) => vertices.reduce((s, v) => s + v[c], 0) / vertices.length);
    writeFileSync(join(dir, `contacts_${pad4(k)}.json`), JSON.stringify({
      frame: k, candidate_triangles: candidates, vertex_face: vertexFace, edge_edge: edgeEdge,
      observers: [center], substeps }));
  }
  const { faces } = readObj(join(dir, 'cloth_0000.obj'));
  writeFileSync(join(dir, 'clusters.json'), JSON.stringify({
    cluster_of_face: faces.map((_, f) => Math.floor((f * clusters) / faces.length)) }));
  return frames - 1;
}
