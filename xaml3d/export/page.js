// The xaml3d export page: loads the embedded three.js modules and glTF, shows the scene from the
// XAML camera and keeps the camera-pipeline panel (docs/camera-math.md) up to date.
const $ = (id) => document.getElementById(id);

async function unpack(id) {
  const bytes = Uint8Array.from(atob($(id).textContent.trim()), (c) => c.charCodeAt(0));
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
  return await new Response(stream).text();
}

async function loadModules() {
  const url = {};
  const link = (src, map) => {
    for (const [spec, target] of Object.entries(map)) {
      src = src.split(`from '${spec}'`).join(`from '${target}'`);
    }
    return URL.createObjectURL(new Blob([src], { type: "text/javascript" }));
  };
  url.core = link(await unpack("x3d-core"), {});
  url.three = link(await unpack("x3d-three"), { "./three.core.js": url.core });
  url.bgu = link(await unpack("x3d-bgu"), { three: url.three });
  url.sku = link(await unpack("x3d-sku"), { three: url.three });
  url.gltf = link(await unpack("x3d-gltf"), {
    three: url.three,
    "../utils/BufferGeometryUtils.js": url.bgu,
    "../utils/SkeletonUtils.js": url.sku,
  });
  url.orbit = link(await unpack("x3d-orbit"), { three: url.three });
  return {
    THREE: await import(url.three),
    GLTFLoader: (await import(url.gltf)).GLTFLoader,
    OrbitControls: (await import(url.orbit)).OrbitControls,
  };
}

// ------------------------------------------------------------------ camera pipeline (column form)
const sub = (a, b) => a.map((x, i) => x - b[i]);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const scale = (a, s) => a.map((x) => x * s);
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const eye = (n) => Array.from({ length: n }, (_, i) => Array.from({ length: n }, (_, j) => +(i === j)));
function mul(a, b) {
  return a.map((row) => b[0].map((_, j) => row.reduce((s, x, k) => s + x * b[k][j], 0)));
}
function apply(m, p) {
  return m.map((row) => row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3]);
}
function invert4(m) {
  // Gauss-Jordan with partial pivoting
  const a = m.map((row, i) => [...row, ...eye(4)[i]]);
  for (let c = 0; c < 4; c++) {
    let p = c;
    for (let r = c + 1; r < 4; r++) if (Math.abs(a[r][c]) > Math.abs(a[p][c])) p = r;
    [a[c], a[p]] = [a[p], a[c]];
    const d = a[c][c];
    for (let j = 0; j < 8; j++) a[c][j] /= d;
    for (let r = 0; r < 4; r++) {
      if (r === c) continue;
      const f = a[r][c];
      for (let j = 0; j < 8; j++) a[r][j] -= f * a[c][j];
    }
  }
  return a.map((row) => row.slice(4));
}

function frame(look, up) {
  const w = scale(look, -1 / norm(look));
  const upPerp = sub(up, scale(w, dot(up, w)));
  const v = scale(upPerp, 1 / norm(upPerp));
  return [cross(v, w), v, w];
}

function viewFromFrame(P, u, v, w) {
  const m = eye(4);
  [u, v, w].forEach((axis, i) => {
    m[i][0] = axis[0];
    m[i][1] = axis[1];
    m[i][2] = axis[2];
    m[i][3] = -dot(axis, P);
  });
  return m;
}

function effectiveFar(view, near, far, perspective, bounds) {
  if (far !== null) return far;
  if (!bounds) return perspective ? near * 1e5 : near + 1e5;
  const [lo, hi] = bounds;
  let depth = -Infinity;
  for (const x of [lo[0], hi[0]]) for (const y of [lo[1], hi[1]]) for (const z of [lo[2], hi[2]]) {
    depth = Math.max(depth, -apply(view, [x, y, z])[2]);
  }
  const result = depth + 1e-3 * Math.max(Math.abs(depth), Math.abs(near));
  return perspective ? Math.max(result, 2 * near) : Math.max(result, near + Math.max(Math.abs(near), 1));
}

function mwind(W, H) {
  return [[W / 2, 0, W / 2], [0, -H / 2, H / 2], [0, 0, 1]];
}

