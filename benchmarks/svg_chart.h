// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Panels stacked over one logarithmic x axis, written as SVG text (no
// library): for a benchmark's picture of measures against a swept setting.
// Each panel has its own y axis (linear or logarithmic), points joined by a
// line, each point filled or hollow, horizontal reference lines, and the
// figure has vertical reference lines through every panel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace bench {

struct ChartLine {  // a reference line at `at` (x or y units)
  double at = 0;
  std::string label, color = "#c0392b";
};

struct ChartSeries {
  std::vector<double> x, y;
  std::vector<bool> filled;  // per point; hollow where false
  std::string color = "#1f4e9c";
  bool joined = true;  // a line through the points in order
  bool diamond = false;  // diamond markers instead of circles
};

struct ChartPanel {
  std::string y_label;
  bool log_y = false;
  std::vector<ChartSeries> series;
  std::vector<ChartLine> lines;  // horizontal
  bool diagonal = false;         // the line y = x (same units as x)
  const char* y_tick_format = nullptr;  // default: "%.2g" on a log axis, "%g" on a linear one
  double y_tick_scale = 1;              // label = tick × scale
};

struct Chart {
  std::string title, x_label, legend;
  double x_min = 0, x_max = 1;      // > 0: the x axis is logarithmic
  std::vector<double> x_ticks;      // labelled with x_tick_format
  const char* x_tick_format = "%g";
  double x_tick_scale = 1;          // label = tick × scale
  std::vector<ChartLine> lines;     // vertical, through every panel
  std::vector<ChartPanel> panels;
};

namespace svg_detail {

inline std::string Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

inline std::string Escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

inline std::string Text(double x, double y, const std::string& s, const char* anchor = "start",
                        int size = 11, const std::string& extra = "") {
  return "<text x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" font-size=\"" + std::to_string(size) +
         "\" text-anchor=\"" + anchor + "\"" + extra + ">" + Escape(s) + "</text>\n";
}

inline std::string Line(double x0, double y0, double x1, double y1, const std::string& color,
                        const std::string& extra = "") {
  return "<line x1=\"" + Num(x0) + "\" y1=\"" + Num(y0) + "\" x2=\"" + Num(x1) + "\" y2=\"" +
         Num(y1) + "\" stroke=\"" + color + "\"" + extra + "/>\n";
}

// Up to about six round values covering [lo, hi] (linear axis).
inline std::vector<double> LinearTicks(double lo, double hi) {
  const double raw = (hi - lo) / 5;
  const double magnitude = std::pow(10, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::fabs(t) < 1e-9 * step ? 0.0 : t);  // no "-0"
  }
  return ticks;
}

// Powers of ten in [lo, hi], with 2 and 5 times them when fewer than three.
inline std::vector<double> LogTicks(double lo, double hi) {
  std::vector<double> ticks;
  for (double mantissas : {1.0, 3.0}) {
    ticks.clear();
    for (int e = int(std::floor(std::log10(lo))); e <= int(std::ceil(std::log10(hi))); ++e) {
      for (double m : {1.0, 2.0, 5.0}) {
        if (m > 1 && mantissas < 2) continue;
        const double t = m * std::pow(10, e);
        if (t >= lo * (1 - 1e-12) && t <= hi * (1 + 1e-12)) ticks.push_back(t);
      }
    }
    if (ticks.size() >= 3) break;
  }
  return ticks;
}

}  // namespace svg_detail

