// diffuv painter: paint regions on a mesh, see diffuv's patches and map.
//
// Served by `diffuv serve` with three.js (Debian's libjs-three, r111) under
// /three/. three itself is imported by the same URL OrbitControls resolves
// ("../../../build/three.module.js"), so both share one module instance.
//
// The mesh is drawn non-indexed: face f owns vertices 3f..3f+2 of the
// geometry, so per-face colours are plain vertex colours and a raycast's
// faceIndex is the face id the server uses.

import * as THREE from "/three/build/three.module.js";
import { OrbitControls } from "/three/examples/jsm/controls/OrbitControls.js";

// ---------------------------------------------------------------------------
// Constants

const UNPAINTED = -1;
const UNPAINTED_COLOR = new THREE.Color("#c8c8cc");
const BASE_LABEL_COLORS = [
  "#e6194b", "#3cb44b", "#4363d8", "#ffe119", "#f58231", "#911eb4",
  "#42d4f4", "#f032e6", "#bfef45", "#9a6324", "#469990", "#dcbeff",
];
const INITIAL_LABEL_COUNT = 8;
const MAX_PALETTE_BUTTONS = 64;
const SIDE_COLORS = { u1: "#e41a1c", u2: "#ff9f1c", v1: "#2b6fde", v2: "#19c3c3" };
const SIDE_NAMES = ["u1", "u2", "v1", "v2"];
const HIGHLIGHT_COLOR = new THREE.Color("#ffd000");
const FADED = new THREE.Color("#e8e8ec");
const UNMAPPED_COLOR = new THREE.Color("#555555");
const LAYOUT_DELAY_MS = 300;
const RADIUS_MIN = 1;   // percent of the bounding box diagonal
const RADIUS_MAX = 20;
const MESH_EXTENSIONS = [".off", ".obj", ".ply", ".stl"];
const TEST_MODE = new URLSearchParams(window.location.search).get("test") === "1";

// ---------------------------------------------------------------------------
// State

const state = {
  mesh: null,          // see buildMesh()
  labels: null,        // Int32Array, one label per face, UNPAINTED = -1
  labelsVersion: 0,    // bumped on every change of labels
  tool: "brush",       // brush | eraser | fill | orbit
  label: 0,            // the label the brush and the fill paint
  radiusPercent: 5,    // brush radius, percent of the bounding box diagonal
  paletteSize: INITIAL_LABEL_COUNT,
  view: "paint",       // paint | patches | isolines | distortion
  stroke: null,        // Map face -> label before the stroke, while painting
  undoStack: [],       // steps {faces, before, after}
  redoStack: [],
  layout: null,        // last /api/layout (or /api/param) answer
  layoutVersion: -1,   // labelsVersion the layout was computed for
  param: null,         // last /api/param answer, plus what the page made of it
  paramVersion: -1,
  highlightPatch: -1,  // patch of the selected problem, or -1
  sidePolylineCount: 0,
  cornerCount: 0,
};

// three.js objects
let renderer, scene, camera, controls, surface, overlay, brushCursor;
let colorMaterial, isolineMaterial;
const raycaster = new THREE.Raycaster();

const $ = (id) => document.getElementById(id);

// ---------------------------------------------------------------------------
// Messages and server calls

/** Shows a message over the view; errors stay until closed. */
function showMessage(text, kind = "info") {
  const box = $("messages");
  const item = document.createElement("div");
  item.className = "message " + kind;
  item.textContent = text;
  const close = document.createElement("button");
  close.textContent = "\u00d7";
  close.title = "close";
  close.addEventListener("click", () => item.remove());
  item.appendChild(close);
  box.appendChild(item);
  while (box.children.length > 5) box.firstChild.remove();
  if (kind !== "error") setTimeout(() => item.remove(), 4000);
}

function showError(error) {
  const text = error instanceof Error ? error.message : String(error);
  console.error(error);
  showMessage(text, "error");
}

let busyCount = 0;
function setBusy(delta) {
  busyCount += delta;
  $("busy").hidden = busyCount <= 0;
}

/**
 * Calls the server; resolves to the parsed answer (json, text or blob).
 * Rejects with an Error carrying the server's {"error"} message for a status
 * >= 400, so callers only need to catch and show it.
 */
async function api(path, { body, method = body === undefined ? "GET" : "POST", as = "json", contentType } = {}) {
  const init = { method, headers: {} };
  if (body !== undefined) {
    const raw = body instanceof Blob || body instanceof ArrayBuffer;
    init.body = raw ? body : JSON.stringify(body);
    init.headers["Content-Type"] = contentType || (raw ? "application/octet-stream" : "application/json");
  }
  setBusy(+1);
  try {
    let response;
    try {
      response = await fetch(path, init);
    } catch (e) {
      throw new Error(`cannot reach the diffuv server (${path}): ${e.message}`);
    }
    if (!response.ok) {
      let message = `${response.status} ${response.statusText}`;
      try {
        const answer = await response.json();
        if (answer && answer.error) message = answer.error;
      } catch (e) { /* not JSON: keep the status line */ }
      throw new Error(`${path}: ${message}`);
    }
    if (as === "text") return await response.text();
    if (as === "blob") return await response.blob();
    return await response.json();
  } finally {
    setBusy(-1);
  }
}

/** The labels as the server wants them: [] when nothing is painted (automatic layout). */
function labelsForServer() {
  const labels = state.labels;
  if (!labels || labels.every((l) => l === UNPAINTED)) return [];
  return Array.from(labels);
}

// ---------------------------------------------------------------------------
// Colours

function labelColor(label) {
  if (label < 0) return UNPAINTED_COLOR;
  if (label < BASE_LABEL_COLORS.length) return new THREE.Color(BASE_LABEL_COLORS[label]);
  // Beyond the fixed list: hues spread by the golden ratio stay distinct.
  return new THREE.Color().setHSL((label * 0.618034) % 1, 0.7, 0.5);
}

function patchColor(patch) {
  const lightness = [0.5, 0.62, 0.74][patch % 3];
  return new THREE.Color().setHSL((patch * 0.618034 + 0.1) % 1, 0.55, lightness);
}

/** Area distortion max(r, 1/r) >= 1 onto blue (1) - white - orange - red (>= 4). */
const DISTORTION_RAMP = ["#3b5bdb", "#f5f5f5", "#f08c00", "#c92a2a"].map((c) => new THREE.Color(c));
function distortionColor(value) {
  if (value === null || !Number.isFinite(value) || value <= 0) return UNMAPPED_COLOR;
  const r = Math.max(value, 1 / value);
  const t = Math.min(Math.log(r) / Math.log(4), 1) * (DISTORTION_RAMP.length - 1);
  const i = Math.min(Math.floor(t), DISTORTION_RAMP.length - 2);
  return DISTORTION_RAMP[i].clone().lerp(DISTORTION_RAMP[i + 1], t - i);
}

