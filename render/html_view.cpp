// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the self-contained HTML view (render/picture.h).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/input_error.h"
#include "io/output_stream.h"
#include "render/colormap.h"
#include "render/picture.h"

namespace archgeo {
namespace {

// The page: data in `const VIEW = {...}`; painter's algorithm on 2D
// canvases that fill the window (orthographic, flat shading as the PNG); the
// legend keeps its column. Drag rotates, shift- or right-drag pans, the wheel
// zooms about the cursor, R or the button resets; hovering a face shows its
// id and value, a click pins it (and puts #face=ID in the address, which
// pins it when the page is opened).
constexpr const char* kPage = R"HTML(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>archgeo view</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<style>
html, body { height: 100%; margin: 0; }
body { font-family: "DejaVu Sans", sans-serif; background: #fff; display: flex;
  flex-direction: column; overflow: hidden; }
#main { flex: 1; display: flex; min-height: 0; }
#panels { flex: 1; display: flex; min-width: 0; }
.panel { flex: 1; display: flex; flex-direction: column; min-width: 0; text-align: center; }
.panel h2 { font-size: 16px; margin: 8px 4px 2px; overflow: hidden; white-space: nowrap;
  text-overflow: ellipsis; }
.panel p { font-size: 13px; margin: 0 4px 4px; min-height: 1em; }
.panel canvas { flex: 1; min-height: 0; width: 100%; display: block; cursor: grab;
  touch-action: none; }
#legend { flex: 0 0 120px; display: flex; padding: 48px 8px 32px 12px; box-sizing: border-box; }
#gradient { width: 26px; border: 1px solid #000;
  background: linear-gradient(to top, #00ff00, #ffff00 50%, #ff0000); }
#ticks { position: relative; flex: 1; font-size: 12px; }
#ticks span { position: absolute; left: 6px; transform: translateY(-50%); white-space: nowrap; }
#footer { display: flex; flex-wrap: wrap; align-items: center; gap: 4px 12px; font-size: 13px;
  margin: 4px 12px 6px; }
#caption { flex: 1 1 300px; }
#pinned { flex: 1 0 100%; order: 3; font-weight: bold; }
#pinned:empty { display: none; }
#tip { position: fixed; pointer-events: none; background: rgba(255,255,255,0.92);
  border: 1px solid #444; padding: 2px 6px; font-size: 12px; display: none; white-space: nowrap; }
</style></head><body>
<div id="main"><div id="panels"></div><div id="legend"></div></div>
<div id="footer"><span id="caption"></span><span id="pinned"></span>
<button id="reset" type="button">Reset view (R)</button></div>
<div id="tip"></div>
<script>
const VIEW = @DATA@;
function rotate(v, axis, a) {  // Rodrigues
  const c = Math.cos(a), s = Math.sin(a);
  const d = axis[0]*v[0] + axis[1]*v[1] + axis[2]*v[2];
  const x = [axis[1]*v[2]-axis[2]*v[1], axis[2]*v[0]-axis[0]*v[2], axis[0]*v[1]-axis[1]*v[0]];
  return [0,1,2].map(i => v[i]*c + x[i]*s + axis[i]*d*(1-c));
}
const dot = (a, b) => a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
let cam, zoom, pan, pinned = null;
const shown = [];  // per panel, from the last draw: screen points and the drawing order
function reset() { cam = VIEW.camera.map(r => r.slice()); zoom = 1; pan = [0, 0]; }
function extent() {
  let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
  for (const p of VIEW.panels) for (const q of p.points) {
    const s = [dot(q, cam[0]), dot(q, cam[1])];
    for (let i = 0; i < 2; ++i) { lo[i] = Math.min(lo[i], s[i]); hi[i] = Math.max(hi[i], s[i]); }
  }
  return [lo, hi];
}
function canvasSize(canvas) {
  const r = canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
  const w = Math.max(1, Math.floor(r.width)), h = Math.max(1, Math.floor(r.height));
  if (canvas.width != Math.round(w*dpr) || canvas.height != Math.round(h*dpr)) {
    canvas.width = Math.round(w*dpr); canvas.height = Math.round(h*dpr);
  }
  return [w, h, dpr];
}
function draw() {
  const [lo, hi] = extent();
  const cx = (lo[0]+hi[0])/2, cy = (lo[1]+hi[1])/2;
  let fit = Infinity;
  const sizes = VIEW.panels.map((p, i) => canvasSize(document.getElementById("c" + i)));
  for (const [W, H] of sizes) {
    const m = 16;
    fit = Math.min(fit, (W - 2*m) / Math.max(hi[0]-lo[0], 1e-300),
                   (H - 2*m) / Math.max(hi[1]-lo[1], 1e-300));
  }
  const k = Math.max(fit, 1e-300) * zoom;
  VIEW.panels.forEach((p, i) => {
    const [W, H, dpr] = sizes[i];
    const ctx = document.getElementById("c" + i).getContext("2d");
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, W, H);
    const sx = p.points.map(q => W/2 + pan[0] + k*(dot(q, cam[0]) - cx));
    const sy = p.points.map(q => H/2 + pan[1] - k*(dot(q, cam[1]) - cy));
    const depth = p.faces.map(f => f.reduce((a, v) => a + dot(p.points[v], cam[2]), 0) / f.length);
    const order = p.faces.map((f, j) => j).sort((a, b) => depth[a] - depth[b]);
    shown[i] = {sx, sy, order};
    let edge = 0, n = 0;
    for (const f of p.faces) for (let j = 0; j < f.length; ++j) {
      const a = f[j], b = f[(j+1) % f.length]; edge += Math.hypot(sx[a]-sx[b], sy[a]-sy[b]); ++n; }
    const edges = n > 0 && edge / n > 6;
    for (const j of order) {
      const f = p.faces[j];
      let nx = 0, ny = 0, nz = 0;  // Newell normal
      for (let t = 0; t < f.length; ++t) {
        const a = p.points[f[t]], b = p.points[f[(t+1) % f.length]];
        nx += a[1]*b[2]-a[2]*b[1]; ny += a[2]*b[0]-a[0]*b[2]; nz += a[0]*b[1]-a[1]*b[0];
      }
      const len = Math.hypot(nx, ny, nz) || 1;
      const light = 0.45 + 0.55*Math.abs(dot([nx/len, ny/len, nz/len], cam[2]));
      const c = p.colors[j];
      outline(ctx, f, sx, sy);
      const fill = `rgb(${Math.round(light*c[0])},${Math.round(light*c[1])},${Math.round(light*c[2])})`;
      ctx.fillStyle = fill; ctx.fill();
      ctx.lineWidth = edges ? 0.6 : 0.5;
      ctx.strokeStyle = edges ? "rgba(26,26,26,0.6)" : fill; ctx.stroke();
    }
    if (pinned !== null && pinned < p.faces.length) {
      outline(ctx, p.faces[pinned], sx, sy);
      ctx.lineWidth = 3; ctx.strokeStyle = "#0050ff"; ctx.stroke();
    }
  });
}
function outline(ctx, f, sx, sy) {
  ctx.beginPath();
  ctx.moveTo(sx[f[0]], sy[f[0]]);
  for (let t = 1; t < f.length; ++t) ctx.lineTo(sx[f[t]], sy[f[t]]);
  ctx.closePath();
}
// The front-most face of panel i under (x, y) in canvas pixels, or null.
function pick(i, x, y) {
  const s = shown[i], faces = VIEW.panels[i].faces;
  if (!s) return null;
  for (let o = s.order.length - 1; o >= 0; --o) {
    const f = faces[s.order[o]];
    let inside = false;
    for (let a = 0, b = f.length - 1; a < f.length; b = a++) {
      const xa = s.sx[f[a]], ya = s.sy[f[a]], xb = s.sx[f[b]], yb = s.sy[f[b]];
      if ((ya > y) != (yb > y) && x < (xb - xa) * (y - ya) / (yb - ya) + xa) inside = !inside;
    }
    if (inside) return s.order[o];
  }
  return null;
}
function describe(i, j) {
  const p = VIEW.panels[i], v = p.values ? p.values[j] : null;
  if (v === null || v === undefined) return `face ${j}`;
  const number = v != 0 && Math.abs(v) < 1e-3 ? v.toExponential(3) : String(+v.toPrecision(4));
  return `face ${j}: ${VIEW.scale.label} ${number}` +
         (VIEW.scale.units ? ` [${VIEW.scale.units}]` : "");
}
function pin(j) {
  pinned = j;
  const text = pinned === null ? "" : VIEW.panels.map((p, i) =>
      (VIEW.panels.length > 1 ? p.title + " \u2014 " : "") + describe(i, pinned)).join("; ");
  document.getElementById("pinned").textContent = text ? "pinned " + text : "";
  try { history.replaceState(null, "", pinned === null ? location.pathname : "#face=" + pinned); }
  catch (e) { /* a page the browser will not let change its address */ }
  draw();
}
function setup() {
  const box = document.getElementById("panels");
  VIEW.panels.forEach((p, i) => {
    const d = document.createElement("div"); d.className = "panel";
    d.innerHTML = `<h2></h2><p></p><canvas id="c${i}"></canvas>`;
    d.querySelector("h2").textContent = p.title;
    d.querySelector("p").textContent = p.summary;
    box.appendChild(d);
  });
  const legend = document.getElementById("legend");
  if (VIEW.scale.bar) {
    legend.innerHTML = `<div id="gradient"></div><div id="ticks"></div>`;
    const ticks = legend.querySelector("#ticks");
    for (const f of [0, 0.25, 0.5, 0.75, 1]) {
      const s = document.createElement("span"); s.style.top = `${(1-f)*100}%`;
      s.textContent = (f == 1 ? "\u2265 " : "") + +(f*VIEW.scale.red_at).toPrecision(3);
      ticks.appendChild(s);
    }
  } else {
    legend.style.display = "none";
  }
  document.getElementById("caption").textContent =
      VIEW.caption + " \u2014 drag: rotate, shift/right-drag: pan, wheel: zoom, click: pin a face";
  const tip = document.getElementById("tip");
  let last = null, moved = 0, panning = false;
  box.addEventListener("contextmenu", e => e.preventDefault());
  box.addEventListener("pointerdown", e => {
    last = [e.clientX, e.clientY]; moved = 0; panning = e.shiftKey || e.button != 0;
  });
  window.addEventListener("pointerup", e => {
    if (last && moved < 4 && e.target.tagName == "CANVAS") {
      const i = +e.target.id.slice(1), r = e.target.getBoundingClientRect();
      const j = pick(i, e.clientX - r.left, e.clientY - r.top);
      pin(j === pinned ? null : j);
    }
    last = null;
  });
  window.addEventListener("pointermove", e => {
    if (last) {
      const dx = e.clientX - last[0], dy = e.clientY - last[1]; last = [e.clientX, e.clientY];
      moved += Math.abs(dx) + Math.abs(dy);
      if (panning) { pan = [pan[0] + dx, pan[1] + dy]; }
      else { const up = cam[1], right = cam[0];
             cam = cam.map(v => rotate(rotate(v, up, dx*0.01), right, dy*0.01)); }
      tip.style.display = "none";
      draw();
      return;
    }
    if (e.target.tagName != "CANVAS") { tip.style.display = "none"; return; }
    const i = +e.target.id.slice(1), r = e.target.getBoundingClientRect();
    const j = pick(i, e.clientX - r.left, e.clientY - r.top);
    if (j === null) { tip.style.display = "none"; return; }
    tip.textContent = describe(i, j);
    tip.style.display = "block";
    tip.style.left = Math.min(e.clientX + 14, window.innerWidth - tip.offsetWidth - 4) + "px";
    tip.style.top = Math.max(e.clientY - 28, 4) + "px";
  });
  box.addEventListener("wheel", e => {
    if (e.target.tagName != "CANVAS") return;
    e.preventDefault();
    const r = e.target.getBoundingClientRect();
    const mx = e.clientX - r.left - r.width/2, my = e.clientY - r.top - r.height/2;
    const z = Math.min(Math.max(zoom * Math.exp(-e.deltaY * 0.0015), 0.05), 500);
    pan = [mx - (z/zoom)*(mx - pan[0]), my - (z/zoom)*(my - pan[1])];
    zoom = z;
    draw();
  }, {passive: false});
  document.getElementById("reset").addEventListener("click", () => { reset(); draw(); });
  window.addEventListener("keydown", e => {
    if (e.key == "r" || e.key == "R") { reset(); draw(); }
    if (e.key == "Escape") pin(null);
  });
  window.addEventListener("resize", draw);
  reset();
  const hash = /^#face=(\d+)$/.exec(location.hash);
  if (hash && VIEW.panels.some(p => +hash[1] < p.faces.length)) pin(+hash[1]); else draw();
}
setup();
</script></body></html>
)HTML";

}  // namespace

