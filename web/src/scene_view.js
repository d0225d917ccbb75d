// The three.js scene of the viewer: cloth and arm, and the overlays of a frame's contacts.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { computeVertexNormals, interpolated, segmentContactPoint } from './geometry.js';

/** Display colours; the browser test tells cloth, arm and red apart by these hues. */
export const COLORS = {
  background: 0x26282c,
  cloth: 0x3f7fe0,
  arm: 0xd9a27c,
  candidate: 0xff0000,
  collidingFace: 0xffd000,
  collidingEdge: 0xff8c00,
  contactPoint: 0xff00ff,
  observer: 0x00e5ff,
};

// Distinct colours for radial-view clusters (golden-angle hues).
function clusterColor(id) {
  return new THREE.Color().setHSL((id * 0.618034) % 1, 0.65, 0.55);
}

// The WebGL renderer's name, from a scratch context (its antialias flag is fixed at creation).
function webglRendererName() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return '';
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  const lose = gl.getExtension('WEBGL_lose_context');
  if (lose) lose.loseContext();
  return name;
}

// A geometry whose buffers grow as needed (contacts differ from frame to frame).
class GrowingGeometry {
  constructor(object, itemSize = 3) {
    this.object = object;
    this.itemSize = itemSize;
    this.capacity = 0;
  }
  set(values) {
    const count = values.length / this.itemSize;
    if (count > this.capacity || this.capacity === 0) {
      this.capacity = Math.max(64, 2 * count);
      this.object.geometry.dispose();
      this.object.geometry = new THREE.BufferGeometry();
      const buffer = new Float32Array(this.capacity * this.itemSize);
      this.object.geometry.setAttribute('position', new THREE.BufferAttribute(buffer, 3));
    }
    const attribute = this.object.geometry.getAttribute('position');
    attribute.array.set(values);
    attribute.needsUpdate = true;
    this.object.geometry.setDrawRange(0, count);
    this.object.geometry.computeBoundingSphere();
  }
}

function overlayMaterial(Material, color, extra = {}) {
  return new Material({ color, depthTest: false, transparent: true, ...extra });
}