function mwind4(W, H) {
  return [[W / 2, 0, 0, W / 2], [0, -H / 2, 0, H / 2], [0, 0, 1, 0], [0, 0, 0, 1]];
}

// The pipeline of camera-math.md for a camera (position, look, up in its own space; T its
// Camera.Transform), as `xaml3d camera --json` gives it.
function pipeline(c, W, H, bounds) {
  const aspect = W / H;
  const tInv = invert4(c.transform);
  const out = { kind: c.kind, transform: c.transform, m_wind: mwind(W, H) };
  if (c.kind === "matrix") {
    const viewRow = c.view, projRow = c.projection;
    const T = (m) => m[0].map((_, j) => m.map((row) => row[j]));
    const view = mul(T(viewRow), tInv);
    const clip = mul(mul([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]], T(projRow)), view);
    Object.assign(out, { view_matrix: view, clip_matrix: clip, world_to_pixel: mul(mwind4(W, H), clip) });
    return out;
  }
  const P = c.position;
  const [u, v, w] = frame(c.look, c.up);
  const view = mul(viewFromFrame(P, u, v, w), tInv);
  const near = c.near;
  const perspective = c.kind === "perspective";
  const far = effectiveFar(view, near, c.far, perspective, bounds);
  Object.assign(out, { u, v, w, near, far, view_matrix: view });
  const local = viewFromFrame(P, u, v, w);
  if (perspective) {
    const t = Math.tan((c.fov * Math.PI) / 360);
    const s = [1 / (far * t), aspect / (far * t), 1 / far];
    const mPer = local.map((row, i) => (i < 3 ? row.map((x) => x * s[i]) : row));
    const cc = -near / far, k = 1 + cc;
    const mPp = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1 / k, -cc / k], [0, 0, -1, 0]];
    const clip = mul(mul(mPp, mPer), tInv);
    Object.assign(out, { fov_h: c.fov, fov_v: (360 / Math.PI) * Math.atan(t / aspect), c: cc,
                         m_per: mPer, m_pp: mPp, clip_matrix: clip,
                         world_to_pixel: mul(mwind4(W, H), clip) });
    return out;
  }
  // orthographic: P - n w -> origin, (W/2) u -> x, (H/2) v -> y, (n - f) w -> -z
  const half = [c.width / 2, c.width / aspect / 2, far - near];
  const origin = sub(P, scale(w, near));
  const mOrtho = eye(4);
  [u, v, w].forEach((axis, i) => {
    for (let j = 0; j < 3; j++) mOrtho[i][j] = axis[j] / half[i];
    mOrtho[i][3] = -dot(axis, origin) / half[i];
  });
  const clip = mul(mOrtho, tInv);
  Object.assign(out, { m_ortho: mOrtho, clip_matrix: clip, world_to_pixel: mul(mwind4(W, H), clip) });
  return out;
}

// A number as `xaml3d camera` prints it: 6 significant digits, no trailing zeros (Python's %.6g).
function num(x) {
  if (!Number.isFinite(x)) return Number.isNaN(x) ? "NaN" : x > 0 ? "Infinity" : "-Infinity";
  if (x === 0) return "0";
  const e = Math.floor(Math.log10(Math.abs(Number(x.toPrecision(6)))));
  const s = e < -4 || e >= 6 ? x.toExponential(5) : x.toPrecision(6);
  // trailing zeros of the fraction only (100000 stays 100000), and a two-digit exponent
  return s.replace(/(\.\d*?)0+(?=e|$)/, "$1").replace(/\.(?=e|$)/, "")
    .replace(/e([+-])(\d)$/, (_, sign, d) => `e${sign}0${d}`);
}

function show(m) {
  const fmt = (x) => (Math.abs(x) < 1e-12 ? "0" : num(x));
  if (typeof m[0] === "number") return "  (" + m.map(fmt).join(", ") + ")";
  const cells = m.map((row) => row.map(fmt));
  const width = Math.max(...cells.flat().map((s) => s.length));
  return cells.map((row) => "  | " + row.map((s) => s.padStart(width)).join("  ") + " |").join("\n");
}