/** A texture of u isolines (red), v isolines (blue) over a faint checker. */
function makeIsolineTexture() {
  const size = 1024, cells = 10;
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = size;
  const g = canvas.getContext("2d");
  g.fillStyle = "#ffffff";
  g.fillRect(0, 0, size, size);
  const step = size / (2 * cells);
  g.fillStyle = "#e4e4e4";
  for (let i = 0; i < 2 * cells; i++) {
    for (let j = 0; j < 2 * cells; j++) {
      if ((i + j) % 2) g.fillRect(i * step, j * step, step, step);
    }
  }
  const width = 7;
  for (let i = 0; i <= cells; i++) {
    const x = Math.min(Math.max(i * size / cells, width / 2), size - width / 2);
    g.fillStyle = "#d0202a"; // u = constant: vertical lines in texture space
    g.fillRect(x - width / 2, 0, width, size);
    g.fillStyle = "#1f4fd0"; // v = constant
    g.fillRect(0, x - width / 2, size, width);
  }
  const texture = new THREE.CanvasTexture(canvas);
  texture.anisotropy = 4;
  return texture;
}

// ---------------------------------------------------------------------------
// The mesh

/**
 * Builds what the page needs from GET /api/mesh: typed arrays, face
 * centroids, the face adjacency graph (CSR: neighbours of f are
 * adjFace[adjStart[f] .. adjStart[f+1]), adjLength the centroid distances)
 * and per-vertex normals (to lift the side polylines off the surface).
 */
function buildMesh(json) {
  if (!json || !Array.isArray(json.vertices) || !Array.isArray(json.faces)) {
    throw new Error("the server sent no mesh");
  }
  const V = json.vertices.length / 3, F = json.faces.length / 3;
  if (!Number.isInteger(V) || !Number.isInteger(F) || F === 0) throw new Error("the mesh has no faces");
  const positions = Float64Array.from(json.vertices);
  const faces = Uint32Array.from(json.faces);
  for (let i = 0; i < faces.length; i++) {
    if (faces[i] >= V) throw new Error(`face ${Math.floor(i / 3)} names vertex ${faces[i]} of ${V}`);
  }

  const centroids = new Float64Array(3 * F);
  const vertexNormals = new Float32Array(3 * V);
  const faceNormals = new Float32Array(3 * F);
  const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
  for (let f = 0; f < F; f++) {
    const [ia, ib, ic] = [faces[3 * f], faces[3 * f + 1], faces[3 * f + 2]];
    a.fromArray(positions, 3 * ia); b.fromArray(positions, 3 * ib); c.fromArray(positions, 3 * ic);
    for (let d = 0; d < 3; d++) centroids[3 * f + d] = (positions[3 * ia + d] + positions[3 * ib + d] + positions[3 * ic + d]) / 3;
    // cross product, area weighted: big faces count more in vertex normals
    const n = b.clone().sub(a).cross(c.clone().sub(a));
    for (const v of [ia, ib, ic]) {
      vertexNormals[3 * v] += n.x; vertexNormals[3 * v + 1] += n.y; vertexNormals[3 * v + 2] += n.z;
    }
    n.normalize();
    faceNormals[3 * f] = n.x; faceNormals[3 * f + 1] = n.y; faceNormals[3 * f + 2] = n.z;
  }
  for (let v = 0; v < V; v++) {
    const n = new THREE.Vector3().fromArray(vertexNormals, 3 * v).normalize();
    n.toArray(vertexNormals, 3 * v);
  }

  const { adjStart, adjFace, adjLength, facesOfEdge } = buildFaceAdjacency(faces, V, F, centroids);

  let diagonal = Number(json.diagonal);
  if (!(diagonal > 0)) {
    const box = new THREE.Box3().setFromArray(positions);
    diagonal = box.getSize(new THREE.Vector3()).length() || 1;
  }
  // Optional: the polygon of the mesh file each face comes from, when the
  // file had polygons that were split into triangles (label files count polygons).
  const fileFace = Array.isArray(json.file_face) && json.file_face.length === F ? json.file_face : null;
  const facesInFile = fileFace ? fileFace.reduce((top, p) => Math.max(top, p), -1) + 1 : F;
  return {
    name: String(json.name || "mesh"), labelSource: String(json.label_source || ""), fileFace, facesInFile,
    V, F, positions, faces, centroids,
    faceNormals, vertexNormals, adjStart, adjFace, adjLength, facesOfEdge, diagonal,
    // scratch for the Dijkstra, reused between calls
    distance: new Float64Array(F).fill(Infinity),
  };
}

/**
 * Faces sharing an edge are neighbours (all pairs at a non-manifold edge).
 * Also returns facesOfEdge: edge key (see edgeKey) -> face or array of faces.
 */
function buildFaceAdjacency(faces, V, F, centroids) {
  const facesOfEdge = new Map(); // key min*V+max -> face, or array of faces
  for (let f = 0; f < F; f++) {
    for (let k = 0; k < 3; k++) {
      const p = faces[3 * f + k], q = faces[3 * f + (k + 1) % 3];
      const key = edgeKey(p, q, V);
      const seen = facesOfEdge.get(key);
      if (seen === undefined) facesOfEdge.set(key, f);
      else if (typeof seen === "number") facesOfEdge.set(key, [seen, f]);
      else seen.push(f);
    }
  }
  const degree = new Int32Array(F);
  const pairs = [];
  for (const value of facesOfEdge.values()) {
    if (typeof value === "number") continue;
    for (let i = 0; i < value.length; i++) {
      for (let j = i + 1; j < value.length; j++) {
        if (value[i] === value[j]) continue;
        pairs.push(value[i], value[j]);
        degree[value[i]]++; degree[value[j]]++;
      }
    }
  }
  const adjStart = new Int32Array(F + 1);
  for (let f = 0; f < F; f++) adjStart[f + 1] = adjStart[f] + degree[f];
  const adjFace = new Int32Array(adjStart[F]);
  const adjLength = new Float64Array(adjStart[F]);
  const fillPos = adjStart.slice(0, F);
  for (let i = 0; i < pairs.length; i += 2) {
    const f = pairs[i], g = pairs[i + 1];
    const dx = centroids[3 * f] - centroids[3 * g];
    const dy = centroids[3 * f + 1] - centroids[3 * g + 1];
    const dz = centroids[3 * f + 2] - centroids[3 * g + 2];
    const length = Math.sqrt(dx * dx + dy * dy + dz * dz);
    adjFace[fillPos[f]] = g; adjLength[fillPos[f]++] = length;
    adjFace[fillPos[g]] = f; adjLength[fillPos[g]++] = length;
  }
  return { adjStart, adjFace, adjLength, facesOfEdge };
}

function edgeKey(p, q, V) {
  return Math.min(p, q) * V + Math.max(p, q);
}

