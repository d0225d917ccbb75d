// The page of `tailor view`: wires the data, the three.js view, the timeline, the toggles
// and the statistics panel, and exposes window.tailorViewer for tests and measurements.

import { FrameStore, loadScene } from './data_loader.js';
import { SceneView } from './scene_view.js';
import { StatsPanel } from './stats_panel.js';
import { classifyPixels } from './pixel_classes.js';

const $ = (id) => document.getElementById(id);
const api = (window.tailorViewer = { ready: false, error: null, timing: {}, framesShown: 0 });

function showMessage(text, kind) {
  const box = $('message');
  box.textContent = text;
  box.className = `box ${kind}`;
}

function fail(error) {
  api.error = String(error && error.message ? error.message : error);
  showMessage(`error: ${api.error}`, 'error');
  console.error(error);
}

const TOGGLES = [
  { name: 'arm', label: 'arm', color: '#d9a27c' },
  { name: 'candidates', label: 'triangles in candidate pairs', color: '#ff0000' },
  { name: 'collisions', label: 'colliding VF / EE at time of impact', color: '#ffd000' },
  { name: 'clusters', label: 'radial-view clusters', color: 'linear-gradient(90deg,#e55,#5e5,#55e)' },
  { name: 'observers', label: 'radial-view observers', color: '#00e5ff' },
];

function buildToggles(scene, view) {
  const anyContacts = scene.has_contacts.some((x) => x);
  const available = {
    arm: !!scene.arm,
    candidates: anyContacts,
    collisions: anyContacts,
    clusters: !!scene.clusters,
    observers: anyContacts && scene.kind === 'simulation',
  };
  const why = {
    arm: 'no arm in this output',
    candidates: 'no contact data (contacts_NNNN.json) in this output',
    collisions: 'no contact data (contacts_NNNN.json) in this output',
    clusters: 'no clusters.json in this output',
    observers: 'no contact data (contacts_NNNN.json) in this output',
  };
  const inputs = {};
  for (const toggle of TOGGLES) {
    const label = document.createElement('label');
    const input = document.createElement('input');
    input.type = 'checkbox';
    input.id = `show-${toggle.name}`;
    input.disabled = !available[toggle.name];
    input.checked = available[toggle.name] && view.visible[toggle.name];
    input.addEventListener('change', () => view.setVisible(toggle.name, input.checked));
    view.visible[toggle.name] = input.checked;
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = toggle.color;
    label.append(input, swatch, toggle.label);
    if (input.disabled) {
      label.className = 'disabled';
      label.title = why[toggle.name];
    }
    $('toggles').append(label);
    inputs[toggle.name] = input;
  }
  view.applyVisibility();
  return inputs;
}

function contactsSummary(frame, scene) {
  const c = frame.contacts;
  if (!c) {
    return frame.index === 0 ? 'initial state (no step ends here)' : 'no contact data for this frame';
  }
  return `${c.candidate_count} candidate triangles, ${c.vertex_face_count} VF and ` +
    `${c.edge_edge_count} EE collisions` +
    (scene.kind === 'simulation'
      ? ` in ${c.substeps} substeps, ${c.observers.length} observer${c.observers.length === 1 ? '' : 's'}`
      : '');
}

