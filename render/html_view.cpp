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

// The page: data in `const VIEW = {...}`; painter's algorithm on a 2D
// canvas, orthographic, flat shading as the PNG.
constexpr const char* kPage = R"HTML(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>archgeo view</title>
<style>
body { font-family: "DejaVu Sans", sans-serif; margin: 0; background: #fff; }
#panels { display: flex; align-items: flex-start; }
.panel { text-align: center; }
.panel h2 { font-size: 16px; margin: 8px 0 2px; }
.panel p { font-size: 13px; margin: 0 0 4px; }
#bar { margin: 80px 0 0 16px; display: flex; }
#gradient { width: 26px; border: 1px solid #000;
  background: linear-gradient(to top, #00ff00, #ffff00 50%, #ff0000); }
#ticks { position: relative; width: 90px; font-size: 12px; }
#ticks span { position: absolute; left: 6px; transform: translateY(-50%); white-space: nowrap; }
#caption { font-size: 13px; margin: 6px 12px; }
</style></head><body>
<div id="panels"></div>
<div id="caption"></div>
<script>
const VIEW = @DATA@;
function rotate(v, axis, a) {  // Rodrigues
  const c = Math.cos(a), s = Math.sin(a);
  const d = axis[0]*v[0] + axis[1]*v[1] + axis[2]*v[2];
  const x = [axis[1]*v[2]-axis[2]*v[1], axis[2]*v[0]-axis[0]*v[2], axis[0]*v[1]-axis[1]*v[0]];
  return [0,1,2].map(i => v[i]*c + x[i]*s + axis[i]*d*(1-c));
}
let cam = VIEW.camera.map(r => r.slice());
const dot = (a, b) => a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
function extent() {
  let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
  for (const p of VIEW.panels) for (const q of p.points) {
    const s = [dot(q, cam[0]), dot(q, cam[1])];
    for (let i = 0; i < 2; ++i) { lo[i] = Math.min(lo[i], s[i]); hi[i] = Math.max(hi[i], s[i]); }
  }
  return [lo, hi];
}
function draw() {
  const [lo, hi] = extent();
  const W = VIEW.width, H = VIEW.height, m = 24;
  const k = Math.min((W - 2*m) / Math.max(hi[0]-lo[0], 1e-300), (H - 2*m) / Math.max(hi[1]-lo[1], 1e-300));
  const cx = (lo[0]+hi[0])/2, cy = (lo[1]+hi[1])/2;
  VIEW.panels.forEach((p, i) => {
    const ctx = document.getElementById("c" + i).getContext("2d");
    ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, W, H);
    const sx = p.points.map(q => W/2 + k*(dot(q, cam[0]) - cx));
    const sy = p.points.map(q => H/2 - k*(dot(q, cam[1]) - cy));
    const depth = p.faces.map(f => f.reduce((a, v) => a + dot(p.points[v], cam[2]), 0) / f.length);
    const order = p.faces.map((f, j) => j).sort((a, b) => depth[a] - depth[b]);
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
      ctx.beginPath();
      ctx.moveTo(sx[f[0]], sy[f[0]]);
      for (let t = 1; t < f.length; ++t) ctx.lineTo(sx[f[t]], sy[f[t]]);
      ctx.closePath();
      const fill = `rgb(${Math.round(light*c[0])},${Math.round(light*c[1])},${Math.round(light*c[2])})`;
      ctx.fillStyle = fill; ctx.fill();
      ctx.lineWidth = edges ? 0.6 : 0.5;
      ctx.strokeStyle = edges ? "rgba(26,26,26,0.6)" : fill; ctx.stroke();
    }
  });
}
function setup() {
  const box = document.getElementById("panels");
  VIEW.panels.forEach((p, i) => {
    const d = document.createElement("div"); d.className = "panel";
    d.innerHTML = `<h2></h2><p></p><canvas id="c${i}" width="${VIEW.width}" height="${VIEW.height}"></canvas>`;
    d.querySelector("h2").textContent = p.title;
    d.querySelector("p").textContent = p.summary;
    box.appendChild(d);
  });
  if (!VIEW.scale.bar) {
    document.getElementById("caption").textContent = VIEW.caption + " \u2014 drag to rotate";
  }
  const bar = document.createElement("div"); bar.id = "bar";
  if (!VIEW.scale.bar) bar.style.display = "none";
  const h = VIEW.height - 120;
  bar.innerHTML = `<div id="gradient" style="height:${h}px"></div><div id="ticks" style="height:${h}px"></div>`;
  box.appendChild(bar);
  const ticks = bar.querySelector("#ticks");
  for (const f of [0, 0.25, 0.5, 0.75, 1]) {
    const s = document.createElement("span"); s.style.top = `${(1-f)*h}px`;
    s.textContent = (f == 1 ? "\u2265 " : "") + +(f*VIEW.scale.red_at).toPrecision(3) +
                    (f == 1 && VIEW.scale.units ? " [" + VIEW.scale.units + "]" : "");
    ticks.appendChild(s);
  }
  document.getElementById("caption").textContent = VIEW.caption + " \u2014 drag to rotate";
  let last = null;
  box.addEventListener("pointerdown", e => { last = [e.clientX, e.clientY]; });
  window.addEventListener("pointerup", () => { last = null; });
  window.addEventListener("pointermove", e => {
    if (!last) return;
    const dx = e.clientX - last[0], dy = e.clientY - last[1]; last = [e.clientX, e.clientY];
    const up = cam[1], right = cam[0];
    cam = cam.map(v => rotate(rotate(v, up, dx*0.01), right, dy*0.01));
    draw();
  });
  draw();
}
setup();
</script></body></html>
)HTML";

std::string Summary(const PicturePanel& panel, double red_at) {
  if (panel.face_values.empty()) return "";
  double max = 0;
  size_t red = 0;
  for (double v : panel.face_values) {
    if (std::isfinite(v)) max = std::max(max, v);
    red += v >= red_at;
  }
  char buf[128];
  std::snprintf(buf, sizeof buf, "max %.3g, %.1f%% of faces at red", max,
                100.0 * double(red) / double(panel.face_values.size()));
  return buf;
}

}  // namespace

void WriteHtmlView(const std::string& path, const std::vector<PicturePanel>& panels,
                   const PictureScale& scale, const PictureOptions& options,
                   const std::string& key) {
  if (panels.empty()) throw InputError(path, 0, key, "no mesh to draw");
  nlohmann::json view;
  view["width"] = options.panel_width;
  view["height"] = options.panel_height;
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
    view["panels"].push_back({{"title", p.title},
                              {"summary", Summary(p, scale.red_at)},
                              {"points", p.points},
                              {"faces", p.faces},
                              {"colors", colors}});
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