/** Makes the non-indexed geometry: 3 vertices per face, flat normals. */
function buildGeometry(mesh) {
  const { F, positions, faces, faceNormals } = mesh;
  const position = new Float32Array(9 * F);
  const normal = new Float32Array(9 * F);
  for (let f = 0; f < F; f++) {
    for (let k = 0; k < 3; k++) {
      const v = faces[3 * f + k];
      for (let d = 0; d < 3; d++) {
        position[9 * f + 3 * k + d] = positions[3 * v + d];
        normal[9 * f + 3 * k + d] = faceNormals[3 * f + d];
      }
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(position, 3));
  geometry.setAttribute("normal", new THREE.BufferAttribute(normal, 3));
  geometry.setAttribute("color", new THREE.BufferAttribute(new Float32Array(9 * F), 3));
  geometry.setAttribute("uv", new THREE.BufferAttribute(new Float32Array(6 * F), 2));
  geometry.computeBoundingSphere();
  geometry.computeBoundingBox();
  return geometry;
}

/** Replaces the shown mesh by the server's answer (GET or POST /api/mesh). */
function showMesh(json) {
  const mesh = buildMesh(json);
  state.mesh = mesh;
  state.labels = new Int32Array(mesh.F).fill(UNPAINTED);
  if (Array.isArray(json.labels)) {
    if (json.labels.length === mesh.F) {
      state.labels.set(json.labels.map((l) => (Number.isInteger(l) && l >= 0 ? l : UNPAINTED)));
    } else {
      showError(`the mesh came with ${json.labels.length} labels for ${mesh.F} faces; ignored`);
    }
  }
  state.labelsVersion++;
  state.undoStack = [];
  state.redoStack = [];
  state.layout = null;
  state.param = null;
  state.highlightPatch = -1;
  growPaletteFor(state.labels);

  if (surface) {
    scene.remove(surface);
    surface.geometry.dispose();
  }
  surface = new THREE.Mesh(buildGeometry(mesh), colorMaterial);
  scene.add(surface);
  clearOverlay();
  fitCamera();

  $("mesh-info").textContent = `${mesh.name}: ${mesh.V} vertices, ${mesh.F} faces` +
    (mesh.labelSource && countLabel(UNPAINTED) < mesh.F ? `; ${mesh.labelSource}` : "");
  document.title = `${mesh.name} - diffuv painter`;
  $("summary").hidden = true;
  showProblems([]);
  $("layout-status").textContent = "";
  setView("paint");
  updateUndoButtons();
  renderPalette();
}

// ---------------------------------------------------------------------------
// Surface colours per view

/** Colour of face f in the current view. */
function faceColor(f) {
  const { view, labels, layout, param } = state;
  if (view === "patches" && layout) {
    const patch = layout.face_patch[f];
    if (state.highlightPatch >= 0) {
      // the selected problem's patch in yellow, the others faded
      if (patch === state.highlightPatch) return HIGHLIGHT_COLOR;
      return (patch >= 0 ? patchColor(patch) : UNPAINTED_COLOR.clone()).lerp(FADED, 0.7);
    }
    return patch >= 0 ? patchColor(patch) : UNPAINTED_COLOR;
  }
  if (view === "isolines" && param) {
    if (param.unmapped[f]) return UNMAPPED_COLOR;
    // a pale chart colour tells the charts apart under the isolines
    return patchColor(param.faceChart[f]).lerp(WHITE, 0.65);
  }
  if (view === "distortion" && param) return distortionColor(param.distortion[f]);
  return labelColor(labels[f]);
}
const WHITE = new THREE.Color(1, 1, 1);

/** Writes the colour of the given faces (all when faces is omitted). */
function recolor(faces) {
  if (!surface) return;
  const attribute = surface.geometry.getAttribute("color");
  const colors = attribute.array;
  const write = (f) => {
    const c = faceColor(f);
    for (let k = 0; k < 3; k++) {
      colors[9 * f + 3 * k] = c.r; colors[9 * f + 3 * k + 1] = c.g; colors[9 * f + 3 * k + 2] = c.b;
    }
  };
  if (faces) for (const f of faces) write(f);
  else for (let f = 0; f < state.mesh.F; f++) write(f);
  attribute.needsUpdate = true;
  requestRender();
}

function setView(view) {
  if ((view === "isolines" || view === "distortion") && !state.param) {
    showMessage("press Map first: the isolines and the distortion come from the map");
    return;
  }
  if (view === "patches" && !state.layout) requestLayout().catch(showError);
  state.view = view;
  if (surface) surface.material = view === "isolines" ? isolineMaterial : colorMaterial;
  for (const button of document.querySelectorAll("#views button")) {
    button.classList.toggle("active", button.dataset.view === view);
  }
  $("distortion-legend").hidden = view !== "distortion";
  brushCursor.visible = false;
  recolor();
}

// ---------------------------------------------------------------------------
// Picking

/** The face under a point of the page (client coordinates), or null. */
function pickAt(clientX, clientY) {
  if (!surface) return null;
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(
    ((clientX - rect.left) / rect.width) * 2 - 1,
    -((clientY - rect.top) / rect.height) * 2 + 1);
  camera.updateMatrixWorld();
  raycaster.setFromCamera(ndc, camera);
  const hits = raycaster.intersectObject(surface, false);
  if (hits.length === 0) return null;
  return { face: hits[0].faceIndex, point: hits[0].point.clone() };
}

// ---------------------------------------------------------------------------
// Distances along the surface

/** A binary min-heap of (key, value) pairs. */
class MinHeap {
  constructor() { this.keys = []; this.values = []; }
  get size() { return this.keys.length; }
  push(key, value) {
    const keys = this.keys, values = this.values;
    let i = keys.length;
    keys.push(key); values.push(value);
    while (i > 0) {
      const parent = (i - 1) >> 1;
      if (keys[parent] <= key) break;
      keys[i] = keys[parent]; values[i] = values[parent];
      i = parent;
    }
    keys[i] = key; values[i] = value;
  }
  /** Removes the smallest pair; returns [key, value]. */
  pop() {
    const keys = this.keys, values = this.values;
    const top = [keys[0], values[0]];
    const lastKey = keys.pop(), lastValue = values.pop();
    const n = keys.length;
    if (n > 0) {
      let i = 0;
      for (;;) {
        let child = 2 * i + 1;
        if (child >= n) break;
        if (child + 1 < n && keys[child + 1] < keys[child]) child++;
        if (keys[child] >= lastKey) break;
        keys[i] = keys[child]; values[i] = values[child];
        i = child;
      }
      keys[i] = lastKey; values[i] = lastValue;
    }
    return top;
  }
}

/**
 * Dijkstra over the face adjacency graph (edge lengths: distances between
 * centroids) from startFace at distance 0; stops beyond maxDistance. Going
 * along the surface rather than through space keeps the brush from bleeding
 * into a leg or an ear that is close in space but far on the surface.
 * Returns {faces, distances}: the faces reached, nearest first.
 */
function surfaceDistances(startFace, maxDistance = Infinity) {
  const { adjStart, adjFace, adjLength, distance } = state.mesh;
  const reached = [], reachedDistance = [], touched = [startFace];
  const heap = new MinHeap();
  distance[startFace] = 0;
  heap.push(0, startFace);
  while (heap.size > 0) {
    const [d, f] = heap.pop();
    if (d > distance[f]) continue; // a stale entry: f was reached shorter since
    reached.push(f);
    reachedDistance.push(d);
    for (let i = adjStart[f]; i < adjStart[f + 1]; i++) {
      const g = adjFace[i], nd = d + adjLength[i];
      if (nd <= maxDistance && nd < distance[g]) {
        if (distance[g] === Infinity) touched.push(g);
        distance[g] = nd;
        heap.push(nd, g);
      }
    }
  }
  for (const f of touched) distance[f] = Infinity; // ready for the next call
  return { faces: reached, distances: reachedDistance };
}

function brushRadius() {
  return (state.radiusPercent / 100) * state.mesh.diagonal;
}

// ---------------------------------------------------------------------------
// Painting, strokes, undo

function beginStroke() {
  if (state.stroke) endStroke();
  state.stroke = new Map();
  // the isolines and the distortion do not show labels: paint where one can see it
  if (state.view === "isolines" || state.view === "distortion") setView("paint");
}

/** Sets face labels inside the current stroke, remembering what they were. */
function setLabels(faces, label) {
  const changed = [];
  for (const f of faces) {
    if (state.labels[f] === label) continue;
    if (state.stroke && !state.stroke.has(f)) state.stroke.set(f, state.labels[f]);
    state.labels[f] = label;
    changed.push(f);
  }
  if (changed.length > 0) {
    state.labelsVersion++;
    if (state.view === "paint") recolor(changed);
  }
  return changed.length;
}

/** The label the active tool paints. */
function toolLabel() {
  return state.tool === "eraser" ? UNPAINTED : state.label;
}

/** Paints the faces within the brush radius along the surface of hit.face. */
function paintAt(hit, label = toolLabel()) {
  if (!hit || !state.mesh) return 0;
  const { faces } = surfaceDistances(hit.face, brushRadius());
  return setLabels(faces, label);
}

/** Ends a stroke: one undo step, then the patches are recomputed shortly. */
function endStroke() {
  const stroke = state.stroke;
  state.stroke = null;
  if (!stroke) return;
  const faces = [], before = [], after = [];
  for (const [f, old] of stroke) {
    if (state.labels[f] === old) continue;
    faces.push(f); before.push(old); after.push(state.labels[f]);
  }
  if (faces.length === 0) return;
  state.undoStack.push({ faces: Int32Array.from(faces), before: Int32Array.from(before), after: Int32Array.from(after) });
  state.redoStack = [];
  updateUndoButtons();
  labelsChanged();
}

/** Gives the connected region of faces with the clicked face's label the current label. */
function fillAt(face, label = state.label) {
  if (!state.mesh || face < 0 || face >= state.mesh.F) return 0;
  const { adjStart, adjFace } = state.mesh;
  const target = state.labels[face];
  if (target === label) return 0;
  const seen = new Uint8Array(state.mesh.F);
  const region = [face];
  seen[face] = 1;
  for (let i = 0; i < region.length; i++) {
    const f = region[i];
    for (let j = adjStart[f]; j < adjStart[f + 1]; j++) {
      const g = adjFace[j];
      if (!seen[g] && state.labels[g] === target) { seen[g] = 1; region.push(g); }
    }
  }
  beginStroke();
  const count = setLabels(region, label);
  endStroke();
  return count;
}

/** Replaces every label (a loaded file, Clear) as one undoable step. */
function replaceAllLabels(newLabels) {
  beginStroke();
  for (let f = 0; f < newLabels.length; f++) {
    if (state.labels[f] === newLabels[f]) continue;
    state.stroke.set(f, state.labels[f]);
    state.labels[f] = newLabels[f];
  }
  state.labelsVersion++;
  endStroke();
  growPaletteFor(state.labels);
  renderPalette();
  recolor();
}

function applyStep(step, which) {
  const values = step[which];
  for (let i = 0; i < step.faces.length; i++) state.labels[step.faces[i]] = values[i];
  state.labelsVersion++;
  if (state.view === "paint") recolor(step.faces);
  labelsChanged();
}

function undo() {
  if (state.stroke) endStroke();
  const step = state.undoStack.pop();
  if (!step) return false;
  applyStep(step, "before");
  state.redoStack.push(step);
  updateUndoButtons();
  return true;
}

function redo() {
  if (state.stroke) endStroke();
  const step = state.redoStack.pop();
  if (!step) return false;
  applyStep(step, "after");
  state.undoStack.push(step);
  updateUndoButtons();
  return true;
}

function updateUndoButtons() {
  $("undo").disabled = state.undoStack.length === 0;
  $("redo").disabled = state.redoStack.length === 0;
}

/** After labels changed: the layout is out of date, ask again a moment later. */
function labelsChanged() {
  if (state.param) $("summary").classList.add("stale");
  $("layout-status").textContent = "labels changed: updating the patches...";
  scheduleLayout();
}

function countLabel(label) {
  let count = 0;
  for (const l of state.labels) if (l === label) count++;
  return count;
}

// ---------------------------------------------------------------------------
// Layout: patches, sides, corners, problems

let layoutTimer = 0;
let layoutRequestId = 0;

function scheduleLayout() {
  clearTimeout(layoutTimer);
  layoutTimer = setTimeout(() => requestLayout().catch(showError), LAYOUT_DELAY_MS);
}

/**
 * POST /api/layout with the current labels and shows the answer, unless a
 * newer request went out meanwhile. Resolves to the answer.
 */
async function requestLayout() {
  clearTimeout(layoutTimer);
  if (!state.mesh) return null;
  const id = ++layoutRequestId;
  const version = state.labelsVersion;
  $("layout-status").textContent = "computing the patches...";
  let answer;
  try {
    answer = await api("/api/layout", { body: { labels: labelsForServer() } });
  } catch (e) {
    if (id === layoutRequestId) $("layout-status").textContent = "the patches could not be computed";
    throw e;
  }
  if (id === layoutRequestId) showLayout(answer, version);
  return answer;
}

/** Checks the shape of a layout answer, so a bad one is an error message, not a crash. */
function checkLayoutAnswer(answer) {
  const F = state.mesh.F;
  if (!answer || !Array.isArray(answer.face_patch) || answer.face_patch.length !== F) {
    throw new Error(`the server's layout has no face_patch of ${F} values`);
  }
}

function showLayout(answer, version) {
  checkLayoutAnswer(answer);
  answer.problems = Array.isArray(answer.problems) ? answer.problems : [];
  state.layout = answer;
  state.layoutVersion = version;
  state.highlightPatch = -1;
  drawOverlay(answer);
  showProblems(answer.problems);
  const ms = Number(answer.milliseconds);
  $("layout-status").textContent =
    `${answer.patches} patches` + (Number.isFinite(ms) ? ` in ${ms.toFixed(0)} ms` : "") +
    (labelsForServer().length === 0 ? " (automatic layout: nothing painted)" : "");
  if (state.view === "patches") recolor();
  requestRender();
}

function clearOverlay() {
  for (const child of [...overlay.children]) {
    overlay.remove(child);
    child.geometry.dispose();
    child.material.dispose();
  }
  state.sidePolylineCount = 0;
  state.cornerCount = 0;
}

/**
 * Draws each patch's four sides as coloured ribbons and its corners as small
 * spheres. A ribbon lies on the surface just inside its own patch, so where
 * two patches meet both of their sides show, side by side; it is lifted a
 * little along the normals and the surface has a polygon offset, so the
 * surface does not hide it.
 */
function drawOverlay(layout) {
  clearOverlay();
  const mesh = state.mesh;
  const { V, positions, vertexNormals, diagonal } = mesh;
  const lift = 0.001 * diagonal;
  const width = 0.004 * diagonal;
  const validVertex = (v) => Number.isInteger(v) && v >= 0 && v < V;
  const point = (v) => new THREE.Vector3(
    positions[3 * v] + lift * vertexNormals[3 * v],
    positions[3 * v + 1] + lift * vertexNormals[3 * v + 1],
    positions[3 * v + 2] + lift * vertexNormals[3 * v + 2]);
  const sides = Array.isArray(layout.sides) ? layout.sides : [];

  let polylines = 0;
  for (const name of SIDE_NAMES) {
    const triangles = []; // xyz of 6 vertices (2 triangles) a segment
    sides.forEach((patchSides, patch) => {
      const polyline = patchSides && patchSides[name];
      if (!Array.isArray(polyline) || polyline.length < 2) return;
      let drawn = false;
      for (let i = 0; i + 1 < polyline.length; i++) {
        const p = polyline[i], q = polyline[i + 1];
        if (!validVertex(p) || !validVertex(q) || p === q) continue;
        const a = point(p), b = point(q);
        const inward = inwardDirection(p, q, patch, layout.face_patch, a, b);
        const a2 = a.clone().addScaledVector(inward, width), b2 = b.clone().addScaledVector(inward, width);
        for (const c of [a, b, b2, a, b2, a2]) triangles.push(c.x, c.y, c.z);
        drawn = true;
      }
      if (drawn) polylines++;
    });
    if (triangles.length === 0) continue;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(new Float32Array(triangles), 3));
    const material = new THREE.MeshBasicMaterial({
      color: SIDE_COLORS[name], side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: -1, polygonOffsetUnits: -1,
    });
    const ribbons = new THREE.Mesh(geometry, material);
    ribbons.name = "side-" + name;
    overlay.add(ribbons);
  }
  state.sidePolylineCount = polylines;

  const cornerVertices = new Set();
  for (const corners of Array.isArray(layout.corners) ? layout.corners : []) {
    if (Array.isArray(corners)) for (const v of corners) if (validVertex(v)) cornerVertices.add(v);
  }
  if (cornerVertices.size > 0) {
    const sphere = new THREE.SphereBufferGeometry(0.004 * diagonal, 10, 8);
    const spheres = new THREE.InstancedMesh(sphere, new THREE.MeshLambertMaterial({ color: "#111111" }), cornerVertices.size);
    const matrix = new THREE.Matrix4();
    let i = 0;
    for (const v of cornerVertices) {
      const c = point(v);
      spheres.setMatrixAt(i++, matrix.makeTranslation(c.x, c.y, c.z));
    }
    spheres.instanceMatrix.needsUpdate = true;
    spheres.name = "corners";
    overlay.add(spheres);
  }
  state.cornerCount = cornerVertices.size;
  overlay.visible = $("show-sides").checked;
}

