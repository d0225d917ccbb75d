// Loads the data scripts `tailor view` writes (data/scene.js, data/frame_NNNN.js). They are
// classic scripts calling tailorViewData.scene(...) / tailorViewData.frame(k, ...), because
// from file:// Chromium refuses fetch() and module imports of local files but runs
// <script src> tags.

const received = { scene: null, frames: new Map() };
const data = (window.tailorViewData = window.tailorViewData || {});
data.scene = (scene) => {
  received.scene = scene;
};
data.frame = (k, frame) => {
  received.frames.set(k, frame);
};

function loadScript(src) {
  return new Promise((resolve, reject) => {
    const script = document.createElement('script');
    script.src = src;
    script.onload = () => {
      script.remove();
      resolve();
    };
    script.onerror = () => {
      script.remove();
      reject(new Error(`cannot load ${src} (is the folder complete?)`));
    };
    document.head.appendChild(script);
  });
}

/** Bytes of a base64 string (native decoder where the browser has one). */
export function decodeBase64(text) {
  if (typeof Uint8Array.fromBase64 === 'function') return Uint8Array.fromBase64(text);
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

// The data is little-endian, as is every platform browsers run on.
function float32(text) {
  const bytes = decodeBase64(text);
  return new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4);
}
export function uint32(text) {
  const bytes = decodeBase64(text);
  return new Uint32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4);
}

/** Loads and decodes data/scene.js. */
export async function loadScene() {
  await loadScript('data/scene.js');
  const scene = received.scene;
  if (!scene || scene.format !== 1) throw new Error('data/scene.js: not a tailor view scene');
  scene.cloth.indices = uint32(scene.cloth.indices);
  if (scene.arm) scene.arm.indices = uint32(scene.arm.indices);
  if (scene.clusters) scene.clusters = uint32(scene.clusters);
  return scene;
}

function pad4(k) {
  return String(k).padStart(4, '0');
}

/**
 * Frames by number, loaded on demand and kept while they fit in `budgetBytes` (the least
 * recently used go first), so long runs of large meshes play without exhausting memory.
 */
export class FrameStore {
  constructor(scene, budgetBytes = 768 * 1024 * 1024) {
    this.scene = scene;
    this.budget = budgetBytes;
    this.cache = new Map(); // k -> Promise<frame>, in use order
    this.bytes = new Map(); // k -> decoded size
  }

  get(k) {
    let entry = this.cache.get(k);
    if (entry) {
      this.cache.delete(k); // move to the back (most recently used)
      this.cache.set(k, entry);
      return entry;
    }
    entry = this.load(k);
    this.cache.set(k, entry);
    entry.catch(() => this.cache.delete(k));
    return entry;
  }

  async load(k) {
    await loadScript(`data/frame_${pad4(k)}.js`);
    const raw = received.frames.get(k);
    received.frames.delete(k);
    if (!raw) throw new Error(`data/frame_${pad4(k)}.js: no frame ${k} in it`);
    const frame = {
      index: k,
      cloth: float32(raw.cloth),
      arm: raw.arm ? float32(raw.arm) : null,
      contacts: null,
    };
    if (raw.contacts) {
      const c = raw.contacts;
      frame.contacts = {
        ...c,
        candidates: uint32(c.candidates),
        vertex_face: uint32(c.vertex_face), // (vertex, face, substep) per pair
        vertex_face_toi: float32(c.vertex_face_toi),
        edge_edge: uint32(c.edge_edge), // (a0, a1, b0, b1, substep) per pair
        edge_edge_toi: float32(c.edge_edge_toi),
      };
    }
    this.bytes.set(k, frame.cloth.byteLength + (frame.arm ? frame.arm.byteLength : 0));
    this.evict(k);
    return frame;
  }

  evict(keep) {
    let total = 0;
    for (const size of this.bytes.values()) total += size;
    for (const k of this.cache.keys()) {
      if (total <= this.budget) break;
      if (k === keep || !this.bytes.has(k)) continue;
      total -= this.bytes.get(k);
      this.bytes.delete(k);
      this.cache.delete(k);
    }
  }
}