const LABELS = [
  ["u", "u (camera right)"], ["v", "v (camera up)"], ["w", "w (camera back: -look)"],
  ["m_per", "Mper: world -> standard perspective view volume"],
  ["m_pp", "Mpp: perspective -> parallel view volume (c = -near/far)"],
  ["m_ortho", "Morth: world -> standard parallel view volume"],
  ["m_wind", "Mwind: [-1,1]^2 -> pixels"],
  ["world_to_pixel", "product, world -> pixel: "],  // + the factors this camera multiplies
];

// The factors of the world -> pixel product: conf.factors (xaml3d's world_to_pixel_factors) for
// the pipeline's camera kind, inverse(Camera.Transform) last when the camera has a transform.
function productLabel(p) {
  const t = p.transform;
  const moved = t && t.some((row, i) => row.some((x, j) => x !== (i === j ? 1 : 0)));
  return conf.factors[p.kind] + (moved ? " inverse(Camera.Transform)" : "") +
         (p.kind === "orthographic" ? " (w = 1: nothing to divide)" : " (divide by w)");
}

function panelText(p, moved) {
  const head = [`${p.kind} camera, ${num(conf.width)} x ${num(conf.height)} px` +
                (moved ? " (moved: Camera.Transform folded into the frame)" : " (as in the XAML)")];
  if (p.near !== undefined) head.push(`near ${num(p.near)}, far ${num(p.far)}` + (p.c !== undefined ? `, c = ${num(p.c)}` : ""));
  const parts = LABELS.filter(([k]) => p[k] !== undefined).map(([k, label]) =>
    `${k === "world_to_pixel" ? label + productLabel(p) : label}\n${show(p[k])}`);
  return head.join("\n") + "\n\n" + parts.join("\n\n");
}

// ------------------------------------------------------------------ the page
const conf = JSON.parse($("x3d-config").textContent);
const W = Math.round(conf.width), H = Math.round(conf.height);
window.xaml3d = { ready: false };