/**
 * Unit vector across the edge (p, q), on the surface, pointing into the face
 * of the edge that belongs to the patch (a and b: the edge's end points).
 */
function inwardDirection(p, q, patch, facePatch, a, b) {
  const { V, centroids, vertexNormals } = state.mesh;
  const along = b.clone().sub(a).normalize();
  let seen = state.mesh.facesOfEdge.get(edgeKey(p, q, V));
  seen = typeof seen === "number" ? [seen] : seen || [];
  const face = seen.find((f) => facePatch[f] === patch) ?? seen[0];
  let inward;
  if (face !== undefined) {
    // from the edge's middle towards the face's third corner, across the edge
    inward = new THREE.Vector3().fromArray(centroids, 3 * face).sub(a.clone().add(b).multiplyScalar(0.5));
  } else {
    inward = new THREE.Vector3().fromArray(vertexNormals, 3 * p).cross(along);
  }
  inward.addScaledVector(along, -inward.dot(along));
  const length = inward.length();
  return length > 0 ? inward.divideScalar(length) : inward;
}

function showProblems(problems) {
  const list = $("problems");
  list.textContent = "";
  $("problem-count").textContent = problems.length ? `(${problems.length})` : "";
  problems.forEach((problem) => {
    const item = document.createElement("li");
    const kind = document.createElement("span");
    kind.className = "kind";
    kind.textContent = String(problem.kind || "problem");
    item.appendChild(kind);
    const hasPatch = Number.isInteger(problem.patch) && problem.patch >= 0;
    item.appendChild(document.createTextNode((hasPatch ? `patch ${problem.patch}: ` : "") + String(problem.message || "")));
    item.addEventListener("click", () => selectProblem(problem, item));
    list.appendChild(item);
  });
}