void WriteHtmlView(const std::string& path, const std::vector<PicturePanel>& panels,
                   const PictureScale& scale, const PictureOptions& options,
                   const std::string& key) {
  if (panels.empty()) throw InputError(path, 0, key, "no mesh to draw");
  nlohmann::json view;
  view["camera"] = DefaultCamera(panels.front(), options.tilt_degrees);
  view["scale"] = {{"label", scale.label}, {"units", scale.units}, {"red_at", scale.red_at},
                   {"bar", scale.bar}};
  char caption[512];
  std::snprintf(caption, sizeof caption, "colour: %s%s; red at %.3g%s", scale.label.c_str(),
                scale.units.empty() ? "" : (" [" + scale.units + "]").c_str(), scale.red_at,
                scale.red_from.empty() ? "" : (" (" + scale.red_from + ")").c_str());
  view["caption"] = scale.bar ? std::string(caption) : "faces grey: " + scale.label;
  for (const PicturePanel& p : panels) {
    if (p.faces.empty()) throw InputError(path, 0, key, "a mesh to draw has no faces");
    nlohmann::json colors = nlohmann::json::array();
    for (size_t f = 0; f < p.faces.size(); ++f) {
      const auto c = p.face_values.empty() ? std::array<unsigned char, 3>{190, 190, 190}
                                           : ScaleColor(p.face_values[f], scale.red_at);
      colors.push_back({c[0], c[1], c[2]});
    }
    // The values the colours show, for hover and pin (null where not finite).
    nlohmann::json values = nullptr;
    if (!p.face_values.empty()) {
      values = nlohmann::json::array();
      for (double v : p.face_values) values.push_back(std::isfinite(v) ? nlohmann::json(v) : nullptr);
    }
    view["panels"].push_back({{"title", p.title},
                              {"summary", PanelSummary(p, scale.red_at)},
                              {"points", p.points},
                              {"faces", p.faces},
                              {"colors", colors},
                              {"values", values}});
  }
  std::string page = kPage;
  // "</" cannot end the script early: JSON escapes it.
  std::string data = view.dump();
  for (size_t at = 0; (at = data.find("</", at)) != std::string::npos; at += 3) {
    data.replace(at, 2, "<\\/");
  }
  page.replace(page.find("@DATA@"), 6, data);
  NoFollowOfstream out(path);
  if (!out) {
    throw InputError(path, 0, key, std::string("cannot open for writing: ") + std::strerror(errno));
  }
  out << page;
  out.close();
  if (!out) throw InputError(path, 0, key, "cannot write the HTML view");
}

void WriteView(const std::string& path, const std::vector<PicturePanel>& panels,
               const PictureScale& scale, const PictureOptions& options,
               const std::string& key) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".html" || extension == ".htm") {
    WriteHtmlView(path, panels, scale, options, key);
  } else {
    WritePicture(path, panels, scale, options, key);
  }
}

}  // namespace archgeo