async function main() {
  const scene = await loadScene();
  api.timing.sceneLoadedMs = performance.now();
  document.title = `tailor view: ${scene.title}`;
  $('source').textContent = `${scene.kind}: ${scene.title}`;
  $('counts').textContent = `cloth ${scene.cloth.vertices} vertices, ${scene.cloth.faces} faces` +
    (scene.arm ? `; arm ${scene.arm.faces} faces` : '');

  const store = new FrameStore(scene);
  const view = new SceneView($('canvas'), scene);
  const stats = new StatsPanel($('plots'), $('stats-table'), scene.stats, scene.frames);
  const toggles = buildToggles(scene, view);
  const slider = $('frame');
  slider.max = String(scene.frames - 1);

  let requested = 0, shown = -1;
  const waiting = new Map(); // frame -> resolvers of whenShown
  const label = (k) => `frame ${k} / ${scene.frames - 1}`;

  async function setFrame(k) {
    k = Math.max(0, Math.min(scene.frames - 1, Math.round(k)));
    requested = k;
    slider.value = String(k);
    $('frame-label').textContent = label(k);
    const start = performance.now();
    const needsPrevious = k > 0 && scene.has_contacts[k];
    const [frame, previous] = await Promise.all([store.get(k), needsPrevious ? store.get(k - 1) : null]);
    if (requested !== k) return false; // a later request took over
    view.showFrame(frame, previous);
    stats.show(k);
    $('contacts-summary').textContent = contactsSummary(frame, scene);
    shown = k;
    ++api.framesShown;
    api.timing.lastFrameMs = performance.now() - start;
    for (const resolve of waiting.get(k) || []) resolve();
    waiting.delete(k);
    if (k + 1 < scene.frames) store.get(k + 1).catch(() => {}); // prefetch
    return true;
  }
  const guarded = (k) => setFrame(k).catch(fail);

  slider.addEventListener('input', () => guarded(Number(slider.value)));
  let playing = false;
  async function play() {
    while (playing) {
      const started = performance.now();
      await setFrame((shown + 1) % scene.frames);
      const wait = 1000 / 30 - (performance.now() - started);
      if (wait > 0) await new Promise((resolve) => setTimeout(resolve, wait));
    }
  }
  const togglePlay = () => {
    playing = !playing;
    $('play').textContent = playing ? 'pause' : 'play';
    if (playing) play().catch(fail);
  };
  $('play').addEventListener('click', togglePlay);
  document.addEventListener('keydown', (event) => {
    if (event.target === slider) return; // the slider steps on arrows itself
    if (event.key === 'ArrowRight') guarded(requested + 1);
    else if (event.key === 'ArrowLeft') guarded(requested - 1);
    else if (event.key === ' ') {
      event.preventDefault();
      togglePlay();
    }
  });

  await setFrame(0);
  view.fitCamera();
  view.render();
  api.timing.firstFrameMs = performance.now();
  showMessage('', '');

  Object.assign(api, {
    renderer: { name: view.rendererName, antialias: view.antialias },
    scene: { kind: scene.kind, frames: scene.frames, title: scene.title,
      clothFaces: scene.cloth.faces, hasArm: !!scene.arm,
      hasContacts: scene.has_contacts, hasClusters: !!scene.clusters },
    frame: () => shown,
    setFrame: (k) => setFrame(k),
    /** Resolves once frame k is on screen. */
    whenShown: (k) => (shown === k && requested === k ? Promise.resolve()
      : new Promise((resolve) => waiting.set(k, [...(waiting.get(k) || []), resolve]))),
    /** Turns an overlay on or off, as its checkbox does. */
    setVisible: (name, on) => {
      toggles[name].checked = on;
      view.setVisible(name, on);
    },
    /** Pixel counts of the picture by colour class (cloth, arm, red, ...). */
    pixelCounts: () => classifyPixels(view.readPixels()),
    /** A cheap fingerprint of the picture, to see that it changed. */
    picture: () => view.readPixels(),
    /** Mean ms of `renders` back-to-back renders while orbiting, and the fps of an rAF-paced orbit. */
    benchmark: async (renders = 30, seconds = 3) => {
      const renderMs = view.timeRenders(renders);
      let count = 0;
      const start = performance.now();
      await new Promise((resolve) => {
        const step = () => {
          view.camera.position.applyAxisAngle(view.camera.up, 0.02);
          view.camera.lookAt(view.controls.target);
          view.render();
          ++count;
          if (performance.now() - start < seconds * 1000) requestAnimationFrame(step);
          else resolve();
        };
        requestAnimationFrame(step);
      });
      return { renderMs, rafFps: (count * 1000) / (performance.now() - start) };
    },
  });
  api.ready = true;
}

window.addEventListener('error', (event) => fail(event.error || event.message));
main().catch(fail);