/** Highlights the problem's patch on the surface (a second click clears it). */
function selectProblem(problem, item) {
  const patch = Number.isInteger(problem.patch) ? problem.patch : -1;
  const again = state.highlightPatch === patch && item.classList.contains("selected");
  for (const li of $("problems").children) li.classList.remove("selected");
  state.highlightPatch = again ? -1 : patch;
  if (!again) item.classList.add("selected");
  if (state.highlightPatch >= 0) {
    if (state.view !== "patches") setView("patches");
    else recolor();
    aimAtPatch(state.highlightPatch);
  } else {
    recolor();
  }
}

/** Turns the orbit centre to a patch so it is in view. */
function aimAtPatch(patch) {
  const { centroids, F } = state.mesh;
  const sum = new THREE.Vector3();
  let n = 0;
  for (let f = 0; f < F; f++) {
    if (state.layout.face_patch[f] !== patch) continue;
    sum.x += centroids[3 * f]; sum.y += centroids[3 * f + 1]; sum.z += centroids[3 * f + 2];
    n++;
  }
  if (n === 0) return;
  sum.divideScalar(n);
  camera.position.add(sum.clone().sub(controls.target));
  controls.target.copy(sum);
  controls.update();
  requestRender();
}

// ---------------------------------------------------------------------------
// Map: POST /api/param

let paramRequestId = 0;

async function requestParam() {
  if (!state.mesh) return null;
  clearTimeout(layoutTimer);
  const id = ++paramRequestId;
  const version = state.labelsVersion;
  $("map").disabled = true;
  $("layout-status").textContent = "mapping...";
  try {
    const answer = await api("/api/param", { body: { labels: labelsForServer() } });
    if (id !== paramRequestId) return answer;
    layoutRequestId++; // the map's layout is newer than any layout on its way
    showLayout(answer, version);
    showParam(answer, version);
    return answer;
  } finally {
    $("map").disabled = false;
  }
}

/** Puts corner_uv into the geometry's uv attribute and shows the isolines. */
function showParam(answer, version) {
  const F = state.mesh.F;
  const cornerUv = answer.corner_uv;
  if (!Array.isArray(cornerUv) || cornerUv.length !== 6 * F) {
    throw new Error(`the server's map has ${Array.isArray(cornerUv) ? cornerUv.length : "no"} corner_uv values, not ${6 * F}`);
  }
  const uv = surface.geometry.getAttribute("uv");
  const unmapped = new Uint8Array(F);
  for (let f = 0; f < F; f++) {
    let mapped = true;
    for (let i = 6 * f; i < 6 * f + 6; i++) if (typeof cornerUv[i] !== "number") mapped = false;
    unmapped[f] = mapped ? 0 : 1;
    for (let i = 6 * f; i < 6 * f + 6; i++) uv.array[i] = mapped ? cornerUv[i] : 0.025;
  }
  uv.needsUpdate = true;
  const fill = (array, value) => (Array.isArray(array) && array.length === F ? array : new Array(F).fill(value));
  state.param = {
    answer,
    unmapped,
    faceChart: fill(answer.face_chart, -1),
    distortion: fill(answer.face_area_distortion, null),
  };
  state.paramVersion = version;
  showSummary(answer.summary || {}, answer.milliseconds);
  setView("isolines");
}

function showSummary(summary, milliseconds) {
  const table = $("summary");
  table.textContent = "";
  table.classList.remove("stale");
  const number = (x, digits = 3) => (typeof x === "number" ? x.toFixed(digits) : "-");
  const rows = [
    ["charts", summary.charts ?? "-"],
    ["L2 stretch", number(summary.l2)],
    ["area distortion", number(summary.area)],
    ["angle distortion", number(summary.angle)],
    ["vertices moved", summary.moved ?? "-"],
    ["injective", summary.injective === undefined ? "-" : summary.injective ? "yes" : "no"],
  ];
  if (typeof milliseconds === "number") rows.push(["time", `${milliseconds.toFixed(0)} ms`]);
  for (const [name, value] of rows) {
    const tr = table.insertRow();
    tr.insertCell().textContent = name;
    tr.insertCell().textContent = String(value);
  }
  table.hidden = false;
}

