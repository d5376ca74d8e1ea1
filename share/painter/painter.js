// diffuv painter: paint regions on a mesh, see diffuv's patches and map;
// with a second mesh (B), paint the same regions on it and see the
// correspondence of A and B.
//
// Served by `diffuv serve` with three.js (Debian's libjs-three, r111) under
// /three/. three itself is imported by the same URL OrbitControls resolves
// ("../../../build/three.module.js"), so both share one module instance.
//
// Each mesh is drawn non-indexed: face f owns vertices 3f..3f+2 of the
// geometry, so per-face colours are plain vertex colours and a raycast's
// faceIndex is the face id the server uses.
//
// Mesh A and mesh B are two "sides" (makeSide()): each has its own labels,
// undo history, layout, map, and its own canvas, camera and orbit controls.
// Without B only A's canvas is shown and the page is the one-mesh painter.

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
// The sides are drawn as a coloured stripe in a dark outline, which tells
// them from the region colours (some of which have the same hues).
const SIDE_COLORS = { u1: "#ff2d2d", u2: "#ffb000", v1: "#2f7bff", v2: "#00e0d0" };
const SIDE_OUTLINE_COLOR = "#161618";
const SIDE_NAMES = ["u1", "u2", "v1", "v2"];
const HIGHLIGHT_COLOR = new THREE.Color("#ffd000");
const FADED = new THREE.Color("#e8e8ec");
const UNMAPPED_COLOR = new THREE.Color("#555555");
const UNPAIRED_COLOR = new THREE.Color("#a4a4aa");
const MARKER_COLOR = "#ff00d4";
const LAYOUT_DELAY_MS = 300;
const CORRESPOND_DELAY_MS = 400;
const RADIUS_MIN = 1;   // percent of the bounding box diagonal
const RADIUS_MAX = 20;
const MESH_EXTENSIONS = [".off", ".obj", ".ply", ".stl"];
const PARAMS = new URLSearchParams(window.location.search);
const TEST_MODE = PARAMS.get("test") === "1";

// ---------------------------------------------------------------------------
// State

/** One mesh of the page (A, the mesh painted, or B, the second mesh) and its view. */
function makeSide(key) {
  return {
    key,                 // "a" or "b": the server's ?mesh=
    title: key.toUpperCase(),
    mesh: null,          // see buildMesh()
    labels: null,        // Int32Array, one label per face, UNPAINTED = -1
    labelsVersion: 0,    // bumped on every change of labels
    stroke: null,        // Map face -> label before the stroke, while painting
    undoStack: [],       // steps {faces, before, after}
    redoStack: [],
    layout: null,        // last /api/layout (or /api/param) answer
    layoutVersion: -1,   // labelsVersion the layout was computed for
    layoutRequestId: 0,
    layoutTimer: 0,
    layoutStatus: "",
    param: null,         // last /api/param answer, plus what the page made of it
    paramVersion: -1,
    paramRequestId: 0,
    highlightPatch: -1,  // patch of the selected problem, or -1
    sidePolylineCount: 0,
    cornerCount: 0,
    // three.js: each side has its own canvas, renderer, scene, camera, controls
    viewport: null, renderer: null, scene: null, camera: null, controls: null,
    surface: null, overlay: null, brushCursor: null, marker: null, resize: null,
    framed: false,       // the camera is where fitCamera() put it (the user has not turned the view)
    colorMaterial: null, isolineMaterial: null,
    renderQueued: false,
  };
}

const sides = { a: makeSide("a"), b: makeSide("b") };
const SIDES = [sides.a, sides.b];

const state = {
  tool: "brush",       // brush | eraser | fill | pick | orbit
  toolBeforePick: "brush",
  label: 0,            // the label the brush and the fill paint
  radiusPercent: 5,    // brush radius, percent of the bounding box diagonal
  paletteSize: INITIAL_LABEL_COUNT,
  view: "paint",       // paint | patches | isolines | distortion | correspond
  active: sides.a,     // the mesh undo, clear and the files act on: the last one painted or clicked
  corrColors: "charts", // correspondence colouring: charts | gradient
  corr: null,          // last /api/correspond answer and what the page made of it
  pick: null,          // {face, barycentric, point} picked on A, and its image on B
};
// The one-mesh names of the first version (console, scripts): mesh A's.
for (const name of ["mesh", "labels", "layout", "param", "undoStack", "redoStack"]) {
  Object.defineProperty(state, name, { get: () => sides.a[name] });
}

const raycaster = new THREE.Raycaster();
const $ = (id) => document.getElementById(id);
const hasB = () => !!sides.b.mesh;
const loadedSides = () => SIDES.filter((side) => side.mesh);

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
      const error = new Error(`${path}: ${message}`);
      error.status = response.status;
      throw error;
    }
    if (as === "text") return await response.text();
    if (as === "blob") return await response.blob();
    return await response.json();
  } finally {
    setBusy(-1);
  }
}

/** An API path about a side's mesh: B's requests carry ?mesh=b, A's nothing (A is the default). */
function sidePath(side, path, params = {}) {
  const query = new URLSearchParams(params);
  if (side.key !== "a") query.set("mesh", side.key);
  const text = query.toString();
  return text ? `${path}?${text}` : path;
}