export class SceneView {
  constructor(canvas, scene) {
    this.scene = scene;
    // Multisampling costs a CPU renderer (SwiftShader) ~3x per frame and a GPU little: on
    // unless the renderer is a software one; ?antialias=0 or =1 in the address decides.
    this.rendererName = webglRendererName();
    const choice = new URLSearchParams(window.location.search).get('antialias');
    this.antialias = choice === null ? !/swiftshader|llvmpipe|software/i.test(this.rendererName)
      : choice !== '0';
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: this.antialias });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.world = new THREE.Scene();
    this.world.background = new THREE.Color(COLORS.background);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.001, 1000);
    this.world.add(this.camera);
    this.world.add(new THREE.HemisphereLight(0xffffff, 0x606060, 1.4));
    const headlight = new THREE.DirectionalLight(0xffffff, 1.6);
    headlight.position.set(0.3, 0.6, 1);
    this.camera.add(headlight); // lit from the viewer's side whichever way it turns
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.requestRender());

    this.cloth = this.makeSurface(scene.cloth, COLORS.cloth);
    this.arm = scene.arm ? this.makeSurface(scene.arm, COLORS.arm) : null;

    // Candidate triangles: cloth faces drawn again in flat red over the cloth (sharing its
    // positions), through an index buffer sized once for every face.
    const candidates = new THREE.BufferGeometry();
    candidates.setAttribute('position', this.cloth.geometry.getAttribute('position'));
    candidates.setIndex(new THREE.BufferAttribute(new Uint32Array(scene.cloth.indices.length), 1));
    candidates.setDrawRange(0, 0);
    this.candidates = new THREE.Mesh(candidates, new THREE.MeshBasicMaterial({
      color: COLORS.candidate, side: THREE.DoubleSide, polygonOffset: true,
      polygonOffsetFactor: -1, polygonOffsetUnits: -4 }));
    this.candidates.frustumCulled = false;
    this.world.add(this.candidates);

    // Colliding primitives at their time of impact, drawn over everything.
    this.collidingFaces = new GrowingGeometry(new THREE.Mesh(new THREE.BufferGeometry(),
      overlayMaterial(THREE.MeshBasicMaterial, COLORS.collidingFace,
        { side: THREE.DoubleSide, opacity: 0.85 })));
    this.collidingEdges = new GrowingGeometry(new THREE.LineSegments(new THREE.BufferGeometry(),
      overlayMaterial(THREE.LineBasicMaterial, COLORS.collidingEdge)));
    this.contactPoints = new GrowingGeometry(new THREE.Points(new THREE.BufferGeometry(),
      overlayMaterial(THREE.PointsMaterial, COLORS.contactPoint,
        { size: 7, sizeAttenuation: false })));
    this.observers = new GrowingGeometry(new THREE.Points(new THREE.BufferGeometry(),
      overlayMaterial(THREE.PointsMaterial, COLORS.observer, { size: 12, sizeAttenuation: false })));
    this.collisionGroup = new THREE.Group();
    for (const part of [this.collidingFaces, this.collidingEdges, this.contactPoints]) {
      part.object.renderOrder = 10;
      this.collisionGroup.add(part.object);
    }
    this.observers.object.renderOrder = 11;
    this.world.add(this.collisionGroup, this.observers.object);
    this.clusterMesh = null;
    this.visible = { arm: true, candidates: true, collisions: true, clusters: false, observers: true };
    this.renderPending = false;
    this.resize();
    window.addEventListener('resize', () => this.resize());
  }

  makeSurface(part, color) {
    const geometry = new THREE.BufferGeometry();
    const positions = new THREE.BufferAttribute(new Float32Array(part.vertices * 3), 3);
    const normals = new THREE.BufferAttribute(new Float32Array(part.vertices * 3), 3);
    positions.setUsage(THREE.DynamicDrawUsage);
    normals.setUsage(THREE.DynamicDrawUsage);
    geometry.setAttribute('position', positions);
    geometry.setAttribute('normal', normals);
    geometry.setIndex(new THREE.BufferAttribute(part.indices, 1));
    const mesh = new THREE.Mesh(geometry,
      new THREE.MeshLambertMaterial({ color, side: THREE.DoubleSide }));
    this.world.add(mesh);
    return mesh;
  }

  static updateSurface(mesh, positions) {
    const geometry = mesh.geometry;
    const position = geometry.getAttribute('position');
    const normal = geometry.getAttribute('normal');
    position.array.set(positions);
    position.needsUpdate = true;
    computeVertexNormals(position.array, geometry.index.array, normal.array);
    normal.needsUpdate = true;
    geometry.computeBoundingSphere();
  }

  /** Shows `frame`; `previous` (frame k-1, or null) places the contacts at their time. */
  showFrame(frame, previous) {
    SceneView.updateSurface(this.cloth, frame.cloth);
    if (this.arm && frame.arm) SceneView.updateSurface(this.arm, frame.arm);
    const contacts = frame.contacts;
    const faces = this.scene.cloth.indices;

    const candidateIndex = this.candidates.geometry.index;
    const ids = contacts ? contacts.candidates : new Uint32Array(0);
    for (let i = 0; i < ids.length; ++i) {
      candidateIndex.array.set(faces.subarray(3 * ids[i], 3 * ids[i] + 3), 3 * i);
    }
    candidateIndex.clearUpdateRanges();
    candidateIndex.addUpdateRange(0, 3 * ids.length);
    candidateIndex.needsUpdate = true;
    this.candidates.geometry.setDrawRange(0, 3 * ids.length);

    // Contact time u in [0, 1] across the frame: substep s of S, time of impact t in it.
    const x1 = frame.cloth, x0 = previous ? previous.cloth : null;
    const vfCount = contacts ? contacts.vertex_face_count : 0;
    const eeCount = contacts ? contacts.edge_edge_count : 0;
    const faceVertices = new Float32Array(9 * vfCount), edgeVertices = new Float32Array(12 * eeCount);
    const points = new Float32Array(3 * (vfCount + eeCount));
    const p = [0, 0, 0];
    for (let i = 0; i < vfCount; ++i) {
      const vf = contacts.vertex_face, face = vf[3 * i + 1];
      const u = (vf[3 * i + 2] + contacts.vertex_face_toi[i]) / contacts.substeps;
      for (let c = 0; c < 3; ++c) faceVertices.set(interpolated(x0, x1, faces[3 * face + c], u, p), 9 * i + 3 * c);
      points.set(interpolated(x0, x1, vf[3 * i], u, p), 3 * i);
    }
    for (let i = 0; i < eeCount; ++i) {
      const ee = contacts.edge_edge;
      const u = (ee[5 * i + 4] + contacts.edge_edge_toi[i]) / contacts.substeps;
      const ends = [0, 1, 2, 3].map((j) => interpolated(x0, x1, ee[5 * i + j], u));
      ends.forEach((end, j) => edgeVertices.set(end, 12 * i + 3 * j));
      points.set(segmentContactPoint(...ends), 3 * (vfCount + i));
    }
    this.collidingFaces.set(faceVertices);
    this.collidingEdges.set(edgeVertices);
    this.contactPoints.set(points);
    this.observers.set(new Float32Array(contacts ? contacts.observers.flat() : []));
    this.applyVisibility();
    this.requestRender();
  }

  ensureClusterMesh() {
    if (this.clusterMesh || !this.scene.clusters) return;
    // The cloth's faces reordered by cluster, one draw group and colour per cluster.
    const clusters = this.scene.clusters, faces = this.scene.cloth.indices;
    const order = Array.from(clusters.keys()).sort((a, b) => clusters[a] - clusters[b]);
    const index = new Uint32Array(faces.length);
    const geometry = new THREE.BufferGeometry();
    const materials = [];
    let start = 0;
    order.forEach((face, i) => {
      index.set(faces.subarray(3 * face, 3 * face + 3), 3 * i);
      const last = i + 1 === order.length || clusters[order[i + 1]] !== clusters[face];
      if (last) {
        geometry.addGroup(3 * start, 3 * (i + 1 - start), materials.length);
        materials.push(new THREE.MeshLambertMaterial({
          color: clusterColor(clusters[face]), side: THREE.DoubleSide }));
        start = i + 1;
      }
    });
    geometry.setAttribute('position', this.cloth.geometry.getAttribute('position'));
    geometry.setAttribute('normal', this.cloth.geometry.getAttribute('normal'));
    geometry.setIndex(new THREE.BufferAttribute(index, 1));
    this.clusterMesh = new THREE.Mesh(geometry, materials);
    this.clusterMesh.frustumCulled = false;
    this.world.add(this.clusterMesh);
  }

  setVisible(name, on) {
    this.visible[name] = on;
    if (name === 'clusters' && on) this.ensureClusterMesh();
    this.applyVisibility();
    this.requestRender();
  }

  applyVisibility() {
    const v = this.visible;
    if (this.arm) this.arm.visible = v.arm;
    const clusters = v.clusters && this.clusterMesh !== null;
    if (this.clusterMesh) this.clusterMesh.visible = clusters;
    this.cloth.visible = !clusters;
    this.candidates.visible = v.candidates;
    this.collisionGroup.visible = v.collisions;
    this.observers.object.visible = v.observers;
  }

  /** Frames the cloth (and arm) as shown now, seen from the front and a little above. */
  fitCamera() {
    const box = new THREE.Box3().setFromObject(this.cloth);
    if (this.arm) box.union(new THREE.Box3().setFromObject(this.arm));
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-6);
    const distance = radius / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) * 1.05;
    const direction = new THREE.Vector3(0.35, 0.45, 1).normalize();
    this.camera.position.copy(center).addScaledVector(direction, distance);
    this.camera.near = distance / 1000;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    this.requestRender();
  }

  resize() {
    const canvas = this.renderer.domElement;
    this.renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
    this.camera.aspect = canvas.clientWidth / Math.max(1, canvas.clientHeight);
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  render() {
    this.renderPending = false;
    this.renderer.render(this.world, this.camera);
  }

  requestRender() {
    if (this.renderPending) return;
    this.renderPending = true;
    requestAnimationFrame(() => this.render());
  }

  /** Renders now and reads the picture back: RGBA bytes, bottom row first. */
  readPixels() {
    this.render();
    const gl = this.renderer.getContext();
    const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return { width, height, pixels };
  }

  /**
   * Mean time of one render of the current view over `count` renders while orbiting,
   * finished by a one-pixel read-back (which waits until the GPU has drawn them all).
   */
  timeRenders(count) {
    const gl = this.renderer.getContext();
    const pixel = new Uint8Array(4);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel); // start from an idle GPU
    const start = performance.now();
    for (let i = 0; i < count; ++i) {
      this.camera.position.applyAxisAngle(this.camera.up, 0.02);
      this.camera.lookAt(this.controls.target);
      this.renderer.render(this.world, this.camera);
    }
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return (performance.now() - start) / count;
  }
}
