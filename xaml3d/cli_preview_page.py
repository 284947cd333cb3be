"""``xaml3d preview``'s page: the picture, the findings with their source lines, the HTML
export's interactive view (in an iframe) and the camera's matrices.

The page follows the server's event stream (``/events``: each rebuild's data as JSON, see
``cli_preview_state``) and updates in place: the picture and the view are reloaded only when
a new good build made them, so while the markup is broken they stay the last good ones, with
the new findings beside them. ``window.preview`` holds the data shown (``state``) and how many
updates arrived (``updates``), for scripts and tests.
"""

PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>xaml3d preview</title>
<style>
body { margin: 0; font: 13px system-ui, sans-serif; background: #f4f4f4; color: #222; }
header { padding: 8px 12px; background: #fff; border-bottom: 1px solid #ccc;
         display: flex; gap: 12px; align-items: baseline; flex-wrap: wrap; }
header b { font-size: 15px; }
#status { padding: 2px 8px; border-radius: 3px; }
#status.ok { background: #d8f0d8; color: #1a5a1a; }
#status.broken { background: #f8d8d0; color: #8a1a0a; font-weight: bold; }
#status.waiting { background: #eee; }
main { display: flex; flex-wrap: wrap; gap: 12px; padding: 12px; align-items: flex-start; }
section { background: #fff; border: 1px solid #ccc; padding: 8px 10px; }
h2 { font-size: 13px; margin: 0 0 6px; color: #555; }
#picture-box img { display: block;
  background: repeating-conic-gradient(#ddd 0% 25%, #fff 0% 50%) 0 0 / 16px 16px; }
#picture-box.stale img { opacity: 0.55; }
#picture-note { color: #8a1a0a; margin-top: 4px; }
#findings { overflow-wrap: anywhere; }
#findings ol { margin: 0; padding: 0; list-style: none; }
#findings li { padding: 4px 0; border-top: 1px solid #eee; }
#findings li:first-child { border-top: none; }
.sev { display: inline-block; min-width: 56px; font-weight: bold; }
.error .sev { color: #b01a0a; } .warning .sev { color: #a06000; } .info .sev { color: #567; }
.where, .code { font-family: ui-monospace, monospace; }
pre.src { margin: 2px 0 0 60px; font: 12px ui-monospace, monospace; color: #444;
          white-space: pre-wrap; background: #f6f6f6; padding: 1px 4px; }
#view-box iframe { border: none; display: block; }
.column { display: flex; flex-direction: column; gap: 12px; flex: 1 1 420px; min-width: 0; }
#camera { font: 12px ui-monospace, monospace; white-space: pre; max-height: 360px;
          overflow: auto; }
</style>
</head>
<body>
<header><b id="file"></b><span id="status" class="waiting">connecting...</span>
<span id="when"></span></header>
<main>
<section id="picture-box"><h2>xaml3d render <span id="picture-size"></span></h2>
<img id="picture" alt="the scene as xaml3d renders it"><div id="picture-note"></div></section>
<div class="column">
<section id="findings"><h2>findings (xaml3d validate)</h2><ol id="list"></ol></section>
<section><h2>camera (xaml3d camera)</h2><div id="camera"></div></section>
</div>
<section id="view-box"><h2>interactive view (the HTML export: drag to orbit)</h2>
<iframe id="view" title="interactive view"></iframe></section>
</main>
<script>
"use strict";
const $ = (id) => document.getElementById(id);
window.preview = { state: null, updates: 0 };

const fmt = (x) => (typeof x === "number" ? String(Number(x.toPrecision(6))) : String(x));
function matrix(m) {
  if (!Array.isArray(m)) return fmt(m);
  if (!Array.isArray(m[0])) return "(" + m.map(fmt).join(", ") + ")";
  const cells = m.map((row) => row.map(fmt));
  const width = Math.max(...cells.flat().map((c) => c.length));
  return cells.map((row) => "  [" + row.map((c) => c.padStart(width)).join(" ") + "]").join("\\n");
}
const MATRICES = [
  ["u", "u"], ["v", "v"], ["w", "w"],
  ["m_per", "Mper (column vectors): world -> perspective view volume"],
  ["m_pp", "Mpp: perspective -> parallel view volume"],
  ["m_ortho", "Morth: world -> parallel view volume"],
  ["m_wind", "Mwind: [-1,1]^2 -> pixels"],
  ["view_matrix", "view (column vectors): world -> camera space"],
  ["world_to_pixel", "world -> pixel"],
  ["wpf_view", "WPF view matrix (ROW vectors)"],
  ["wpf_projection", "WPF projection matrix (ROW vectors)"],
];
function cameraText(report) {
  if (!report) return "(no camera report: the scene was not read)";
  const lines = [];
  const vp = report.viewport;
  const cam = report.camera;
  const label = `viewport ${vp.index}` + (vp.name ? ` (${vp.name})` : "");
  lines.push(`${label}, ${vp.width} x ${vp.height} px`);
  if (!cam) lines.push("Camera is {x:Null}: WPF draws nothing");
  else {
    const note = cam.is_default ? " (WPF's default camera)" : cam.line ? ` (line ${cam.line})` : "";
    lines.push(cam.kind + note);
    for (const [name, p] of Object.entries(cam.properties)) {
      const rows = Array.isArray(p.value) && Array.isArray(p.value[0]);
      const identity = rows && p.value.every((r, i) => r.every((x, j) => x === +(i === j)));
      const v = identity ? " identity" : (rows ? "\\n" : " ") + matrix(p.value);
      lines.push(`  ${name} =${v}${p.default ? " (default)" : ""}`);
    }
  }
  if (report.error) lines.push("", report.error.code + " " + report.error.message);
  const pipe = report.pipeline;
  if (pipe) {
    for (const [key, label] of MATRICES) {
      if (pipe[key] === undefined || pipe[key] === null) continue;
      const text = key === "world_to_pixel" ? `${label}: ${pipe.world_to_pixel_factors}` : label;
      const m = matrix(pipe[key]);
      lines.push("", m.includes("\\n") ? text + "\\n" + m : `${text} = ${m}`);
    }
  }
  return lines.join("\\n");
}

function finding(f) {
  const li = document.createElement("li");
  li.className = f.severity;
  li.dataset.code = f.code;
  li.dataset.line = f.line === null ? "" : f.line;
  const where = [f.file, f.line, f.column].filter((x) => x !== null && x !== undefined).join(":");
  li.innerHTML = '<span class="sev"></span> <span class="code"></span> ' +
    '<span class="where"></span> <span class="msg"></span>';
  li.querySelector(".sev").textContent = f.severity;
  li.querySelector(".code").textContent = f.code;
  li.querySelector(".where").textContent = where;
  li.querySelector(".msg").textContent = f.message;
  if (f.source !== null) {
    const pre = document.createElement("pre");
    pre.className = "src";
    pre.textContent = f.line + " | " + f.source;
    li.appendChild(pre);
  }
  return li;
}

let shown = null;  // the version of the picture and view on the page
function update(state) {
  window.preview.state = state;
  $("file").textContent = state.file;
  document.title = state.file + " (xaml3d preview)";
  const errors = state.findings.filter((f) => f.severity === "error").length;
  const warnings = state.findings.filter((f) => f.severity === "warning").length;
  const status = $("status");
  status.className = state.current ? "ok" : "broken";
  status.textContent = state.current
    ? `up to date: ${warnings} warning(s)`
    : `${errors} error(s): not rendered` + (state.picture ? ", the last good picture is kept" : "");
  $("when").textContent = `read at ${state.time} in ${state.seconds} s (update ${state.version})`;
  const list = $("list");
  list.replaceChildren(...state.findings.map(finding));
  if (!state.findings.length) list.innerHTML = "<li>none</li>";
  const good = state.picture;
  $("picture-box").classList.toggle("stale", !state.current);
  const kept = good ? `the last good picture, from ${good.time} (update ${good.version})` : "";
  $("picture-note").textContent = !good ? "no picture yet" : state.current ? "" : kept;
  if (good && good.version !== shown) {
    shown = good.version;
    $("picture").src = "picture.png?v=" + good.version;
    $("picture-size").textContent = `${good.width} x ${good.height}`;
    const view = $("view");
    view.width = good.width + 560;
    view.height = good.height + 80;
    view.src = "view.html?v=" + good.version;
  }
  $("camera").textContent = cameraText(state.camera);
  window.preview.updates += 1;
}

const events = new EventSource("events");
events.onmessage = (e) => update(JSON.parse(e.data));
events.onerror = () => {
  $("status").className = "waiting";
  $("status").textContent = "reconnecting... (is xaml3d preview still running?)";
};
</script>
</body>
</html>
"""