/** The labels as the server wants them: [] when nothing is painted (automatic layout). */
function labelsForServer(side) {
  const labels = side.labels;
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

/** A point's place in B's bounding box as a colour (x red, y green, z blue), into out[at..at+2]. */
function gradientColorInto(out, at, x, y, z, box) {
  const { min, size } = box;
  const channel = (value, d) => 0.08 + 0.87 * Math.min(1, Math.max(0, size[d] > 0 ? (value - min[d]) / size[d] : 0.5));
  out[at] = channel(x, 0); out[at + 1] = channel(y, 1); out[at + 2] = channel(z, 2);
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
  // the bounding box: the correspondence view colours B by the place in it
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < V; v++) {
    for (let d = 0; d < 3; d++) {
      min[d] = Math.min(min[d], positions[3 * v + d]);
      max[d] = Math.max(max[d], positions[3 * v + d]);
    }
  }
  const box = { min, size: [max[0] - min[0], max[1] - min[1], max[2] - min[2]] };
  return {
    name: String(json.name || "mesh"), labelSource: String(json.label_source || ""), fileFace, facesInFile,
    V, F, positions, faces, centroids, box,
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

/** Replaces a side's mesh by the server's answer (GET or POST /api/mesh). */
function showMesh(side, json) {
  const mesh = buildMesh(json);
  side.mesh = mesh;
  side.labels = new Int32Array(mesh.F).fill(UNPAINTED);
  if (Array.isArray(json.labels)) {
    if (json.labels.length === mesh.F) {
      side.labels.set(json.labels.map((l) => (Number.isInteger(l) && l >= 0 ? l : UNPAINTED)));
    } else {
      showError(`${side.title}: the mesh came with ${json.labels.length} labels for ${mesh.F} faces; ignored`);
    }
  }
  side.labelsVersion++;
  side.stroke = null;
  side.undoStack = [];
  side.redoStack = [];
  side.layout = null;
  side.param = null;
  side.layoutStatus = "";
  side.highlightPatch = -1;
  growPaletteFor(side.labels);
  // a new mesh on either side: the correspondence and the picked point are gone
  state.corr = null;
  state.pick = null;
  showCorrespondenceReport();

  if (side.surface) {
    side.scene.remove(side.surface);
    side.surface.geometry.dispose();
  }
  side.surface = new THREE.Mesh(buildGeometry(mesh), side.colorMaterial);
  side.scene.add(side.surface);
  clearOverlay(side);
  updateSidesUi();
  fitCamera(side);

  showSummary(); // the maps of the meshes still shown
  if (side === sides.a) {
    setView("paint");
  } else if (state.view !== "paint" && state.view !== "patches") {
    setView("paint");
  } else {
    recolor(side);
  }
  showLayoutStatus();
  showProblems();
  updateUndoButtons();
  renderPalette();
}

/** Shows or hides what belongs to mesh B: its viewport, the correspondence, the A/B choice. */
function updateSidesUi() {
  const two = hasB();
  const changed = $("view").classList.contains("two") !== two;
  $("view").classList.toggle("two", two);
  sides.b.viewport.hidden = !two;
  if (changed) {
    // A's canvas is half as wide, or whole again: new aspects, frame the meshes again
    for (const side of SIDES) side.resize();
    for (const side of loadedSides()) fitCamera(side);
  }
  for (const id of ["correspond-view", "pick-tool", "corr-section", "target-row"]) $(id).hidden = !two;
  if (!two && state.active !== sides.a) state.active = sides.a;
  const info = (side) => {
    const mesh = side.mesh;
    const unpainted = countLabel(side, UNPAINTED);
    return `${mesh.name}: ${mesh.V} vertices, ${mesh.F} faces` +
      (mesh.labelSource && unpainted < mesh.F ? `; ${mesh.labelSource}` : "");
  };
  const a = sides.a, b = sides.b;
  if (!two) {
    $("mesh-info").textContent = a.mesh ? info(a) : "no mesh";
    if (a.mesh) document.title = `${a.mesh.name} - diffuv painter`;
  } else {
    $("mesh-info").textContent = `A: ${a.mesh ? info(a) : "no mesh"}\nB: ${info(b)}`;
    document.title = `${a.mesh ? a.mesh.name : "-"} and ${b.mesh.name} - diffuv painter`;
  }
  for (const side of SIDES) {
    const caption = side.viewport.querySelector(".caption");
    caption.textContent = `${side.title}${side.mesh ? ": " + side.mesh.name : ""}`;
  }
  setActive(state.active);
}

/** The mesh undo, clear and the files act on (the last one painted or clicked). */
function setActive(side) {
  if (!side.mesh && side !== sides.a) return;
  state.active = side;
  const two = hasB();
  for (const s of SIDES) s.viewport.classList.toggle("active", two && s === side);
  for (const button of document.querySelectorAll("#target button")) {
    button.classList.toggle("active", button.dataset.side === side.key);
  }
  const which = two ? ` of ${side.title}` : "";
  $("save-labels").textContent = `Save labels${which}`;
  $("save-ply").textContent = `Save painted PLY${which}`;
  $("load-labels-button").textContent = `Load labels${which ? " on " + side.title : ""}`;
  $("target-name").textContent = side.mesh ? `${side.title} (${side.mesh.name})` : side.title;
  updateUndoButtons();
}

// ---------------------------------------------------------------------------
// Surface colours per view

/** Colour of face f of a side in the current view. */
function faceColor(side, f) {
  const { view } = state;
  const { labels, layout, param } = side;
  if (view === "correspond" && state.corr) {
    const color = correspondFaceColor(side, f);
    if (color) return color;
  }
  if (view === "patches" && layout) {
    const patch = layout.face_patch[f];
    if (side.highlightPatch >= 0) {
      // the selected problem's patch in yellow, the others faded
      if (patch === side.highlightPatch) return HIGHLIGHT_COLOR;
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

/** Writes the colour of the given faces of a side (all when faces is omitted). */
function recolor(side, faces) {
  if (!side.surface) return;
  const attribute = side.surface.geometry.getAttribute("color");
  const colors = attribute.array;
  // the correspondence's "position on B" colours the corners, not the faces
  const corners = state.view === "correspond" && state.corr && state.corrColors === "gradient"
    ? state.corr.gradient[side.key] : null;
  const sent = state.view === "correspond" && state.corr ? state.corr.sent[side.key] : null;
  const { faces: vertexOf } = side.mesh;
  const write = (f) => {
    if (corners && sent[f] === side.labels[f]) {
      for (let k = 0; k < 3; k++) {
        const v = vertexOf[3 * f + k];
        colors[9 * f + 3 * k] = corners[3 * v]; colors[9 * f + 3 * k + 1] = corners[3 * v + 1]; colors[9 * f + 3 * k + 2] = corners[3 * v + 2];
      }
      return;
    }
    const c = faceColor(side, f);
    for (let k = 0; k < 3; k++) {
      colors[9 * f + 3 * k] = c.r; colors[9 * f + 3 * k + 1] = c.g; colors[9 * f + 3 * k + 2] = c.b;
    }
  };
  if (faces) for (const f of faces) write(f);
  else for (let f = 0; f < side.mesh.F; f++) write(f);
  attribute.needsUpdate = true;
  requestRender(side);
}

function recolorAll() {
  for (const side of loadedSides()) recolor(side);
}

function setView(view) {
  if ((view === "isolines" || view === "distortion") && !loadedSides().some((side) => side.param)) {
    showMessage("press Map first: the isolines and the distortion come from the map");
    return;
  }
  if (view === "correspond" && !hasB()) {
    showMessage("open a second mesh (Open mesh B) first: the correspondence maps A onto B");
    return;
  }
  const previous = state.view;
  state.view = view;
  if (view === "patches") {
    for (const side of loadedSides()) if (!side.layout) requestLayout(side).catch(showError);
  }
  if (view === "correspond") {
    if (state.tool !== "pick") {
      state.toolBeforePick = state.tool;
      setTool("pick");
    }
    if (!correspondenceCurrent()) requestCorrespond().catch(showError);
  } else if (previous === "correspond" && state.tool === "pick") {
    setTool(state.toolBeforePick === "pick" ? "brush" : state.toolBeforePick);
  }
  for (const side of SIDES) {
    if (side.surface) side.surface.material = view === "isolines" && side.param ? side.isolineMaterial : side.colorMaterial;
    if (side.brushCursor) side.brushCursor.visible = false;
    if (side.overlay) side.overlay.visible = overlayShown();
  }
  for (const button of document.querySelectorAll("#views button")) {
    button.classList.toggle("active", button.dataset.view === view);
  }
  $("distortion-legend").hidden = view !== "distortion";
  $("corr-legend").hidden = view !== "correspond";
  showMarkers();
  recolorAll();
}

// ---------------------------------------------------------------------------
// Picking

/** The face of a side under a point of the page (client coordinates), or null. */
function pickAt(side, clientX, clientY) {
  if (!side.surface) return null;
  const rect = side.renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(
    ((clientX - rect.left) / rect.width) * 2 - 1,
    -((clientY - rect.top) / rect.height) * 2 + 1);
  side.camera.updateMatrixWorld();
  raycaster.setFromCamera(ndc, side.camera);
  const hits = raycaster.intersectObject(side.surface, false);
  if (hits.length === 0) return null;
  return { face: hits[0].faceIndex, point: hits[0].point.clone() };
}

/** The centre of a side's canvas in client coordinates. */
function canvasCentre(side) {
  const rect = side.renderer.domElement.getBoundingClientRect();
  return [rect.left + rect.width / 2, rect.top + rect.height / 2];
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
function surfaceDistances(side, startFace, maxDistance = Infinity) {
  const { adjStart, adjFace, adjLength, distance } = side.mesh;
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

/** The brush radius on a side's mesh: a percentage of its own diagonal. */
function brushRadius(side) {
  return (state.radiusPercent / 100) * side.mesh.diagonal;
}

// ---------------------------------------------------------------------------
// Painting, strokes, undo (each side has its own history)

function beginStroke(side) {
  if (side.stroke) endStroke(side);
  side.stroke = new Map();
  // the isolines and the distortion do not show labels: paint where one can see it
  if (state.view === "isolines" || state.view === "distortion") setView("paint");
}

/** Sets face labels inside the current stroke, remembering what they were. */
function setLabels(side, faces, label) {
  const changed = [];
  for (const f of faces) {
    if (side.labels[f] === label) continue;
    if (side.stroke && !side.stroke.has(f)) side.stroke.set(f, side.labels[f]);
    side.labels[f] = label;
    changed.push(f);
  }
  if (changed.length > 0) {
    side.labelsVersion++;
    if (state.view === "paint" || state.view === "correspond") recolor(side, changed);
  }
  return changed.length;
}

/** The label the active tool paints. */
function toolLabel() {
  return state.tool === "eraser" ? UNPAINTED : state.label;
}

/** Paints the faces within the brush radius along the surface of hit.face. */
function paintAt(side, hit, label = toolLabel()) {
  if (!hit || !side.mesh) return 0;
  const { faces } = surfaceDistances(side, hit.face, brushRadius(side));
  return setLabels(side, faces, label);
}

/** Ends a stroke: one undo step, then the patches are recomputed shortly. */
function endStroke(side) {
  const stroke = side.stroke;
  side.stroke = null;
  if (!stroke) return;
  const faces = [], before = [], after = [];
  for (const [f, old] of stroke) {
    if (side.labels[f] === old) continue;
    faces.push(f); before.push(old); after.push(side.labels[f]);
  }
  if (faces.length === 0) return;
  side.undoStack.push({ faces: Int32Array.from(faces), before: Int32Array.from(before), after: Int32Array.from(after) });
  side.redoStack = [];
  updateUndoButtons();
  labelsChanged(side);
}

/** Gives the connected region of faces with the clicked face's label the current label. */
function fillAt(side, face, label = state.label) {
  if (!side.mesh || face < 0 || face >= side.mesh.F) return 0;
  const { adjStart, adjFace } = side.mesh;
  const target = side.labels[face];
  if (target === label) return 0;
  const seen = new Uint8Array(side.mesh.F);
  const region = [face];
  seen[face] = 1;
  for (let i = 0; i < region.length; i++) {
    const f = region[i];
    for (let j = adjStart[f]; j < adjStart[f + 1]; j++) {
      const g = adjFace[j];
      if (!seen[g] && side.labels[g] === target) { seen[g] = 1; region.push(g); }
    }
  }
  beginStroke(side);
  const count = setLabels(side, region, label);
  endStroke(side);
  return count;
}

/** Replaces every label (a loaded file, Clear) as one undoable step. */
function replaceAllLabels(side, newLabels) {
  beginStroke(side);
  for (let f = 0; f < newLabels.length; f++) {
    if (side.labels[f] === newLabels[f]) continue;
    side.stroke.set(f, side.labels[f]);
    side.labels[f] = newLabels[f];
  }
  side.labelsVersion++;
  endStroke(side);
  growPaletteFor(side.labels);
  renderPalette();
  recolor(side);
}

function applyStep(side, step, which) {
  const values = step[which];
  for (let i = 0; i < step.faces.length; i++) side.labels[step.faces[i]] = values[i];
  side.labelsVersion++;
  if (state.view === "paint" || state.view === "correspond") recolor(side, step.faces);
  labelsChanged(side);
}

function undo(side = state.active) {
  if (side.stroke) endStroke(side);
  const step = side.undoStack.pop();
  if (!step) return false;
  applyStep(side, step, "before");
  side.redoStack.push(step);
  updateUndoButtons();
  return true;
}

function redo(side = state.active) {
  if (side.stroke) endStroke(side);
  const step = side.redoStack.pop();
  if (!step) return false;
  applyStep(side, step, "after");
  side.undoStack.push(step);
  updateUndoButtons();
  return true;
}

function updateUndoButtons() {
  const side = state.active;
  const which = hasB() ? ` (mesh ${side.title})` : "";
  $("undo").disabled = side.undoStack.length === 0;
  $("redo").disabled = side.redoStack.length === 0;
  $("undo").title = `Ctrl+Z: undo the last stroke${which}`;
  $("redo").title = `Ctrl+Y: redo${which}`;
  $("clear").title = `Unpaint every face${which}`;
}

/** After labels changed: the layout (and the correspondence) is out of date, ask again a moment later. */
function labelsChanged(side) {
  if (side.param) $("summary").classList.add("stale");
  side.layoutStatus = "labels changed: updating the patches...";
  showLayoutStatus();
  scheduleLayout(side);
  if (state.corr) {
    $("corr-report").classList.add("stale");
    if (state.view === "correspond") scheduleCorrespond();
  }
}

function countLabel(side, label) {
  let count = 0;
  for (const l of side.labels) if (l === label) count++;
  return count;
}

// ---------------------------------------------------------------------------
// Layout: patches, sides, corners, problems (for each mesh)

function scheduleLayout(side) {
  clearTimeout(side.layoutTimer);
  side.layoutTimer = setTimeout(() => requestLayout(side).catch(showError), LAYOUT_DELAY_MS);
}

/**
 * POST /api/layout with a side's current labels and shows the answer, unless
 * a newer request went out meanwhile. Resolves to the answer.
 */
async function requestLayout(side) {
  clearTimeout(side.layoutTimer);
  if (!side.mesh) return null;
  const id = ++side.layoutRequestId;
  const version = side.labelsVersion;
  side.layoutStatus = "computing the patches...";
  showLayoutStatus();
  let answer;
  try {
    answer = await api(sidePath(side, "/api/layout"), { body: { labels: labelsForServer(side) } });
  } catch (e) {
    if (id === side.layoutRequestId) {
      side.layoutStatus = "the patches could not be computed";
      showLayoutStatus();
    }
    throw e;
  }
  if (id === side.layoutRequestId) showLayout(side, answer, version);
  return answer;
}

/** Checks the shape of a layout answer, so a bad one is an error message, not a crash. */
function checkLayoutAnswer(side, answer) {
  const F = side.mesh.F;
  if (!answer || !Array.isArray(answer.face_patch) || answer.face_patch.length !== F) {
    throw new Error(`the server's layout of ${side.title} has no face_patch of ${F} values`);
  }
}

function showLayout(side, answer, version) {
  checkLayoutAnswer(side, answer);
  answer.problems = Array.isArray(answer.problems) ? answer.problems : [];
  side.layout = answer;
  side.layoutVersion = version;
  side.highlightPatch = -1;
  drawOverlay(side, answer);
  showProblems();
  const ms = Number(answer.milliseconds);
  side.layoutStatus =
    `${answer.patches} patches` + (Number.isFinite(ms) ? ` in ${ms.toFixed(0)} ms` : "") +
    (labelsForServer(side).length === 0 ? " (automatic layout: nothing painted)" : "");
  showLayoutStatus();
  if (state.view === "patches") recolor(side);
  requestRender(side);
}

/** One status line per mesh (just the line, with one mesh). */
function showLayoutStatus() {
  const shown = loadedSides();
  $("layout-status").textContent = hasB()
    ? shown.map((side) => `${side.title}: ${side.layoutStatus || "-"}`).join("\n")
    : sides.a.layoutStatus;
}

function clearOverlay(side) {
  for (const child of [...side.overlay.children]) {
    side.overlay.remove(child);
    child.geometry.dispose();
    child.material.dispose();
  }
  side.sidePolylineCount = 0;
  side.cornerCount = 0;
}

/**
 * Draws each patch's four sides as coloured stripes in a dark outline and
 * its corners as white dots ringed in black. A stripe lies on the surface
 * just inside its own patch, so where two patches meet both of their sides
 * show, side by side; it is lifted a little along the normals and the
 * surface has a polygon offset, so the surface does not hide it. The dark
 * outline sets the sides apart from region colours of the same hue.
 */
function drawOverlay(side, layout) {
  clearOverlay(side);
  const mesh = side.mesh;
  const { V, positions, vertexNormals, diagonal } = mesh;
  const lift = 0.001 * diagonal;
  const outlineWidth = 0.0065 * diagonal;
  const inset = 0.0014 * diagonal; // the stripe inside the outline: from inset to outlineWidth - inset
  const validVertex = (v) => Number.isInteger(v) && v >= 0 && v < V;
  const point = (v, scale = 1) => new THREE.Vector3(
    positions[3 * v] + scale * lift * vertexNormals[3 * v],
    positions[3 * v + 1] + scale * lift * vertexNormals[3 * v + 1],
    positions[3 * v + 2] + scale * lift * vertexNormals[3 * v + 2]);
  const patchSides = Array.isArray(layout.sides) ? layout.sides : [];
  const ribbonMaterial = (color, offset) => new THREE.MeshBasicMaterial({
    color, side: THREE.DoubleSide,
    polygonOffset: true, polygonOffsetFactor: offset, polygonOffsetUnits: 2 * offset,
  });
  const addRibbons = (triangles, material, name) => {
    if (triangles.length === 0) return;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(new Float32Array(triangles), 3));
    const ribbons = new THREE.Mesh(geometry, material);
    ribbons.name = name;
    side.overlay.add(ribbons);
  };
  // a quad across the segment, from `from` to `to` inward, as two triangles
  const quad = (out, a, b, inward, from, to) => {
    const a1 = a.clone().addScaledVector(inward, from), b1 = b.clone().addScaledVector(inward, from);
    const a2 = a.clone().addScaledVector(inward, to), b2 = b.clone().addScaledVector(inward, to);
    for (const c of [a1, b1, b2, a1, b2, a2]) out.push(c.x, c.y, c.z);
  };

  let polylines = 0;
  const outline = [];
  for (const name of SIDE_NAMES) {
    const stripe = []; // xyz of 6 vertices (2 triangles) a segment
    patchSides.forEach((four, patch) => {
      const polyline = four && four[name];
      if (!Array.isArray(polyline) || polyline.length < 2) return;
      let drawn = false;
      for (let i = 0; i + 1 < polyline.length; i++) {
        const p = polyline[i], q = polyline[i + 1];
        if (!validVertex(p) || !validVertex(q) || p === q) continue;
        const a = point(p), b = point(q);
        const inward = inwardDirection(side, p, q, patch, layout.face_patch, a, b);
        quad(outline, a, b, inward, 0, outlineWidth);
        quad(stripe, point(p, 1.4), point(q, 1.4), inward, inset, outlineWidth - inset);
        drawn = true;
      }
      if (drawn) polylines++;
    });
    addRibbons(stripe, ribbonMaterial(SIDE_COLORS[name], -2), "side-" + name);
  }
  addRibbons(outline, ribbonMaterial(SIDE_OUTLINE_COLOR, -1), "side-outlines");
  side.sidePolylineCount = polylines;

  const cornerVertices = new Set();
  for (const corners of Array.isArray(layout.corners) ? layout.corners : []) {
    if (Array.isArray(corners)) for (const v of corners) if (validVertex(v)) cornerVertices.add(v);
  }
  if (cornerVertices.size > 0) {
    // a white ball in a slightly larger black one seen from inside: a ringed dot
    const radius = 0.0048 * diagonal;
    const dots = [
      [new THREE.SphereBufferGeometry(radius * 1.45, 10, 8), new THREE.MeshBasicMaterial({ color: SIDE_OUTLINE_COLOR, side: THREE.BackSide }), "corner-rings"],
      [new THREE.SphereBufferGeometry(radius, 10, 8), new THREE.MeshLambertMaterial({ color: "#ffffff" }), "corners"],
    ];
    const matrix = new THREE.Matrix4();
    for (const [geometry, material, name] of dots) {
      const spheres = new THREE.InstancedMesh(geometry, material, cornerVertices.size);
      let i = 0;
      for (const v of cornerVertices) {
        const c = point(v);
        spheres.setMatrixAt(i++, matrix.makeTranslation(c.x, c.y, c.z));
      }
      spheres.instanceMatrix.needsUpdate = true;
      spheres.name = name;
      side.overlay.add(spheres);
    }
  }
  side.cornerCount = cornerVertices.size;
  side.overlay.visible = overlayShown();
}

/** The layout's sides and corners show when asked, but not over the correspondence (its charts are not the layout's patches). */
function overlayShown() {
  return $("show-sides").checked && state.view !== "correspond";
}

/**
 * Unit vector across the edge (p, q), on the surface, pointing into the face
 * of the edge that belongs to the patch (a and b: the edge's end points).
 */
function inwardDirection(side, p, q, patch, facePatch, a, b) {
  const { V, centroids, vertexNormals, facesOfEdge } = side.mesh;
  const along = b.clone().sub(a).normalize();
  let seen = facesOfEdge.get(edgeKey(p, q, V));
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

/** Lists the problems of every mesh's layout (tagged A or B when there are two). */
function showProblems() {
  const list = $("problems");
  list.textContent = "";
  let count = 0;
  for (const side of loadedSides()) {
    const problems = side.layout && Array.isArray(side.layout.problems) ? side.layout.problems : [];
    count += problems.length;
    problems.forEach((problem) => {
      const item = document.createElement("li");
      if (hasB()) {
        const tag = document.createElement("span");
        tag.className = "side-tag";
        tag.textContent = side.title;
        item.appendChild(tag);
      }
      const kind = document.createElement("span");
      kind.className = "kind";
      kind.textContent = String(problem.kind || "problem");
      item.appendChild(kind);
      const hasPatch = Number.isInteger(problem.patch) && problem.patch >= 0;
      item.appendChild(document.createTextNode((hasPatch ? `patch ${problem.patch}: ` : "") + String(problem.message || "")));
      item.addEventListener("click", () => selectProblem(side, problem, item));
      list.appendChild(item);
    });
  }
  $("problem-count").textContent = count ? `(${count})` : "";
}

/** Highlights the problem's patch on its mesh's surface (a second click clears it). */
function selectProblem(side, problem, item) {
  const patch = Number.isInteger(problem.patch) ? problem.patch : -1;
  const again = side.highlightPatch === patch && item.classList.contains("selected");
  for (const li of $("problems").children) li.classList.remove("selected");
  for (const s of SIDES) s.highlightPatch = -1;
  side.highlightPatch = again ? -1 : patch;
  if (!again) item.classList.add("selected");
  setActive(side);
  if (side.highlightPatch >= 0) {
    if (state.view !== "patches") setView("patches");
    else recolorAll();
    aimAtPatch(side, side.highlightPatch);
  } else {
    recolorAll();
  }
}

/** Turns a side's orbit centre to a patch so it is in view. */
function aimAtPatch(side, patch) {
  const { centroids, F } = side.mesh;
  const sum = new THREE.Vector3();
  let n = 0;
  for (let f = 0; f < F; f++) {
    if (side.layout.face_patch[f] !== patch) continue;
    sum.x += centroids[3 * f]; sum.y += centroids[3 * f + 1]; sum.z += centroids[3 * f + 2];
    n++;
  }
  if (n === 0) return;
  sum.divideScalar(n);
  side.framed = false;
  side.camera.position.add(sum.clone().sub(side.controls.target));
  side.controls.target.copy(sum);
  side.controls.update();
  requestRender(side);
}

// ---------------------------------------------------------------------------
// Map: POST /api/param

async function requestParam(side) {
  if (!side.mesh) return null;
  clearTimeout(side.layoutTimer);
  const id = ++side.paramRequestId;
  const version = side.labelsVersion;
  $("map").disabled = true;
  side.layoutStatus = "mapping...";
  showLayoutStatus();
  try {
    const answer = await api(sidePath(side, "/api/param"), { body: { labels: labelsForServer(side) } });
    if (id !== side.paramRequestId) return answer;
    side.layoutRequestId++; // the map's layout is newer than any layout on its way
    showLayout(side, answer, version);
    showParam(side, answer, version);
    return answer;
  } catch (e) {
    if (id === side.paramRequestId) {
      side.layoutStatus = "the map could not be computed";
      showLayoutStatus();
    }
    throw e;
  } finally {
    $("map").disabled = false;
  }
}

/** Map (M): every mesh shown, one after the other (the server works on one at a time). */
async function mapAll() {
  const answers = [];
  for (const side of loadedSides()) answers.push(await requestParam(side));
  return answers;
}

/** Puts corner_uv into the geometry's uv attribute and shows the isolines. */
function showParam(side, answer, version) {
  const F = side.mesh.F;
  const cornerUv = answer.corner_uv;
  if (!Array.isArray(cornerUv) || cornerUv.length !== 6 * F) {
    throw new Error(`the server's map of ${side.title} has ${Array.isArray(cornerUv) ? cornerUv.length : "no"} corner_uv values, not ${6 * F}`);
  }
  const uv = side.surface.geometry.getAttribute("uv");
  const unmapped = new Uint8Array(F);
  for (let f = 0; f < F; f++) {
    let mapped = true;
    for (let i = 6 * f; i < 6 * f + 6; i++) if (typeof cornerUv[i] !== "number") mapped = false;
    unmapped[f] = mapped ? 0 : 1;
    for (let i = 6 * f; i < 6 * f + 6; i++) uv.array[i] = mapped ? cornerUv[i] : 0.025;
  }
  uv.needsUpdate = true;
  const fill = (array, value) => (Array.isArray(array) && array.length === F ? array : new Array(F).fill(value));
  side.param = {
    answer,
    unmapped,
    faceChart: fill(answer.face_chart, -1),
    distortion: fill(answer.face_area_distortion, null),
  };
  side.paramVersion = version;
  showSummary();
  setView("isolines");
}

/** The map's summary: one column per mapped mesh. */
function showSummary() {
  const table = $("summary");
  table.textContent = "";
  table.classList.remove("stale");
  const mapped = loadedSides().filter((side) => side.param);
  if (mapped.length === 0) { table.hidden = true; return; }
  const number = (x, digits = 3) => (typeof x === "number" ? x.toFixed(digits) : "-");
  const rows = [
    ["charts", (s) => s.charts ?? "-"],
    ["L2 stretch", (s) => number(s.l2)],
    ["area distortion", (s) => number(s.area)],
    ["angle distortion", (s) => number(s.angle)],
    ["vertices moved", (s) => s.moved ?? "-"],
    ["injective", (s) => (s.injective === undefined ? "-" : s.injective ? "yes" : "no")],
    ["time", (s, ms) => (typeof ms === "number" ? `${ms.toFixed(0)} ms` : "-")],
  ];
  if (hasB()) {
    const head = table.insertRow();
    head.insertCell();
    for (const side of mapped) head.insertCell().textContent = side.title;
    head.className = "head";
  }
  for (const [name, value] of rows) {
    const tr = table.insertRow();
    tr.insertCell().textContent = name;
    for (const side of mapped) {
      const answer = side.param.answer;
      tr.insertCell().textContent = String(value(answer.summary || {}, answer.milliseconds));
    }
  }
  table.hidden = false;
}

// ---------------------------------------------------------------------------
// Correspondence: POST /api/correspond (A onto B through (region, u, v))

let corrTimer = 0;
let corrRequestId = 0;

function scheduleCorrespond() {
  clearTimeout(corrTimer);
  corrTimer = setTimeout(() => requestCorrespond().catch(showError), CORRESPOND_DELAY_MS);
}

/** True when the shown correspondence is that of both meshes' current labels. */
function correspondenceCurrent() {
  const corr = state.corr;
  return !!corr && corr.version.a === sides.a.labelsVersion && corr.version.b === sides.b.labelsVersion;
}

/**
 * The labels of both meshes as /api/correspond takes them. The same number
 * names the same region on both; unpainted faces (-1) become one more
 * region, the same number on both meshes (the largest label of either + 1:
 * "the rest" of A pairs with the rest of B). A mesh with nothing painted
 * is sent as is, and the server says it has no regions.
 */
function correspondLabels() {
  let top = UNPAINTED;
  for (const side of SIDES) for (const l of side.labels) if (l > top) top = l;
  const rest = top + 1;
  const forServer = (labels) => (labels.every((l) => l === UNPAINTED)
    ? Array.from(labels) : Array.from(labels, (l) => (l === UNPAINTED ? rest : l)));
  return { labels_a: forServer(sides.a.labels), labels_b: forServer(sides.b.labels), rest };
}

/**
 * Asks for the correspondence of the current labels (and the picked point's
 * image) and shows it, unless a newer request went out meanwhile.
 * Resolves to the answer.
 */
async function requestCorrespond() {
  clearTimeout(corrTimer);
  if (!sides.a.mesh || !hasB()) throw new Error("open a second mesh (B) first: the correspondence maps A onto B");
  const id = ++corrRequestId;
  const sent = { a: Int32Array.from(sides.a.labels), b: Int32Array.from(sides.b.labels) };
  const version = { a: sides.a.labelsVersion, b: sides.b.labelsVersion };
  const pick = state.pick;
  const { labels_a, labels_b, rest } = correspondLabels();
  const body = { labels_a, labels_b };
  if (pick) body.points = [{ face: pick.face, barycentric: pick.barycentric }];
  $("corr-status").textContent = "computing the correspondence...";
  let answer;
  try {
    answer = await api("/api/correspond", { body });
  } catch (e) {
    if (id === corrRequestId) {
      $("corr-status").textContent = "no correspondence: " + e.message.replace(/^\/api\/correspond: /, "");
    }
    throw e;
  }
  if (id === corrRequestId) showCorrespondence(answer, { sent, version, pick, rest });
  return answer;
}

/** Checks and keeps a correspondence answer, colours both meshes with it, fills the panel. */
function showCorrespondence(answer, { sent, version, pick, rest }) {
  const a = sides.a.mesh, b = sides.b.mesh;
  const isArray = (x, n) => Array.isArray(x) && (n === undefined || x.length === n);
  if (!answer || !isArray(answer.vertex_point, 3 * a.V) || !isArray(answer.face_chart_a, a.F) ||
      !isArray(answer.face_chart_b, b.F) || !isArray(answer.chart_pair)) {
    throw new Error("the server's correspondence has not the expected arrays (vertex_point, face_chart_a, face_chart_b, chart_pair)");
  }
  // B's chart -> A's chart paired with it (-1: none)
  let chartsB = 0;
  for (const c of answer.face_chart_b) if (c + 1 > chartsB) chartsB = c + 1;
  const pairOfB = new Int32Array(chartsB).fill(-1);
  answer.chart_pair.forEach((cb, ca) => { if (Number.isInteger(cb) && cb >= 0 && cb < chartsB) pairOfB[cb] = ca; });
  const chartColors = answer.chart_pair.map((_, c) => patchColor(c));
  // "position on B": B's vertices by their place in B's box, A's by their image's
  const gradient = { a: new Float32Array(3 * a.V), b: new Float32Array(3 * b.V) };
  for (let v = 0; v < b.V; v++) {
    gradientColorInto(gradient.b, 3 * v, b.positions[3 * v], b.positions[3 * v + 1], b.positions[3 * v + 2], b.box);
  }
  const points = answer.vertex_point;
  for (let v = 0; v < a.V; v++) {
    const x = points[3 * v], y = points[3 * v + 1], z = points[3 * v + 2];
    if (typeof x === "number" && typeof y === "number" && typeof z === "number") {
      gradientColorInto(gradient.a, 3 * v, x, y, z, b.box);
    } else {
      gradient.a[3 * v] = UNMAPPED_COLOR.r; gradient.a[3 * v + 1] = UNMAPPED_COLOR.g; gradient.a[3 * v + 2] = UNMAPPED_COLOR.b;
    }
  }
  state.corr = { answer, sent, version, rest, pairOfB, chartColors, gradient };
  // the picked point's image, if the pick is still the one asked about
  if (pick && state.pick === pick) {
    const image = Array.isArray(answer.points) ? answer.points[0] : null;
    pick.image = image && Array.isArray(image.point) && image.point.every((x) => typeof x === "number") ? image : null;
    pick.answered = true;
  }
  showMarkers();
  showCorrespondenceReport();
  if (state.view === "correspond") recolorAll();
}

/** A face's colour in the correspondence view (charts), or null for "position on B" (corner colours). */
function correspondFaceColor(side, f) {
  const corr = state.corr;
  if (corr.sent[side.key][f] !== side.labels[f]) return labelColor(side.labels[f]); // painted since: its label
  if (state.corrColors === "gradient") return null;
  const answer = corr.answer;
  if (side === sides.a) {
    const c = answer.face_chart_a[f];
    if (!(c >= 0)) return UNMAPPED_COLOR;
    return answer.chart_pair[c] >= 0 ? corr.chartColors[c] : UNPAIRED_COLOR;
  }
  const c = answer.face_chart_b[f];
  if (!(c >= 0)) return UNMAPPED_COLOR;
  const ca = c < corr.pairOfB.length ? corr.pairOfB[c] : -1;
  return ca >= 0 ? corr.chartColors[ca] : UNPAIRED_COLOR;
}

function setCorrColors(mode) {
  state.corrColors = mode === "gradient" ? "gradient" : "charts";
  for (const input of document.querySelectorAll('input[name="corr-colors"]')) input.checked = input.value === state.corrColors;
  $("corr-legend-charts").hidden = state.corrColors !== "charts";
  $("corr-legend-gradient").hidden = state.corrColors !== "gradient";
  if (state.view === "correspond") recolorAll();
}

/** The report of the last correspondence, its problems and the picked point, in the panel. */
function showCorrespondenceReport() {
  const table = $("corr-report");
  const list = $("corr-problems");
  table.textContent = "";
  list.textContent = "";
  table.classList.remove("stale");
  const corr = state.corr;
  if (!corr) {
    table.hidden = true;
    $("corr-status").textContent = hasB() ? "press Correspond (C)" : "";
    $("corr-problem-count").textContent = "";
    showPickInfo();
    return;
  }
  const { answer, rest } = corr;
  const report = answer.report || {};
  const labelList = (labels) => (Array.isArray(labels) && labels.length
    ? labels.map((l) => (l === rest ? "unpainted" : String(l))).join(", ") : "none");
  const names = (list) => (Array.isArray(list) && list.length ? `${list.length}: ${list.slice(0, 8).join(" ")}${list.length > 8 ? " ..." : ""}` : "none");
  const rows = [
    ["labels on both", labelList(report.matched_labels)],
    ["only on A", labelList(report.labels_only_in_a)],
    ["only on B", labelList(report.labels_only_in_b)],
    ["in other pieces", labelList(report.labels_with_different_pieces)],
    ["paired patches", report.matched_patches ?? "-"],
    ["unpaired on A", names(report.unmatched_patches_a)],
    ["unpaired on B", names(report.unmatched_patches_b)],
    ["vertices mapped", `${report.mapped ?? "-"} of ${report.vertices ?? "-"}` +
      (typeof report.inside === "number" && report.inside !== report.mapped ? ` (${report.inside} inside their chart)` : "")],
  ];
  for (const [name, value] of rows) {
    const tr = table.insertRow();
    tr.insertCell().textContent = name;
    tr.insertCell().textContent = String(value);
  }
  table.hidden = false;
  const ms = Number(answer.milliseconds);
  const allMapped = report.mapped === report.vertices;
  $("corr-status").textContent = `${report.matched_patches} patches of A paired with B's` +
    (answer.cached ? " (kept from the last request: same meshes and labels)"
      : Number.isFinite(ms) ? ` in ${ms.toFixed(0)} ms` : "") + (allMapped ? "; every vertex of A mapped" : "");
  const problems = Array.isArray(answer.problems) ? answer.problems : [];
  $("corr-problem-count").textContent = problems.length ? `(${problems.length})` : "";
  for (const problem of problems) {
    const item = document.createElement("li");
    item.textContent = String(problem);
    list.appendChild(item);
  }
  if (!correspondenceCurrent()) table.classList.add("stale");
  showPickInfo();
}

// ---------------------------------------------------------------------------
// The picked point (pick tool, correspondence view) and its image on B

/** The barycentric coordinates of a point in face f (in the order of the face's vertices in "faces"). */
function barycentricOf(side, face, point) {
  const { positions, faces } = side.mesh;
  const corner = (k) => new THREE.Vector3().fromArray(positions, 3 * faces[3 * face + k]);
  const w = THREE.Triangle.getBarycoord(point, corner(0), corner(1), corner(2), new THREE.Vector3());
  const weights = [w.x, w.y, w.z].map((x) => (Number.isFinite(x) ? Math.max(0, x) : 0));
  const sum = weights[0] + weights[1] + weights[2];
  return sum > 0 ? weights.map((x) => x / sum) : [1 / 3, 1 / 3, 1 / 3];
}

/** The point of face f at barycentric weights w. */
function pointAt(side, face, w) {
  const { positions, faces } = side.mesh;
  const p = new THREE.Vector3();
  for (let k = 0; k < 3; k++) p.addScaledVector(new THREE.Vector3().fromArray(positions, 3 * faces[3 * face + k]), w[k]);
  return p;
}

/** Picks the point of A at face f, weights w; its image comes with the next correspondence. */
function setPick(face, barycentric) {
  state.pick = { face, barycentric, point: pointAt(sides.a, face, barycentric), image: null, answered: false };
  showMarkers();
  showPickInfo();
}

let pickInFlight = null;  // the correspondence request of the picked point on its way
let pickAgain = false;    // the point moved meanwhile: ask again when it is back

/** Asks for the picked point's image; while dragging, one request at a time, the latest point next. */
function sendPick() {
  if (pickInFlight) { pickAgain = true; return pickInFlight; }
  const request = correspondenceCurrent() ? requestPickImage() : requestCorrespond();
  pickInFlight = request.catch(showError).finally(() => {
    pickInFlight = null;
    if (pickAgain) { pickAgain = false; sendPick(); }
  });
  return pickInFlight;
}

/**
 * The picked point's image alone, when the correspondence shown is that of
 * the current labels: the server keeps it and answers only the point.
 */
async function requestPickImage() {
  const pick = state.pick;
  if (!pick) return null;
  const { labels_a, labels_b } = correspondLabels();
  const answer = await api("/api/correspond", {
    body: { labels_a, labels_b, points: [{ face: pick.face, barycentric: pick.barycentric }], only_points: true },
  });
  if (state.pick === pick) {
    const image = Array.isArray(answer.points) ? answer.points[0] : null;
    pick.image = image && Array.isArray(image.point) && image.point.every((x) => typeof x === "number") ? image : null;
    pick.answered = true;
    showMarkers();
    showPickInfo();
  }
  return answer;
}

/** The pick tool at a point of the page on A's canvas: resolves when its image is shown. */
function pickOnA(clientX, clientY) {
  const hit = pickAt(sides.a, clientX, clientY);
  if (!hit) return Promise.resolve(null);
  setPick(hit.face, barycentricOf(sides.a, hit.face, hit.point));
  return sendPick();
}

/** Puts the markers of the picked point on A and of its image on B (correspondence view only). */
function showMarkers() {
  const pick = state.pick;
  const shown = state.view === "correspond" && !!pick;
  const a = sides.a, b = sides.b;
  if (a.marker) {
    a.marker.visible = shown;
    if (shown) {
      a.marker.position.copy(pick.point);
      a.marker.scale.setScalar(a.mesh.diagonal);
    }
    requestRender(a);
  }
  if (b.marker) {
    const image = shown && pick.image;
    b.marker.visible = !!image;
    if (image) {
      b.marker.position.fromArray(image.point);
      b.marker.scale.setScalar(b.mesh.diagonal);
    }
    requestRender(b);
  }
}

/** Says in the panel where the picked point is and where its image went. */
function showPickInfo() {
  const box = $("pick-info");
  const pick = state.pick, corr = state.corr;
  if (!pick) {
    box.textContent = hasB() ? "Pick (K): click or drag on A to see where a point goes on B." : "";
    return;
  }
  const labelName = (l) => (l === UNPAINTED ? "unpainted" : `label ${l}`);
  let text = `A: face ${pick.face}, ${labelName(sides.a.labels[pick.face])}`;
  if (corr && corr.answer.face_chart_a) {
    const c = corr.answer.face_chart_a[pick.face];
    const name = Array.isArray(corr.answer.chart_name_a) ? corr.answer.chart_name_a[c] : null;
    text += c >= 0 ? `, patch ${name || c}` : ", in no chart";
  }
  if (!pick.answered) {
    box.textContent = text + "\n-> B: ...";
    return;
  }
  const image = pick.image;
  if (!image) {
    box.textContent = text + "\n-> B: not mapped (its patch has no partner on B)";
    return;
  }
  const g = image.face;
  const labelB = g >= 0 && g < sides.b.mesh.F ? corr.sent.b[g] : UNPAINTED;
  const nameB = Number.isInteger(image.chart) && Array.isArray(corr.answer.chart_name_b)
    ? corr.answer.chart_name_b[image.chart] : null;
  box.textContent = text + `\n-> B: face ${g}, ${labelName(labelB)}` + (nameB ? `, patch ${nameB}` : "") +
    (image.inside ? "" : " (outside its chart: the nearest point)");
}

// ---------------------------------------------------------------------------
// Files (they act on the active mesh: the last one painted or clicked)

function baseName(side) {
  return (side.mesh ? side.mesh.name : "mesh").replace(/\.[^.]*$/, "");
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

/** The label file the server writes for a side's current labels. */
function fetchLabelsText(side = sides.a) {
  return api(sidePath(side, "/api/labels.txt"), { body: { labels: Array.from(side.labels) }, as: "text" });
}

async function saveLabels(side = state.active) {
  const text = await fetchLabelsText(side);
  download(new Blob([text], { type: "text/plain" }), `${baseName(side)}.labels.txt`);
  const unpainted = countLabel(side, UNPAINTED);
  if (unpainted > 0) {
    showMessage(`${unpainted} unpainted faces are saved as one more region, label ${largestLabel(side) + 1}`);
  }
}

function largestLabel(side) {
  let largest = UNPAINTED;
  for (const l of side.labels) if (l > largest) largest = l;
  return largest;
}

/**
 * The labels a saved label file holds, one per polygon of the mesh file:
 * the server writes unpainted faces as one more region (the largest label
 * + 1), since a label file cannot say "none".
 */
function expectedFileLabels(side = sides.a) {
  const { F, fileFace, facesInFile } = side.mesh;
  const unpainted = largestLabel(side) + 1;
  const result = new Array(facesInFile).fill(0);
  for (let f = 0; f < F; f++) {
    const l = side.labels[f];
    result[fileFace ? fileFace[f] : f] = l === UNPAINTED ? unpainted : l;
  }
  return result;
}

async function savePaintedPly(side = state.active) {
  const blob = await api(sidePath(side, "/api/painted.ply"), { body: { labels: Array.from(side.labels) }, as: "blob" });
  download(blob, `${baseName(side)}.painted.ply`);
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

/**
 * A label file's labels as one label per triangle of the mesh. A file for a
 * mesh of polygons has one label per polygon of the mesh file, given to
 * each of the polygon's triangles (file_face); a file with one label per
 * triangle is taken as it is. Negative labels are unpainted.
 */
function triangleLabels(mesh, labels, fileName = "the label file") {
  const { F, fileFace, facesInFile } = mesh;
  let result = labels;
  if (fileFace && labels.length === facesInFile && facesInFile !== F) {
    result = Array.from(fileFace, (polygon) => labels[polygon]);
  }
  if (result.length !== F) {
    const polygons = facesInFile !== F ? ` (${facesInFile} polygons in its file)` : "";
    throw new Error(`${fileName} has ${labels.length} labels, but the mesh has ${F} faces${polygons}`);
  }
  return result.map((l) => (l < 0 ? UNPAINTED : l));
}

async function loadLabelsFile(side, file) {
  const inFile = parseLabelFile(await file.text());
  const labels = triangleLabels(side.mesh, inFile, file.name);
  replaceAllLabels(side, labels);
  const perPolygon = inFile.length !== labels.length ? `, one per polygon of ${side.mesh.name}` : "";
  showMessage(`loaded ${inFile.length} labels from ${file.name}${perPolygon}${hasB() ? " onto " + side.title : ""}`);
}

async function openMeshFile(side, file) {
  const json = await api(sidePath(side, "/api/mesh", { name: file.name }), { body: file });
  showMesh(side, json);
  setActive(side);
  showMessage(`opened ${file.name}${side === sides.b ? " as mesh B" : ""}`);
  scheduleLayout(side);
}

function isMeshFile(name) {
  const lower = name.toLowerCase();
  return MESH_EXTENSIONS.some((ext) => lower.endsWith(ext));
}

/**
 * "Copy A's labels to B": for a B lying on top of A (a remeshed copy), B's
 * faces take the labels of A's nearest faces (the server's transfer_labels),
 * as one undoable step on B.
 */
async function transferLabelsToB() {
  if (!hasB()) return;
  const { labels_a, rest } = correspondLabels();
  // labels_b left out: the server gives B the labels of A's nearest faces
  // (it answers them only then) when B came without labels of its own
  const answer = await api("/api/correspond", { body: { labels_a, transfer_labels: true } });
  if (!Array.isArray(answer.labels_b) || answer.labels_b.length !== sides.b.mesh.F) {
    throw new Error(`the server sent no labels for B: it copies A's labels only onto a B that came without labels (${sides.b.mesh.labelSource || "B has labels of its own"})`);
  }
  // A's unpainted faces went as label `rest`: unpainted on B too
  replaceAllLabels(sides.b, answer.labels_b.map((l) => (Number.isInteger(l) && l >= 0 && l !== rest ? l : UNPAINTED)));
  setActive(sides.b);
  showMessage("B has A's labels (those of A's nearest faces): Ctrl+Z takes them back");
}

// ---------------------------------------------------------------------------
// Tools, palette and controls

function setTool(tool) {
  if (tool === "pick" && state.view !== "correspond") {
    if (!hasB()) { showMessage("the pick tool shows a point of A on B: open a second mesh (Open mesh B) first"); return; }
    state.toolBeforePick = state.tool;
    state.tool = "pick";
    setView("correspond");
  }
  state.tool = tool;
  for (const button of document.querySelectorAll("#tools button")) {
    button.classList.toggle("active", button.dataset.tool === tool);
  }
  for (const side of SIDES) {
    if (side.brushCursor) side.brushCursor.visible = false;
    requestRender(side);
  }
}

function setLabel(label) {
  state.label = label;
  growPaletteFor([label]);
  if (state.tool === "eraser" || state.tool === "orbit" || state.tool === "pick") setTool("brush");
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

function clearLabels(side = state.active) {
  if (side.mesh) replaceAllLabels(side, new Int32Array(side.mesh.F).fill(UNPAINTED));
}

function wireUi() {
  for (const button of document.querySelectorAll("#tools button")) {
    button.addEventListener("click", () => setTool(button.dataset.tool));
  }
  for (const button of document.querySelectorAll("#views button")) {
    button.addEventListener("click", () => setView(button.dataset.view));
  }
  for (const button of document.querySelectorAll("#target button")) {
    button.addEventListener("click", () => setActive(sides[button.dataset.side]));
  }
  $("radius").addEventListener("input", (e) => setRadius(Number(e.target.value)));
  $("undo").addEventListener("click", () => undo());
  $("redo").addEventListener("click", () => redo());
  $("clear").addEventListener("click", () => clearLabels());
  $("show-sides").addEventListener("change", () => {
    for (const side of SIDES) { side.overlay.visible = overlayShown(); requestRender(side); }
  });
  $("map").addEventListener("click", run(mapAll));
  $("correspond").addEventListener("click", run(() => {
    if (state.view !== "correspond") setView("correspond");
    else return requestCorrespond();
  }));
  $("transfer").addEventListener("click", run(transferLabelsToB));
  for (const input of document.querySelectorAll('input[name="corr-colors"]')) {
    input.addEventListener("change", () => setCorrColors(input.value));
  }
  $("save-labels").addEventListener("click", run(() => saveLabels()));
  $("save-ply").addEventListener("click", run(() => savePaintedPly()));
  $("load-labels-button").addEventListener("click", () => $("load-labels").click());
  $("open-mesh-button").addEventListener("click", () => $("open-mesh").click());
  $("open-mesh-b-button").addEventListener("click", () => $("open-mesh-b").click());
  $("load-labels").addEventListener("change", run(async (e) => {
    const file = e.target.files[0];
    e.target.value = "";
    if (file) await loadLabelsFile(state.active, file);
  }));
  for (const [id, side] of [["open-mesh", sides.a], ["open-mesh-b", sides.b]]) {
    $(id).addEventListener("change", run(async (e) => {
      const file = e.target.files[0];
      e.target.value = "";
      if (file) await openMeshFile(side, file);
    }));
  }

  // drop a mesh or a label file on the view: on B's half, for B
  const view = $("view");
  view.addEventListener("dragover", (e) => { e.preventDefault(); view.classList.add("dragover"); });
  view.addEventListener("dragleave", () => view.classList.remove("dragover"));
  view.addEventListener("drop", run(async (e) => {
    e.preventDefault();
    view.classList.remove("dragover");
    const file = e.dataTransfer.files[0];
    if (!file) return;
    const side = hasB() && sides.b.viewport.contains(e.target) ? sides.b : sides.a;
    if (isMeshFile(file.name)) await openMeshFile(side, file);
    else if (side.mesh) { setActive(side); await loadLabelsFile(side, file); }
  }));

  window.addEventListener("keydown", onKeyDown);
}

function onKeyDown(e) {
  const target = e.target;
  if (target && (target.tagName === "TEXTAREA" || (target.tagName === "INPUT" && target.type !== "range" && target.type !== "checkbox" && target.type !== "radio"))) return;
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
    k: () => setTool("pick"),
    "[": () => setRadius(state.radiusPercent - 1),
    "]": () => setRadius(state.radiusPercent + 1),
    m: run(mapAll),
    l: () => setView("patches"),
    p: () => setView("paint"),
    d: () => setView("distortion"),
    c: () => setView("correspond"),
    g: () => setCorrColors(state.corrColors === "charts" ? "gradient" : "charts"),
  };
  if (actions[key]) {
    e.preventDefault();
    actions[key]();
  } else if (/^[1-9]$/.test(key)) {
    setLabel(Number(key) - 1);
  }
}

// ---------------------------------------------------------------------------
// Mouse: paint (or pick) with the left button, orbit with the right one, on
// whichever mesh's canvas the pointer is

let painting = null;       // the side being painted, while the left button is down
let picking = false;       // the pick tool dragging on A
let pendingPointer = null; // latest pointer position, handled once per frame
let pointerFrame = 0;
let lastPaintPosition = null; // where the stroke painted last, client coordinates

function onPointerDown(side, e) {
  // OrbitControls acts on the mousedown that follows: say now what it should do.
  const orbitWithLeft = state.tool === "orbit" || e.altKey;
  side.controls.mouseButtons.LEFT = orbitWithLeft ? THREE.MOUSE.ROTATE : -1;
  side.controls.mouseButtons.RIGHT = e.shiftKey || e.ctrlKey ? THREE.MOUSE.PAN : THREE.MOUSE.ROTATE;
  if (side.mesh && state.active !== side) setActive(side);
  if (e.button !== 0 || orbitWithLeft || !side.mesh) return;
  if (state.tool === "pick") {
    if (side !== sides.a) {
      showMessage("pick a point on A (the left mesh): its image is shown on B");
      return;
    }
    picking = true;
    side.renderer.domElement.setPointerCapture(e.pointerId);
    pickOnA(e.clientX, e.clientY);
    return;
  }
  const hit = pickAt(side, e.clientX, e.clientY);
  if (state.tool === "fill") {
    if (hit) fillAt(side, hit.face);
    return;
  }
  painting = side;
  side.renderer.domElement.setPointerCapture(e.pointerId);
  beginStroke(side);
  paintAt(side, hit);
  lastPaintPosition = { x: e.clientX, y: e.clientY };
  moveBrushCursor(side, hit);
}

function onPointerMove(side, e) {
  pendingPointer = { side, x: e.clientX, y: e.clientY, buttons: e.buttons };
  if (!pointerFrame) pointerFrame = requestAnimationFrame(handlePointerMove);
}

function handlePointerMove() {
  pointerFrame = 0;
  if (!pendingPointer) return;
  const side = painting || pendingPointer.side;
  if (!side.mesh) return;
  if (picking) {
    if (pendingPointer.side === sides.a) pickOnA(pendingPointer.x, pendingPointer.y);
    return;
  }
  const brushTool = state.tool === "brush" || state.tool === "eraser";
  // no raycast while orbiting: the view is moving anyway
  if (!painting && (!brushTool || pendingPointer.buttons !== 0)) {
    if (side.brushCursor.visible) { side.brushCursor.visible = false; requestRender(side); }
    return;
  }
  const hit = pickAt(side, pendingPointer.x, pendingPointer.y);
  if (painting) {
    paintBetween(side, lastPaintPosition, pendingPointer);
    paintAt(side, hit);
    lastPaintPosition = { x: pendingPointer.x, y: pendingPointer.y };
  }
  moveBrushCursor(side, brushTool ? hit : null);
}

/** Paints along the screen segment between two pointer positions, so a fast drag leaves no gaps. */
function paintBetween(side, from, to) {
  if (!from) return;
  const length = Math.hypot(to.x - from.x, to.y - from.y);
  const steps = Math.min(16, Math.floor(length / 8));
  for (let i = 1; i < steps; i++) {
    const t = i / steps;
    paintAt(side, pickAt(side, from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)));
  }
}

function onPointerUp(side, e) {
  const canvas = side.renderer.domElement;
  if (canvas.hasPointerCapture(e.pointerId)) canvas.releasePointerCapture(e.pointerId);
  if (picking) { picking = false; return; }
  if (!painting) return;
  const painted = painting;
  painting = null;
  lastPaintPosition = null;
  endStroke(painted);
}

/** A translucent ball of the brush radius where the brush would paint. */
function moveBrushCursor(side, hit) {
  const cursor = side.brushCursor;
  cursor.visible = !!hit;
  if (hit) {
    cursor.position.copy(hit.point);
    cursor.scale.setScalar(brushRadius(side));
    cursor.material.color.copy(state.tool === "eraser" ? UNPAINTED_COLOR : labelColor(state.label));
  }
  // the other mesh's cursor goes away
  for (const other of SIDES) {
    if (other !== side && other.brushCursor && other.brushCursor.visible) { other.brushCursor.visible = false; requestRender(other); }
  }
  requestRender(side);
}

// ---------------------------------------------------------------------------
// Rendering: one canvas (renderer, scene, camera, controls) per mesh

function requestRender(side) {
  if (!side || side.renderQueued || !side.renderer) return;
  side.renderQueued = true;
  requestAnimationFrame(() => renderNow(side));
}

function renderNow(side = sides.a) {
  side.renderQueued = false;
  side.renderer.render(side.scene, side.camera);
}

/** Makes a side's viewport (in #view) with its canvas, scene, camera, lights, controls. */
function setupSide(side) {
  const viewport = document.createElement("div");
  viewport.className = "viewport";
  viewport.id = "viewport-" + side.key;
  const caption = document.createElement("div");
  caption.className = "caption";
  viewport.appendChild(caption);
  $("view").appendChild(viewport);
  side.viewport = viewport;

  // preserveDrawingBuffer: the self test reads the pixels back, and headless
  // Chromium's screenshots show a blank canvas without it
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  side.renderer = renderer;
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor("#eef0f4");
  viewport.insertBefore(renderer.domElement, caption);
  const canvas = renderer.domElement;
  // the painting listener goes first: it sets up OrbitControls for this press
  canvas.addEventListener("pointerdown", (e) => onPointerDown(side, e));
  canvas.addEventListener("pointermove", (e) => onPointerMove(side, e));
  canvas.addEventListener("pointerup", (e) => onPointerUp(side, e));
  canvas.addEventListener("pointercancel", (e) => onPointerUp(side, e));
  canvas.addEventListener("pointerleave", () => {
    if (painting !== side && side.brushCursor.visible) { side.brushCursor.visible = false; requestRender(side); }
  });

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
  side.scene = scene;
  side.camera = camera;
  scene.add(camera);
  scene.add(new THREE.HemisphereLight("#ffffff", "#808088", 0.55));
  const headlight = new THREE.DirectionalLight("#ffffff", 0.55);
  headlight.position.set(0.3, 0.6, 1); // with the camera, so the side you look at is lit
  camera.add(headlight);

  const controls = new OrbitControls(camera, canvas);
  side.controls = controls;
  controls.mouseButtons = { LEFT: -1, MIDDLE: THREE.MOUSE.DOLLY, RIGHT: THREE.MOUSE.ROTATE };
  controls.enableKeys = false;
  controls.screenSpacePanning = true;
  controls.addEventListener("change", () => requestRender(side));
  // once the user turned the view, a new size of the canvas no longer frames the mesh again
  controls.addEventListener("start", () => { side.framed = false; });

  const surfaceMaterial = {
    vertexColors: THREE.VertexColors,
    side: THREE.DoubleSide,
    // the surface steps back a little so the side lines on it win the depth test
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  };
  side.colorMaterial = new THREE.MeshLambertMaterial(surfaceMaterial);
  side.isolineMaterial = new THREE.MeshLambertMaterial({ ...surfaceMaterial, map: makeIsolineTexture() });

  side.overlay = new THREE.Group();
  scene.add(side.overlay);
  side.brushCursor = new THREE.Mesh(
    new THREE.SphereBufferGeometry(1, 24, 16),
    new THREE.MeshBasicMaterial({ color: "#ffffff", transparent: true, opacity: 0.3, depthWrite: false }));
  side.brushCursor.visible = false;
  scene.add(side.brushCursor);

  // the picked point (on A) or its image (on B): a magenta ball ringed in
  // black, drawn over the surface so it shows also on the far side
  const marker = new THREE.Group();
  const ring = new THREE.Mesh(new THREE.SphereBufferGeometry(0.016, 20, 14),
    new THREE.MeshBasicMaterial({ color: "#111111", side: THREE.BackSide, depthTest: false }));
  const ball = new THREE.Mesh(new THREE.SphereBufferGeometry(0.0115, 20, 14),
    new THREE.MeshBasicMaterial({ color: MARKER_COLOR, depthTest: false }));
  ring.renderOrder = 10; ball.renderOrder = 11;
  marker.add(ring, ball);
  marker.name = "marker";
  marker.visible = false;
  scene.add(marker);
  side.marker = marker;

  const resize = () => {
    const width = Math.max(1, viewport.clientWidth), height = Math.max(1, viewport.clientHeight);
    renderer.setSize(width, height, false);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    if (side.framed && side.surface) fitCamera(side);
    requestRender(side);
  };
  side.resize = resize;
  new ResizeObserver(resize).observe(viewport);
  resize();
}

/** Looks at a side's whole mesh from the front, a little from above. */
function fitCamera(side) {
  const { camera, controls } = side;
  const sphere = side.surface.geometry.boundingSphere;
  const radius = sphere.radius || 1;
  const fit = radius / Math.sin(THREE.Math.degToRad(camera.fov / 2)) * 1.05;
  // a viewport narrower than high (side by side): back off so the width fits too
  const distance = camera.aspect < 1 ? fit / Math.max(camera.aspect, 0.3) : fit;
  const direction = new THREE.Vector3(0.25, 0.3, 1).normalize();
  camera.position.copy(sphere.center).addScaledVector(direction, distance);
  camera.near = distance / 100;
  camera.far = distance + radius * 10;
  camera.updateProjectionMatrix();
  controls.target.copy(sphere.center);
  controls.update();
  side.framed = true;
  requestRender(side);
}

/** Renders a side now and counts the distinct colours of its canvas. */
function countCanvasColors(side = sides.a) {
  renderNow(side);
  const gl = side.renderer.getContext();
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
  const A = sides.a, B = sides.b;
  const F = A.mesh ? A.mesh.F : 0;
  try {
    if (!A.mesh) throw new Error("no mesh loaded");
    // start from nothing painted, so label 1 counts only the stroke's faces
    for (const side of loadedSides()) {
      if (countLabel(side, UNPAINTED) !== side.mesh.F) side.labels.fill(UNPAINTED);
      side.undoStack = []; side.redoStack = [];
      side.labelsVersion++;
    }
    setActive(A);
    setView("paint");
    setTool("brush");
    setLabel(1);
    setRadius(5);
    renderNow(A);

    // (a) a stroke at the centre of the canvas, through the mouse's picking code
    const [cx, cy] = canvasCentre(A);
    const hit = pickAt(A, cx, cy);
    let painted = 0;
    if (!hit) {
      check("brush stroke", false, "the centre of the canvas is not on the mesh");
    } else {
      beginStroke(A);
      paintAt(A, hit);
      endStroke(A);
      painted = countLabel(A, 1);
      const radius = brushRadius(A);
      const all = surfaceDistances(A, hit.face); // no limit: every face's distance
      const distance = new Float64Array(F).fill(Infinity);
      all.faces.forEach((f, i) => { distance[f] = all.distances[i]; });
      let outside = 0, missed = 0;
      for (let f = 0; f < F; f++) {
        if (A.labels[f] === 1 && !(distance[f] <= radius)) outside++;
        if (A.labels[f] !== 1 && distance[f] <= radius) missed++;
      }
      check("brush stroke", painted > 0 && outside === 0 && missed === 0 && A.labels[hit.face] === 1,
        { picked_face: hit.face, labelled: painted, radius, outside_radius: outside, missed_within_radius: missed,
          picked_face_labelled: A.labels[hit.face] === 1 });
    }

    // (b) one stroke is one undo step
    undo(A);
    const afterUndo = countLabel(A, 1);
    redo(A);
    const afterRedo = countLabel(A, 1);
    check("undo redo", afterUndo === 0 && afterRedo === painted && painted > 0,
      { after_undo: afterUndo, after_redo: afterRedo, stroke: painted });

    // (c) the saved label file reads back as the page's labels (unpainted
    // faces as the one more region the server makes of them), also through
    // Load labels' own reading (one label per polygon of the file)
    const text = await fetchLabelsText(A);
    const saved = parseLabelFile(text);
    const expected = expectedFileLabels(A);
    let differ = saved.length === expected.length ? 0 : -1;
    if (differ === 0) for (let i = 0; i < expected.length; i++) if (saved[i] !== expected[i]) differ++;
    let reread = -1;
    try {
      const back = triangleLabels(A.mesh, saved);
      const unpaintedAs = largestLabel(A) + 1;
      reread = 0;
      for (let f = 0; f < F; f++) if (back[f] !== (A.labels[f] === UNPAINTED ? unpaintedAs : A.labels[f])) reread++;
    } catch (e) { reread = String(e.message); }
    check("labels file", differ === 0 && reread === 0 && countLabel(A, 1) > 0,
      { lines: saved.length, expected: expected.length, differing: differ, unpainted_saved_as: largestLabel(A) + 1,
        ones_in_file: saved.filter((l) => l === 1).length, reread_differing: reread });

    // (d) the layout of these labels, drawn
    const layout = await requestLayout(A);
    check("layout", layout && layout.patches > 0 && A.sidePolylineCount > 0 && A.layout === layout,
      { patches: layout && layout.patches, side_polylines: A.sidePolylineCount, corners: A.cornerCount,
        problems: layout && layout.problems ? layout.problems.length : null });

    // (e) the map, applied to the geometry's uv
    const param = await requestParam(A);
    const cornerUv = param && param.corner_uv;
    const uv = A.surface.geometry.getAttribute("uv").array;
    let mismatched = 0, mapped = 0;
    if (Array.isArray(cornerUv) && cornerUv.length === 6 * F) {
      for (let f = 0; f < F; f++) {
        if (A.param.unmapped[f]) continue;
        mapped++;
        for (let i = 6 * f; i < 6 * f + 6; i++) if (Math.abs(uv[i] - cornerUv[i]) > 1e-6) mismatched++;
      }
    }
    check("map", Array.isArray(cornerUv) && cornerUv.length === 6 * F && mismatched === 0 && mapped > 0 &&
      state.view === "isolines",
      { corner_uv: cornerUv ? cornerUv.length : null, expected: 6 * F, mapped_faces: mapped, mismatched,
        view: state.view, summary: param && param.summary });

    // (f) the canvas shows something
    const pixels = countCanvasColors(A);
    check("canvas not blank", pixels.colors > 10, pixels);

    if (B.mesh) await selfTestB(check, hit);
  } catch (e) {
    check("no exception", false, String((e && e.stack) || e));
  }
  const result = { ok: checks.length > 0 && checks.every((c) => c.ok), faces: F, faces_b: B.mesh ? B.mesh.F : null, checks };
  const out = $("test-result");
  out.textContent = JSON.stringify(result, null, 1);
  out.hidden = false;
  document.title = "done";
  return result;
}

/**
 * The self test's part for mesh B. The test server runs the same mesh as A
 * and B, so B painted the way A was has A's labels face for face, its
 * layout is A's, and the correspondence maps every vertex onto itself.
 */
async function selfTestB(check, hitA) {
  const A = sides.a, B = sides.b;
  const same = A.mesh.F === B.mesh.F && A.mesh.V === B.mesh.V;
  if (!same) {
    check("B is A's copy", false, { faces_a: A.mesh.F, faces_b: B.mesh.F, note: "the test wants the same mesh as A and B" });
    return;
  }
  setView("paint");
  if (!hitA) throw new Error("no stroke on A to repeat on B");

  // (g) B painted as A: the same stroke (label 1 at A's picked face), then
  // the rest of both filled with label 0 by the fill tool
  const undoA = A.undoStack.length;
  const [bx, by] = canvasCentre(B);
  const hitB = pickAt(B, bx, by); // B's own canvas and camera: on the mesh
  setActive(B);
  setTool("brush");
  setLabel(1);
  beginStroke(B);
  paintAt(B, { face: hitA.face, point: null });
  endStroke(B);
  const strokeB = countLabel(B, 1);
  const undoneB = undo(B) && countLabel(B, 1) === 0 && countLabel(A, 1) === strokeB;
  redo(B);
  let rest = -1;
  for (let f = 0; f < A.mesh.F && rest < 0; f++) if (A.labels[f] === UNPAINTED) rest = f;
  setLabel(0);
  setTool("fill");
  const filledA = rest >= 0 ? fillAt(A, rest, 0) : 0;
  const filledB = rest >= 0 ? fillAt(B, rest, 0) : 0;
  let differ = 0;
  for (let f = 0; f < A.mesh.F; f++) if (A.labels[f] !== B.labels[f]) differ++;
  check("B painted", strokeB > 0 && undoneB && differ === 0 && filledB > 0 && filledA === filledB &&
    B.undoStack.length === 2 && A.undoStack.length === undoA + 1 && hitB !== null,
    { stroke: strokeB, filled: filledB, differing_from_a: differ, undo_b_alone: undoneB,
      undo_steps_a: A.undoStack.length, undo_steps_b: B.undoStack.length, centre_of_b_on_mesh: hitB !== null });

  // (h) B's layout: A's patches, drawn on B
  const [layoutA, layoutB] = await Promise.all([requestLayout(A), requestLayout(B)]);
  let patchDiffer = -1;
  if (layoutA && layoutB) {
    patchDiffer = 0;
    for (let f = 0; f < A.mesh.F; f++) if (layoutA.face_patch[f] !== layoutB.face_patch[f]) patchDiffer++;
  }
  check("B layout", layoutB && layoutB.patches > 0 && B.layout === layoutB && B.sidePolylineCount > 0 &&
    B.cornerCount > 0 && layoutB.patches === layoutA.patches && patchDiffer === 0,
    { patches: layoutB && layoutB.patches, patches_a: layoutA && layoutA.patches, faces_in_other_patch: patchDiffer,
      side_polylines: B.sidePolylineCount, corners: B.cornerCount });

  // (i) the correspondence view: every vertex onto itself, paired charts alike
  setView("correspond");
  const answer = await requestCorrespond();
  const V = A.mesh.V, tolerance = 1e-6 * A.mesh.diagonal;
  let unmapped = 0, far = 0, worst = 0;
  for (let v = 0; v < V; v++) {
    const p = answer.vertex_point.slice(3 * v, 3 * v + 3);
    if (answer.vertex_face[v] < 0 || !p.every((x) => typeof x === "number")) { unmapped++; continue; }
    const d = Math.hypot(p[0] - A.mesh.positions[3 * v], p[1] - A.mesh.positions[3 * v + 1], p[2] - A.mesh.positions[3 * v + 2]);
    worst = Math.max(worst, d);
    if (!(d <= tolerance)) far++;
  }
  // colours as drawn: every face of B in chart chart_pair[c] has the colour of A's chart c
  const colorsA = A.surface.geometry.getAttribute("color").array;
  const colorsB = B.surface.geometry.getAttribute("color").array;
  const colorOfChartA = new Map();
  for (let f = 0; f < A.mesh.F; f++) {
    const c = answer.face_chart_a[f];
    if (c >= 0 && !colorOfChartA.has(c)) colorOfChartA.set(c, [colorsA[9 * f], colorsA[9 * f + 1], colorsA[9 * f + 2]]);
  }
  let pairedFaces = 0, wrongColor = 0, pairs = 0;
  answer.chart_pair.forEach((cb) => { if (cb >= 0) pairs++; });
  for (let g = 0; g < B.mesh.F; g++) {
    const cb = answer.face_chart_b[g];
    const ca = cb >= 0 && cb < state.corr.pairOfB.length ? state.corr.pairOfB[cb] : -1;
    if (ca < 0) continue;
    pairedFaces++;
    const want = colorOfChartA.get(ca);
    if (!want || Math.abs(want[0] - colorsB[9 * g]) > 1e-6 || Math.abs(want[1] - colorsB[9 * g + 1]) > 1e-6 ||
        Math.abs(want[2] - colorsB[9 * g + 2]) > 1e-6) wrongColor++;
  }
  check("correspondence", answer.report && answer.report.mapped === V && unmapped === 0 && far === 0 &&
    pairs > 0 && pairedFaces === B.mesh.F && wrongColor === 0 && state.view === "correspond",
    { vertices: V, mapped: answer.report && answer.report.mapped, unmapped, farther_than_1e_6_diagonal: far,
      worst_distance: worst, chart_pairs: pairs, faces_of_b_in_paired_charts: pairedFaces,
      faces_of_b_coloured_unlike_their_a_chart: wrongColor, problems: answer.problems, ms: answer.milliseconds });

  // (j) "position on B": on the same mesh A's corners have B's colours
  setCorrColors("gradient");
  let gradientDiffer = 0;
  for (let i = 0; i < colorsA.length; i++) if (Math.abs(colorsA[i] - colorsB[i]) > 1e-4) gradientDiffer++;
  check("position colours", gradientDiffer === 0, { corner_values_differing: gradientDiffer });
  setCorrColors("charts");

  // (k) the pick tool at the centre of A's canvas: B's marker on the point picked
  setActive(A);
  const [ax, ay] = canvasCentre(A);
  await pickOnA(ax, ay);
  const pick = state.pick;
  const markerA = A.marker.position, markerB = B.marker.position;
  const gap = pick && pick.image ? markerA.distanceTo(markerB) : null;
  check("picked point", pick && pick.image && A.marker.visible && B.marker.visible && gap <= tolerance &&
    state.tool === "pick" && /-> B: face/.test($("pick-info").textContent),
    { face: pick && pick.face, barycentric: pick && pick.barycentric, image: pick && pick.image,
      marker_a: markerA.toArray(), marker_b: markerB.toArray(), distance: gap, info: $("pick-info").textContent });

  // (l) B's canvas shows something
  const pixels = countCanvasColors(B);
  check("canvas B not blank", pixels.colors > 10, pixels);
}

// ---------------------------------------------------------------------------
// Start

async function loadMeshesFromServer() {
  showMesh(sides.a, await api("/api/mesh"));
  try {
    showMesh(sides.b, await api("/api/mesh?mesh=b"));
  } catch (e) {
    if (e.status !== 404) showError(e); // 404: no second mesh, the one-mesh painter
  }
  setActive(sides.a);
}

async function main() {
  window.addEventListener("error", (e) => showError(e.error || e.message));
  window.addEventListener("unhandledrejection", (e) => showError(e.reason));
  for (const side of SIDES) setupSide(side);
  updateSidesUi();
  wireUi();
  setTool("brush");
  setRadius(state.radiusPercent);
  renderPalette();
  updateUndoButtons();
  setView("paint");
  setCorrColors("charts");
  showCorrespondenceReport();
  try {
    await loadMeshesFromServer();
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
  } else if (sides.a.mesh) {
    // ?view=patches, isolines, distortion or correspond opens the page on
    // that view (a link, a screenshot); with correspond, ?pick=FACE picks
    // the middle of A's face FACE (or ?pick=FACE,w0,w1,w2 a point in it).
    const view = PARAMS.get("view");
    if (view === "isolines" || view === "distortion") {
      await mapAll().catch(showError);
      setView(view);
    } else {
      for (const side of loadedSides()) await requestLayout(side).catch(showError);
      if (view === "patches") setView("patches");
      if (view === "correspond" && hasB()) {
        const pick = (PARAMS.get("pick") || "").split(",").map(Number);
        if (Number.isInteger(pick[0]) && pick[0] >= 0 && pick[0] < sides.a.mesh.F) {
          const w = pick.length === 4 && pick.slice(1).every((x) => x >= 0) ? pick.slice(1) : [1, 1, 1];
          const sum = w[0] + w[1] + w[2] || 1;
          setPick(pick[0], w.map((x) => x / sum));
        }
        state.view = "paint";
        setView("correspond");
        $("corr-section").scrollIntoView({ block: "start" });
        await requestCorrespond().catch(showError);
        if (state.corrColors !== (PARAMS.get("colors") || "charts")) setCorrColors(PARAMS.get("colors"));
      }
    }
  }
}

// For tests and the console: the painting and picking functions (most take a side first: sides.a or sides.b).
window.diffuvPainter = {
  state, sides, pickAt, paintAt, beginStroke, endStroke, fillAt, undo, redo,
  setTool, setLabel, setRadius, setView, setActive, brushRadius, surfaceDistances, countLabel,
  requestLayout, requestParam, mapAll, requestCorrespond, pickOnA, setPick, setCorrColors,
  fetchLabelsText, parseLabelFile, triangleLabels, replaceAllLabels,
  renderNow, countCanvasColors, runSelfTest,
  /** A whole stroke through the given client points, as the mouse would paint it. */
  strokeThrough(side, points, label = toolLabel()) {
    beginStroke(side);
    for (const [x, y] of points) paintAt(side, pickAt(side, x, y), label);
    endStroke(side);
    return countLabel(side, label);
  },
};

main();