// The chart as an SVG document, `width` pixels wide, `panel_height` per panel.
inline std::string RenderSvg(const Chart& c, double width = 680, double panel_height = 150) {
  using namespace svg_detail;
  const double left = 78, right = 24, top = 56, gap = 26, bottom = 48;
  const double plot_w = width - left - right;
  const double height = top + c.panels.size() * (panel_height + gap) - gap + bottom;
  const auto px = [&](double x) {
    return left + plot_w * (std::log(x) - std::log(c.x_min)) / (std::log(c.x_max) - std::log(c.x_min));
  };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + Num(width) +
                  "\" height=\"" + Num(height) + "\" viewBox=\"0 0 " + Num(width) + " " +
                  Num(height) + "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += Text(width / 2, 20, c.title, "middle", 13, " font-weight=\"bold\"");
  s += Text(width / 2, 38, c.legend, "middle", 11);
  for (size_t i = 0; i < c.panels.size(); ++i) {
    const ChartPanel& p = c.panels[i];
    const double y0 = top + i * (panel_height + gap), y1 = y0 + panel_height;
    // The y range: every point and reference line, padded.
    double lo = 1e300, hi = -1e300;
    for (const ChartSeries& se : p.series) {
      for (double y : se.y) {
        if (std::isfinite(y) && (!p.log_y || y > 0)) lo = std::min(lo, y), hi = std::max(hi, y);
      }
    }
    for (const ChartLine& l : p.lines) lo = std::min(lo, l.at), hi = std::max(hi, l.at);
    if (p.diagonal) lo = std::min(lo, c.x_min), hi = std::max(hi, c.x_max);
    if (!(lo <= hi)) lo = p.log_y ? 1 : 0, hi = p.log_y ? 10 : 1;
    if (p.log_y) {
      lo /= 1.4, hi *= 1.4;
    } else {
      const double pad = hi > lo ? 0.08 * (hi - lo) : std::max(1.0, 0.05 * std::fabs(hi));
      lo = lo >= 0 ? std::max(0.0, lo - pad) : lo - pad;  // no negative range for data ≥ 0
      hi += pad;
    }
    const auto py = [&](double y) {
      const double t = p.log_y ? (std::log(y) - std::log(lo)) / (std::log(hi) - std::log(lo))
                               : (y - lo) / (hi - lo);
      return y1 - panel_height * t;
    };
    s += "<rect x=\"" + Num(left) + "\" y=\"" + Num(y0) + "\" width=\"" + Num(plot_w) +
         "\" height=\"" + Num(panel_height) + "\" fill=\"none\" stroke=\"#555\"/>\n";
    std::vector<double> ticks = p.log_y ? LogTicks(lo, hi) : LinearTicks(lo, hi);
    if (ticks.size() < 3) ticks = LinearTicks(lo, hi);  // a log axis less than a decade long
    for (double t : ticks) {
      s += Line(left, py(t), left + plot_w, py(t), "#e4e4e4");
      char b[32];
      std::snprintf(b, sizeof b, p.y_tick_format ? p.y_tick_format : p.log_y ? "%.2g" : "%g",
                    t * p.y_tick_scale);
      s += Text(left - 5, py(t) + 4, b, "end", 10);
    }
    for (double t : c.x_ticks) s += Line(px(t), y0, px(t), y1, "#e4e4e4");
    s += Text(14, (y0 + y1) / 2, p.y_label, "middle", 11,
              " transform=\"rotate(-90 14 " + Num((y0 + y1) / 2) + ")\"");
    // Lines and points are clipped to the panel.
    const std::string clip = "panel" + std::to_string(i);
    s += "<clipPath id=\"" + clip + "\"><rect x=\"" + Num(left) + "\" y=\"" + Num(y0) +
         "\" width=\"" + Num(plot_w) + "\" height=\"" + Num(panel_height) + "\"/></clipPath>\n";
    s += "<g clip-path=\"url(#" + clip + ")\">\n";
    if (p.diagonal) {
      s += Line(px(c.x_min), py(c.x_min), px(c.x_max), py(c.x_max), "#888",
                " stroke-dasharray=\"2 3\"");
      // Labelled above the line, where no point lies when y ≤ x.
      const double at = c.x_min * std::pow(c.x_max / c.x_min, 0.3);
      s += Text(px(at), py(at) - 8, "y = x", "end", 10, " fill=\"#666\"");
    }
    for (const ChartLine& l : p.lines) {
      s += Line(left, py(l.at), left + plot_w, py(l.at), l.color, " stroke-dasharray=\"6 4\"");
      // The label above the line, below it where the panel's top is near.
      const double label_y = py(l.at) - 4 < y0 + 12 ? py(l.at) + 12 : py(l.at) - 4;
      s += Text(left + 4, label_y, l.label, "start", 10, " fill=\"" + l.color + "\"");
    }
    for (const ChartLine& l : c.lines) {
      s += Line(px(l.at), y0, px(l.at), y1, l.color, " stroke-dasharray=\"6 4\"");
      // The label left of the line, right of it where the panel's left edge is near.
      const bool room_left = px(l.at) - left > 6.0 * l.label.size();
      if (i == 0) {
        s += Text(px(l.at) + (room_left ? -4 : 4), y0 + 12, l.label, room_left ? "end" : "start",
                  10, " fill=\"" + l.color + "\"");
      }
    }
    for (const ChartSeries& se : p.series) {
      std::string path;
      for (size_t k = 0; k < se.x.size(); ++k) {
        if (!std::isfinite(se.y[k]) || (p.log_y && se.y[k] <= 0)) continue;
        path += (path.empty() ? "M" : " L") + Num(px(se.x[k])) + " " + Num(py(se.y[k]));
      }
      if (se.joined && !path.empty()) {
        s += "<path d=\"" + path + "\" fill=\"none\" stroke=\"" + se.color +
             "\" stroke-width=\"1.5\"/>\n";
      }
      for (size_t k = 0; k < se.x.size(); ++k) {
        if (!std::isfinite(se.y[k]) || (p.log_y && se.y[k] <= 0)) continue;
        const double x = px(se.x[k]), y = py(se.y[k]);
        const std::string fill = k < se.filled.size() && se.filled[k] ? se.color : "white";
        const std::string style = "\" fill=\"" + fill + "\" stroke=\"" + se.color +
                                  "\" stroke-width=\"1.5\"/>\n";
        if (se.diamond) {
          s += "<path d=\"M" + Num(x) + " " + Num(y - 6) + " L" + Num(x + 6) + " " + Num(y) +
               " L" + Num(x) + " " + Num(y + 6) + " L" + Num(x - 6) + " " + Num(y) + " Z" + style;
        } else {
          s += "<circle cx=\"" + Num(x) + "\" cy=\"" + Num(y) + "\" r=\"4" + style;
        }
      }
    }
    s += "</g>\n";
  }
  const double axis_y = top + c.panels.size() * (panel_height + gap) - gap;
  for (double t : c.x_ticks) {
    char b[32];
    std::snprintf(b, sizeof b, c.x_tick_format, t * c.x_tick_scale);
    s += Line(px(t), axis_y, px(t), axis_y + 4, "#555");
    s += Text(px(t), axis_y + 16, b, "middle", 10);
  }
  s += Text(left + plot_w / 2, axis_y + 36, c.x_label, "middle", 11);
  return s + "</svg>\n";
}

}  // namespace bench