async function main() {
  const { THREE, GLTFLoader, OrbitControls } = await loadModules();
  const renderer = new THREE.WebGLRenderer({ antialias: true, alpha: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(W, H);
  renderer.setClearColor(0x000000, 0);
  $("view").appendChild(renderer.domElement);
  const glb = Uint8Array.from(atob($("x3d-glb").textContent.trim()), (c) => c.charCodeAt(0));
  const gltf = await new GLTFLoader().parseAsync(glb.buffer, "");
  const scene = gltf.scene;
  const ambient = gltf.scene.userData?.ambientLight ?? gltf.parser.json.scenes[0].extras?.ambientLight;
  if (ambient) scene.add(new THREE.AmbientLight(new THREE.Color().setRGB(...ambient.color, THREE.SRGBColorSpace), Math.PI));

  const c = conf.camera;
  let camera;
  if (gltf.cameras.length) {
    camera = gltf.cameras[0];
  } else {
    camera = new THREE.PerspectiveCamera(45, W / H, 0.125, 1e5);
    camera.position.set(0, 0, 5);
  }
  camera.updateMatrixWorld(true);
  const world = camera.matrixWorld.clone();
  // the camera leaves the glTF tree (its node's world matrix kept) so orbiting moves it alone
  world.decompose(camera.position, camera.quaternion, camera.scale);
  camera.removeFromParent();
  scene.add(camera);
  const base = c ? pipeline(c, conf.width, conf.height, conf.bounds) : null;
  if (camera.isPerspectiveCamera) {
    camera.aspect = conf.width / conf.height;
    if (base && base.far) camera.far = base.far * 1.0001;
    camera.updateProjectionMatrix();
  } else if (camera.isOrthographicCamera && base && base.far) {
    camera.far = base.far * 1.0001;
    camera.updateProjectionMatrix();
  }
  if (c && c.kind === "matrix") {
    const p = c.projection; // WPF row form, Direct3D clip -> three's column form, OpenGL clip
    const gl = new THREE.Matrix4().set(
      p[0][0], p[1][0], p[2][0], p[3][0],
      p[0][1], p[1][1], p[2][1], p[3][1],
      2 * p[0][2] - p[0][3], 2 * p[1][2] - p[1][3], 2 * p[2][2] - p[2][3], 2 * p[3][2] - p[3][3],
      p[0][3], p[1][3], p[2][3], p[3][3]);
    camera.projectionMatrix.copy(gl);
    camera.projectionMatrixInverse.copy(gl).invert();
  }
  const look = new THREE.Vector3(0, 0, -1).applyQuaternion(camera.quaternion);
  camera.up.set(0, 1, 0).applyQuaternion(camera.quaternion);
  let distance = 1;
  if (conf.bounds) {
    const centre = new THREE.Vector3(...conf.bounds[0]).add(new THREE.Vector3(...conf.bounds[1])).multiplyScalar(0.5);
    distance = Math.max(centre.clone().sub(camera.position).dot(look), 1e-3);
  }
  const home = { position: camera.position.clone(), quaternion: camera.quaternion.clone(),
                 up: camera.up.clone(), target: camera.position.clone().add(look.multiplyScalar(distance)) };
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(home.target);
  controls.update();
  camera.quaternion.copy(home.quaternion); // exactly the XAML frame, not OrbitControls' rounding
  let moved = false;

  const mixer = new THREE.AnimationMixer(scene);
  const clip = gltf.animations[0];
  let action = null, playing = false, length = 0;
  if (clip) {
    action = mixer.clipAction(clip);
    action.play();
    playing = true;
    length = clip.duration;
    $("time").max = String(length);
  } else {
    $("play").disabled = true;
    $("time").disabled = true;
  }
  const clock = new THREE.Clock();
  let t = 0;

  function current() {
    if (!moved && base) return base;
    const q = camera.quaternion;
    const here = {
      kind: camera.isPerspectiveCamera ? "perspective" : c && c.kind === "matrix" ? "perspective" : "orthographic",
      transform: eye(4),
      position: camera.position.toArray(),
      look: new THREE.Vector3(0, 0, -1).applyQuaternion(q).toArray(),
      up: new THREE.Vector3(0, 1, 0).applyQuaternion(q).toArray(),
      near: c && c.near !== undefined ? c.near : camera.near,
      far: c ? c.far ?? null : camera.far,
      fov: c && c.fov !== undefined ? c.fov : 2 * Math.atan(Math.tan((camera.fov * Math.PI) / 360) * camera.aspect) * 180 / Math.PI,
      width: c && c.width !== undefined ? c.width : 2,
    };
    return pipeline(here, conf.width, conf.height, conf.bounds);
  }
  function panel() {
    const p = current();
    window.xaml3d.pipeline = p;
    $("panel").textContent = panelText(p, moved);
  }
  controls.addEventListener("change", () => { moved = true; panel(); });
  $("reset").onclick = () => {
    camera.position.copy(home.position);
    camera.up.copy(home.up);
    controls.target.copy(home.target);
    controls.update();
    camera.quaternion.copy(home.quaternion);
    moved = false;
    panel();
  };
  $("play").onclick = () => { playing = !playing; $("play").textContent = playing ? "Pause" : "Play"; };
  $("time").oninput = () => { t = parseFloat($("time").value); playing = false; $("play").textContent = "Play"; };
  function setTime(seconds) { t = seconds; if (action) mixer.setTime(t); }
  function frame() {
    const dt = clock.getDelta();
    if (action) {
      if (playing) t = length > 0 ? (t + dt) % length : 0;
      mixer.setTime(t);
      $("time").value = String(t);
      $("clock").textContent = `${t.toFixed(2)} / ${length.toFixed(2)} s`;
    }
    renderer.render(scene, camera);
  }
  renderer.setAnimationLoop(frame);
  panel();
  Object.assign(window.xaml3d, {
    ready: true,
    pause() { playing = false; $("play").textContent = "Play"; },
    setTime(s) { setTime(s); renderer.render(scene, camera); },
    snapshot() { renderer.render(scene, camera); return renderer.domElement.toDataURL("image/png"); },
  });
}

main().catch((e) => { $("panel").textContent = "error: " + e; window.xaml3d.error = String(e); });