// ---------------------------------------------------------------------------
// Files

function baseName() {
  return (state.mesh ? state.mesh.name : "mesh").replace(/\.[^.]*$/, "");
}

function download(blob, filename) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement("a");
  link.href = url;
  link.download = filename;
  document.body.appendChild(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** The label file the server writes for the current labels. */
function fetchLabelsText() {
  return api("/api/labels.txt", { body: { labels: Array.from(state.labels) }, as: "text" });
}

async function saveLabels() {
  const text = await fetchLabelsText();
  download(new Blob([text], { type: "text/plain" }), `${baseName()}.labels.txt`);
  const unpainted = countLabel(UNPAINTED);
  if (unpainted > 0) {
    showMessage(`${unpainted} unpainted faces are saved as one more region, label ${largestLabel() + 1}`);
  }
}

function largestLabel() {
  let largest = UNPAINTED;
  for (const l of state.labels) if (l > largest) largest = l;
  return largest;
}

/**
 * The labels a saved label file holds, one per polygon of the mesh file:
 * the server writes unpainted faces as one more region (the largest label
 * + 1), since a label file cannot say "none".
 */
function expectedFileLabels() {
  const { F, fileFace, facesInFile } = state.mesh;
  const unpainted = largestLabel() + 1;
  const result = new Array(facesInFile).fill(0);
  for (let f = 0; f < F; f++) {
    const l = state.labels[f];
    result[fileFace ? fileFace[f] : f] = l === UNPAINTED ? unpainted : l;
  }
  return result;
}

async function savePaintedPly() {
  const blob = await api("/api/painted.ply", { body: { labels: Array.from(state.labels) }, as: "blob" });
  download(blob, `${baseName()}.painted.ply`);
}

/** Parses a label file: integers separated by white space, `#` starts a comment. */
function parseLabelFile(text) {
  const labels = [];
  text.split(/\r?\n/).forEach((line, i) => {
    const content = line.replace(/#.*/, "").trim();
    if (!content) return;
    for (const word of content.split(/\s+/)) {
      if (!/^[-+]?\d+$/.test(word)) throw new Error(`label file, line ${i + 1}: "${word}" is not an integer`);
      labels.push(parseInt(word, 10));
    }
  });
  return labels;
}

async function loadLabelsFile(file) {
  const { F, fileFace, facesInFile } = state.mesh;
  let labels = parseLabelFile(await file.text());
  if (fileFace && labels.length === facesInFile && facesInFile !== F) {
    const perPolygon = labels; // one label per polygon of the file: give it to its triangles
    labels = fileFace.map((polygon) => perPolygon[polygon]);
  }
  if (labels.length !== F) {
    const polygons = facesInFile !== F ? ` (${facesInFile} polygons in its file)` : "";
    throw new Error(`${file.name} has ${labels.length} labels, but the mesh has ${F} faces${polygons}`);
  }
  replaceAllLabels(labels.map((l) => (l < 0 ? UNPAINTED : l)));
  showMessage(`loaded ${labels.length} labels from ${file.name}`);
}

async function openMeshFile(file) {
  const json = await api(`/api/mesh?name=${encodeURIComponent(file.name)}`, { body: file });
  showMesh(json);
  showMessage(`opened ${file.name}`);
  scheduleLayout();
}

function isMeshFile(name) {
  const lower = name.toLowerCase();
  return MESH_EXTENSIONS.some((ext) => lower.endsWith(ext));
}

// ---------------------------------------------------------------------------
// Tools, palette and controls

function setTool(tool) {
  state.tool = tool;
  for (const button of document.querySelectorAll("#tools button")) {
    button.classList.toggle("active", button.dataset.tool === tool);
  }
  brushCursor.visible = false;
  requestRender();
}

function setLabel(label) {
  state.label = label;
  growPaletteFor([label]);
  if (state.tool === "eraser" || state.tool === "orbit") setTool("brush");
  renderPalette();
}

function setRadius(percent) {
  state.radiusPercent = Math.min(RADIUS_MAX, Math.max(RADIUS_MIN, percent));
  $("radius").value = String(state.radiusPercent);
  $("radius-value").textContent = `${state.radiusPercent} % of the diagonal`;
}

function growPaletteFor(labels) {
  let top = -1;
  for (const l of labels) if (l > top) top = l;
  state.paletteSize = Math.min(MAX_PALETTE_BUTTONS, Math.max(state.paletteSize, top + 1));
}

function renderPalette() {
  const palette = $("palette");
  palette.textContent = "";
  for (let label = 0; label < state.paletteSize; label++) {
    const button = document.createElement("button");
    button.style.background = "#" + labelColor(label).getHexString();
    button.textContent = String(label);
    button.title = `label ${label}`;
    button.classList.toggle("active", label === state.label);
    button.addEventListener("click", () => setLabel(label));
    palette.appendChild(button);
  }
  const add = document.createElement("button");
  add.className = "add";
  add.textContent = "+";
  add.title = "add a label";
  add.disabled = state.paletteSize >= MAX_PALETTE_BUTTONS;
  add.addEventListener("click", () => {
    state.paletteSize++;
    setLabel(state.paletteSize - 1);
  });
  palette.appendChild(add);
}

/** Runs an async action from the UI; its error is shown, never thrown. */
function run(action) {
  return (...args) => Promise.resolve().then(() => action(...args)).catch(showError);
}

function wireUi() {
  for (const button of document.querySelectorAll("#tools button")) {
    button.addEventListener("click", () => setTool(button.dataset.tool));
  }
  for (const button of document.querySelectorAll("#views button")) {
    button.addEventListener("click", () => setView(button.dataset.view));
  }
  $("radius").addEventListener("input", (e) => setRadius(Number(e.target.value)));
  $("undo").addEventListener("click", undo);
  $("redo").addEventListener("click", redo);
  $("clear").addEventListener("click", () => state.mesh && replaceAllLabels(new Int32Array(state.mesh.F).fill(UNPAINTED)));
  $("show-sides").addEventListener("change", (e) => { overlay.visible = e.target.checked; requestRender(); });
  $("map").addEventListener("click", run(requestParam));
  $("save-labels").addEventListener("click", run(saveLabels));
  $("save-ply").addEventListener("click", run(savePaintedPly));
  $("load-labels-button").addEventListener("click", () => $("load-labels").click());
  $("open-mesh-button").addEventListener("click", () => $("open-mesh").click());
  $("load-labels").addEventListener("change", run(async (e) => {
    const file = e.target.files[0];
    e.target.value = "";
    if (file) await loadLabelsFile(file);
  }));
  $("open-mesh").addEventListener("change", run(async (e) => {
    const file = e.target.files[0];
    e.target.value = "";
    if (file) await openMeshFile(file);
  }));

  // drop a mesh or a label file on the view
  const view = $("view");
  view.addEventListener("dragover", (e) => { e.preventDefault(); view.classList.add("dragover"); });
  view.addEventListener("dragleave", () => view.classList.remove("dragover"));
  view.addEventListener("drop", run(async (e) => {
    e.preventDefault();
    view.classList.remove("dragover");
    const file = e.dataTransfer.files[0];
    if (!file) return;
    if (isMeshFile(file.name)) await openMeshFile(file);
    else await loadLabelsFile(file);
  }));

  window.addEventListener("keydown", onKeyDown);
}

function onKeyDown(e) {
  const target = e.target;
  if (target && (target.tagName === "TEXTAREA" || (target.tagName === "INPUT" && target.type !== "range" && target.type !== "checkbox"))) return;
  const key = e.key.toLowerCase();
  if (e.ctrlKey || e.metaKey) {
    if (key === "z" && !e.shiftKey) { e.preventDefault(); undo(); }
    else if (key === "y" || (key === "z" && e.shiftKey)) { e.preventDefault(); redo(); }
    return;
  }
  if (e.altKey) return;
  const actions = {
    b: () => setTool("brush"),
    e: () => setTool("eraser"),
    f: () => setTool("fill"),
    v: () => setTool("orbit"),
    "[": () => setRadius(state.radiusPercent - 1),
    "]": () => setRadius(state.radiusPercent + 1),
    m: run(requestParam),
    l: () => setView("patches"),
    p: () => setView("paint"),
    d: () => setView("distortion"),
  };
  if (actions[key]) {
    e.preventDefault();
    actions[key]();
  } else if (/^[1-9]$/.test(key)) {
    setLabel(Number(key) - 1);
  }
}

// ---------------------------------------------------------------------------
// Mouse: paint with the left button, orbit with the right one

let painting = false;
let pendingPointer = null; // latest pointer position, handled once per frame
let pointerFrame = 0;
let lastPaintPosition = null; // where the stroke painted last, client coordinates

function onPointerDown(e) {
  // OrbitControls acts on the mousedown that follows: say now what it should do.
  const orbitWithLeft = state.tool === "orbit" || e.altKey;
  controls.mouseButtons.LEFT = orbitWithLeft ? THREE.MOUSE.ROTATE : -1;
  controls.mouseButtons.RIGHT = e.shiftKey || e.ctrlKey ? THREE.MOUSE.PAN : THREE.MOUSE.ROTATE;
  if (e.button !== 0 || orbitWithLeft || !state.mesh) return;
  const hit = pickAt(e.clientX, e.clientY);
  if (state.tool === "fill") {
    if (hit) fillAt(hit.face);
    return;
  }
  painting = true;
  renderer.domElement.setPointerCapture(e.pointerId);
  beginStroke();
  paintAt(hit);
  lastPaintPosition = { x: e.clientX, y: e.clientY };
  moveBrushCursor(hit);
}

function onPointerMove(e) {
  pendingPointer = { x: e.clientX, y: e.clientY, buttons: e.buttons };
  if (!pointerFrame) pointerFrame = requestAnimationFrame(handlePointerMove);
}

function handlePointerMove() {
  pointerFrame = 0;
  if (!pendingPointer || !state.mesh) return;
  const brushTool = state.tool === "brush" || state.tool === "eraser";
  // no raycast while orbiting: the view is moving anyway
  if (!painting && (!brushTool || pendingPointer.buttons !== 0)) {
    if (brushCursor.visible) { brushCursor.visible = false; requestRender(); }
    return;
  }
  const hit = pickAt(pendingPointer.x, pendingPointer.y);
  if (painting) {
    paintBetween(lastPaintPosition, pendingPointer);
    paintAt(hit);
    lastPaintPosition = { x: pendingPointer.x, y: pendingPointer.y };
  }
  moveBrushCursor(brushTool ? hit : null);
}

/** Paints along the screen segment between two pointer positions, so a fast drag leaves no gaps. */
function paintBetween(from, to) {
  if (!from) return;
  const length = Math.hypot(to.x - from.x, to.y - from.y);
  const steps = Math.min(16, Math.floor(length / 8));
  for (let i = 1; i < steps; i++) {
    const t = i / steps;
    paintAt(pickAt(from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)));
  }
}

function onPointerUp(e) {
  if (!painting) return;
  painting = false;
  lastPaintPosition = null;
  if (renderer.domElement.hasPointerCapture(e.pointerId)) renderer.domElement.releasePointerCapture(e.pointerId);
  endStroke();
}

/** A translucent ball of the brush radius where the brush would paint. */
function moveBrushCursor(hit) {
  brushCursor.visible = !!hit;
  if (hit) {
    brushCursor.position.copy(hit.point);
    brushCursor.scale.setScalar(brushRadius());
    brushCursor.material.color.copy(state.tool === "eraser" ? UNPAINTED_COLOR : labelColor(state.label));
  }
  requestRender();
}

// ---------------------------------------------------------------------------
// Rendering

let renderQueued = false;

function requestRender() {
  if (renderQueued || !renderer) return;
  renderQueued = true;
  requestAnimationFrame(renderNow);
}

function renderNow() {
  renderQueued = false;
  renderer.render(scene, camera);
}

function setupRenderer() {
  const view = $("view");
  // preserveDrawingBuffer: the self test reads the pixels back, and headless
  // Chromium's screenshots show a blank canvas without it
  renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor("#eef0f4");
  view.appendChild(renderer.domElement);
  // the painting listener goes first: it sets up OrbitControls for this press
  renderer.domElement.addEventListener("pointerdown", onPointerDown);
  renderer.domElement.addEventListener("pointermove", onPointerMove);
  renderer.domElement.addEventListener("pointerup", onPointerUp);
  renderer.domElement.addEventListener("pointercancel", onPointerUp);
  renderer.domElement.addEventListener("pointerleave", () => {
    if (!painting && brushCursor.visible) { brushCursor.visible = false; requestRender(); }
  });

  scene = new THREE.Scene();
  camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
  scene.add(camera);
  scene.add(new THREE.HemisphereLight("#ffffff", "#808088", 0.55));
  const headlight = new THREE.DirectionalLight("#ffffff", 0.55);
  headlight.position.set(0.3, 0.6, 1); // with the camera, so the side you look at is lit
  camera.add(headlight);

  controls = new OrbitControls(camera, renderer.domElement);
  controls.mouseButtons = { LEFT: -1, MIDDLE: THREE.MOUSE.DOLLY, RIGHT: THREE.MOUSE.ROTATE };
  controls.enableKeys = false;
  controls.screenSpacePanning = true;
  controls.addEventListener("change", requestRender);

  const surfaceMaterial = {
    vertexColors: THREE.VertexColors,
    side: THREE.DoubleSide,
    // the surface steps back a little so the side lines on it win the depth test
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  };
  colorMaterial = new THREE.MeshLambertMaterial(surfaceMaterial);
  isolineMaterial = new THREE.MeshLambertMaterial({ ...surfaceMaterial, map: makeIsolineTexture() });

  overlay = new THREE.Group();
  scene.add(overlay);
  brushCursor = new THREE.Mesh(
    new THREE.SphereBufferGeometry(1, 24, 16),
    new THREE.MeshBasicMaterial({ color: "#ffffff", transparent: true, opacity: 0.3, depthWrite: false }));
  brushCursor.visible = false;
  scene.add(brushCursor);

  const resize = () => {
    const width = Math.max(1, view.clientWidth), height = Math.max(1, view.clientHeight);
    renderer.setSize(width, height, false);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    requestRender();
  };
  new ResizeObserver(resize).observe(view);
  resize();
}

/** Looks at the whole mesh from the front, a little from above. */
function fitCamera() {
  const sphere = surface.geometry.boundingSphere;
  const radius = sphere.radius || 1;
  const distance = radius / Math.sin(THREE.Math.degToRad(camera.fov / 2)) * 1.05;
  const direction = new THREE.Vector3(0.25, 0.3, 1).normalize();
  camera.position.copy(sphere.center).addScaledVector(direction, distance);
  camera.near = distance / 100;
  camera.far = distance + radius * 10;
  camera.updateProjectionMatrix();
  controls.target.copy(sphere.center);
  controls.update();
  requestRender();
}

/** Renders now and counts the distinct colours of the canvas. */
function countCanvasColors() {
  renderNow();
  const gl = renderer.getContext();
  const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
  const pixels = new Uint8Array(4 * width * height);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const colors = new Set();
  for (let i = 0; i < pixels.length; i += 4) {
    colors.add((pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2]);
  }
  return { colors: colors.size, width, height };
}

// ---------------------------------------------------------------------------
// Self test (?test=1): drives the page as a user would, reports in #test-result

async function runSelfTest() {
  const checks = [];
  const check = (name, ok, detail) => checks.push({ name, ok: !!ok, detail });
  const F = state.mesh ? state.mesh.F : 0;
  try {
    if (!state.mesh) throw new Error("no mesh loaded");
    // start from nothing painted, so label 1 counts only the stroke's faces
    if (countLabel(UNPAINTED) !== F) state.labels.fill(UNPAINTED);
    state.undoStack = []; state.redoStack = [];
    setView("paint");
    setTool("brush");
    setLabel(1);
    setRadius(5);
    renderNow();

    // (a) a stroke at the centre of the canvas, through the mouse's picking code
    const rect = renderer.domElement.getBoundingClientRect();
    const hit = pickAt(rect.left + rect.width / 2, rect.top + rect.height / 2);
    let painted = 0;
    if (!hit) {
      check("brush stroke", false, "the centre of the canvas is not on the mesh");
    } else {
      beginStroke();
      paintAt(hit);
      endStroke();
      painted = countLabel(1);
      const radius = brushRadius();
      const all = surfaceDistances(hit.face); // no limit: every face's distance
      const distance = new Float64Array(F).fill(Infinity);
      all.faces.forEach((f, i) => { distance[f] = all.distances[i]; });
      let outside = 0, missed = 0;
      for (let f = 0; f < F; f++) {
        if (state.labels[f] === 1 && !(distance[f] <= radius)) outside++;
        if (state.labels[f] !== 1 && distance[f] <= radius) missed++;
      }
      check("brush stroke", painted > 0 && outside === 0 && missed === 0 && state.labels[hit.face] === 1,
        { picked_face: hit.face, labelled: painted, radius, outside_radius: outside, missed_within_radius: missed,
          picked_face_labelled: state.labels[hit.face] === 1 });
    }

    // (b) one stroke is one undo step
    undo();
    const afterUndo = countLabel(1);
    redo();
    const afterRedo = countLabel(1);
    check("undo redo", afterUndo === 0 && afterRedo === painted && painted > 0,
      { after_undo: afterUndo, after_redo: afterRedo, stroke: painted });

    // (c) the saved label file reads back as the page's labels (unpainted
    // faces as the one more region the server makes of them)
    const text = await fetchLabelsText();
    const saved = parseLabelFile(text);
    const expected = expectedFileLabels();
    let differ = saved.length === expected.length ? 0 : -1;
    if (differ === 0) for (let i = 0; i < expected.length; i++) if (saved[i] !== expected[i]) differ++;
    check("labels file", differ === 0 && countLabel(1) > 0,
      { lines: saved.length, expected: expected.length, differing: differ, unpainted_saved_as: largestLabel() + 1,
        ones_in_file: saved.filter((l) => l === 1).length });

    // (d) the layout of these labels, drawn
    const layout = await requestLayout();
    check("layout", layout && layout.patches > 0 && state.sidePolylineCount > 0 && state.layout === layout,
      { patches: layout && layout.patches, side_polylines: state.sidePolylineCount, corners: state.cornerCount,
        problems: layout && layout.problems ? layout.problems.length : null });

    // (e) the map, applied to the geometry's uv
    const param = await requestParam();
    const cornerUv = param && param.corner_uv;
    const uv = surface.geometry.getAttribute("uv").array;
    let mismatched = 0, mapped = 0;
    if (Array.isArray(cornerUv) && cornerUv.length === 6 * F) {
      for (let f = 0; f < F; f++) {
        if (state.param.unmapped[f]) continue;
        mapped++;
        for (let i = 6 * f; i < 6 * f + 6; i++) if (Math.abs(uv[i] - cornerUv[i]) > 1e-6) mismatched++;
      }
    }
    check("map", Array.isArray(cornerUv) && cornerUv.length === 6 * F && mismatched === 0 && mapped > 0 &&
      state.view === "isolines",
      { corner_uv: cornerUv ? cornerUv.length : null, expected: 6 * F, mapped_faces: mapped, mismatched,
        view: state.view, summary: param && param.summary });

    // (f) the canvas shows something
    const pixels = countCanvasColors();
    check("canvas not blank", pixels.colors > 10, pixels);
  } catch (e) {
    check("no exception", false, String((e && e.stack) || e));
  }
  const result = { ok: checks.length > 0 && checks.every((c) => c.ok), faces: F, checks };
  const out = $("test-result");
  out.textContent = JSON.stringify(result, null, 1);
  out.hidden = false;
  document.title = "done";
  return result;
}

// ---------------------------------------------------------------------------
// Start

async function loadMeshFromServer() {
  showMesh(await api("/api/mesh"));
}

async function main() {
  window.addEventListener("error", (e) => showError(e.error || e.message));
  window.addEventListener("unhandledrejection", (e) => showError(e.reason));
  setupRenderer();
  wireUi();
  setTool("brush");
  setRadius(state.radiusPercent);
  renderPalette();
  updateUndoButtons();
  setView("paint");
  try {
    await loadMeshFromServer();
  } catch (e) {
    // Started without a mesh: not an error, the first step.
    if (String(e && e.message).includes("no mesh is loaded")) {
      showMessage("Open a mesh (Open mesh, or drop a .off .obj .ply .stl file on the view).", "info");
    } else {
      showError(e);
    }
  }
  if (TEST_MODE) {
    await runSelfTest();
  } else if (state.mesh) {
    // ?view=patches, isolines or distortion opens the page on that view (a link, a screenshot).
    const view = new URLSearchParams(window.location.search).get("view");
    if (view === "isolines" || view === "distortion") {
      await requestParam().catch(showError);
      setView(view);
    } else {
      await requestLayout().catch(showError);
      if (view === "patches") setView("patches");
    }
  }
}

// For tests and the console: the painting and picking functions.
window.diffuvPainter = {
  state, pickAt, paintAt, beginStroke, endStroke, fillAt, undo, redo,
  setTool, setLabel, setRadius, setView, brushRadius, surfaceDistances, countLabel,
  requestLayout, requestParam, fetchLabelsText, parseLabelFile, replaceAllLabels,
  renderNow, countCanvasColors, runSelfTest,
  /** A whole stroke through the given client points, as the mouse would paint it. */
  strokeThrough(points, label = toolLabel()) {
    beginStroke();
    for (const [x, y] of points) paintAt(pickAt(x, y), label);
    endStroke();
    return countLabel(label);
  },
};

main();
