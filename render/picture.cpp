// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/picture.h"

#include <cairo.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>

#include "core/input_error.h"
#include "core/newell.h"
#include "io/output_stream.h"
#include "render/colormap.h"

namespace archgeo {
namespace {

constexpr int kBarWidth = 180;    // colour bar column, pixels
constexpr int kTitleHeight = 56;  // panel titles
constexpr int kCaptionHeight = 34;
constexpr double kPi = 3.14159265358979323846;

using Vec = Eigen::Vector3d;

Vec At(const std::array<double, 3>& p) { return Vec(p[0], p[1], p[2]); }

// Screen axes (right, up) and the direction towards the viewer.
struct Camera {
  Vec right, up, toward;
};

Camera MakeCamera(const PicturePanel& panel, double tilt_degrees) {
  Vec mean = Vec::Zero();
  for (const auto& p : panel.points) mean += At(p);
  mean /= double(std::max<size_t>(1, panel.points.size()));
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : panel.points) covariance += (At(p) - mean) * (At(p) - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  Vec normal = eig.eigenvectors().col(0);  // least spread
  Vec right = eig.eigenvectors().col(2);   // most spread
  if (normal.z() < 0 || (normal.z() == 0 && normal.y() < 0)) normal = -normal;
  Vec up = normal.cross(right);
  const double t = tilt_degrees * kPi / 180;
  // Tilt about `right`: the viewer moves from the normal towards -up.
  Camera c;
  c.toward = (std::cos(t) * normal - std::sin(t) * up).normalized();
  c.up = (std::sin(t) * normal + std::cos(t) * up).normalized();
  c.right = c.up.cross(c.toward);
  if (c.up.z() < 0) {  // screen-up towards the world's +z where the view allows
    c.up = -c.up;
    c.right = -c.right;
  }
  return c;
}

Vec FaceNormal(const PicturePanel& panel, const std::vector<int>& face) {
  return NewellNormal(int(face.size()), [&](int i) { return At(panel.points[face[size_t(i)]]); });
}

void Text(cairo_t* cr, double x, double y, const std::string& text, double size, bool bold = false,
          bool centred = false) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(cr, centred ? x - extents.width / 2 - extents.x_bearing : x, y);
  cairo_show_text(cr, text.c_str());
}

std::string Number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

void DrawColorBar(cairo_t* cr, double x, double top, double height, const PictureScale& scale) {
  const double width = 26;
  const int steps = 200;
  for (int i = 0; i < steps; ++i) {
    const double value = scale.red_at * (i + 0.5) / steps;
    const auto c = ScaleColor(value, scale.red_at);
    cairo_set_source_rgb(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    const double y = top + height * (1 - double(i + 1) / steps);
    cairo_rectangle(cr, x, y, width, height / steps + 0.7);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, x, top, width, height);
  cairo_stroke(cr);
  for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double y = top + height * (1 - f);
    cairo_move_to(cr, x + width, y);
    cairo_line_to(cr, x + width + 5, y);
    cairo_stroke(cr);
    Text(cr, x + width + 8, y + 4, (f == 1.0 ? "≥ " : "") + Number(f * scale.red_at), 12);
  }
  // What it shows: the label up to its first ':' (its name), and the unit.
  const std::string name = scale.label.substr(0, scale.label.find(':'));
  Text(cr, x, top - 30, name, 13, true);
  Text(cr, x, top - 12, scale.units.empty() ? "" : "[" + scale.units + "]", 13, true);
}

void DrawPanel(cairo_t* cr, const PicturePanel& panel, const Camera& camera, double scale,
               const Eigen::Vector2d& centre, double x0, double y0, const PictureScale& colours,
               const PictureOptions& options) {
  const double cx = x0 + options.panel_width / 2.0;
  const double cy = y0 + kTitleHeight + (options.panel_height - kTitleHeight) / 2.0;
  std::vector<Eigen::Vector2d> screen(panel.points.size());
  std::vector<double> depth(panel.points.size());
  for (size_t i = 0; i < panel.points.size(); ++i) {
    const Vec p = At(panel.points[i]);
    screen[i] = {cx + scale * (p.dot(camera.right) - centre.x()),
                 cy - scale * (p.dot(camera.up) - centre.y())};
    depth[i] = p.dot(camera.toward);
  }
  std::vector<double> face_depth(panel.faces.size(), 0.0);
  double edge_pixels = 0;
  size_t edge_count = 0;
  for (size_t f = 0; f < panel.faces.size(); ++f) {
    for (size_t k = 0; k < panel.faces[f].size(); ++k) {
      const int a = panel.faces[f][k], b = panel.faces[f][(k + 1) % panel.faces[f].size()];
      face_depth[f] += depth[a] / double(panel.faces[f].size());
      edge_pixels += (screen[a] - screen[b]).norm();
      ++edge_count;
    }
  }
  const bool edges = options.edges && edge_count > 0 && edge_pixels / double(edge_count) > 6;
  std::vector<size_t> order(panel.faces.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return face_depth[a] < face_depth[b]; });
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (size_t f : order) {
    const std::vector<int>& face = panel.faces[f];
    // Flat shading: both sides lit, so a back face is not black.
    const double light = 0.45 + 0.55 * std::abs(FaceNormal(panel, face).dot(camera.toward));
    std::array<unsigned char, 3> c = {190, 190, 190};
    if (!panel.face_values.empty()) c = ScaleColor(panel.face_values[f], colours.red_at);
    cairo_move_to(cr, screen[face[0]].x(), screen[face[0]].y());
    for (size_t k = 1; k < face.size(); ++k) cairo_line_to(cr, screen[face[k]].x(), screen[face[k]].y());
    cairo_close_path(cr);
    cairo_set_source_rgb(cr, light * c[0] / 255.0, light * c[1] / 255.0, light * c[2] / 255.0);
    if (edges) {
      cairo_fill_preserve(cr);
      cairo_set_source_rgba(cr, 0.1, 0.1, 0.1, 0.6);
      cairo_set_line_width(cr, 0.6);
      cairo_stroke(cr);
    } else {
      cairo_set_line_width(cr, 0.5);  // closes hairline gaps between faces
      cairo_fill_preserve(cr);
      cairo_stroke(cr);
    }
  }
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const PictureLine& line : panel.lines) {
    if (line.points.size() < 2) continue;
    for (size_t k = 0; k < line.points.size(); ++k) {
      const Vec p = At(line.points[k]);
      const double x = cx + scale * (p.dot(camera.right) - centre.x());
      const double y = cy - scale * (p.dot(camera.up) - centre.y());
      if (k == 0) {
        cairo_move_to(cr, x, y);
      } else {
        cairo_line_to(cr, x, y);
      }
    }
    cairo_set_source_rgb(cr, line.rgb[0] / 255.0, line.rgb[1] / 255.0, line.rgb[2] / 255.0);
    cairo_set_line_width(cr, line.width);
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  Text(cr, cx, y0 + 22, panel.title, 16, true, true);
  Text(cr, cx, y0 + 44, PanelSummary(panel, colours.red_at), 13, false, true);
}

// cairo's PNG stream writer into a stdio file.
cairo_status_t WritePngBytes(void* file, const unsigned char* data, unsigned int length) {
  return std::fwrite(data, 1, length, static_cast<std::FILE*>(file)) == length
             ? CAIRO_STATUS_SUCCESS
             : CAIRO_STATUS_WRITE_ERROR;
}

}  // namespace

std::array<std::array<double, 3>, 3> DefaultCamera(const PicturePanel& panel,
                                                   double tilt_degrees) {
  const Camera c = MakeCamera(panel, tilt_degrees);
  return {{{c.right.x(), c.right.y(), c.right.z()},
           {c.up.x(), c.up.y(), c.up.z()},
           {c.toward.x(), c.toward.y(), c.toward.z()}}};
}

std::string PanelSummary(const PicturePanel& panel, double red_at) {
  if (panel.face_values.empty()) return "";
  double max = 0;
  size_t red = 0;
  for (double v : panel.face_values) {
    if (std::isfinite(v)) max = std::max(max, v);
    red += v >= red_at;
  }
  char buf[128];
  std::snprintf(buf, sizeof buf, "max %s, %.1f%% of faces at red", Number(max).c_str(),
                100.0 * double(red) / double(panel.face_values.size()));
  return buf;
}

void WritePicture(const std::string& path, const std::vector<PicturePanel>& panels,
                  const PictureScale& scale, const PictureOptions& options,
                  const std::string& key) {
  if (panels.empty()) throw InputError(path, 0, key, "no mesh to draw");
  for (const PicturePanel& p : panels) {
    if (p.faces.empty()) throw InputError(path, 0, key, "a mesh to draw has no faces");
  }
  const Camera camera = MakeCamera(panels.front(), options.tilt_degrees);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const PicturePanel& panel : panels) {
    for (const auto& p : panel.points) {
      const Eigen::Vector2d s(At(p).dot(camera.right), At(p).dot(camera.up));
      lo = lo.cwiseMin(s);
      hi = hi.cwiseMax(s);
    }
  }
  const Eigen::Vector2d centre = (lo + hi) / 2;
  const double margin = 24;
  const double usable_w = options.panel_width - 2 * margin;
  const double usable_h = options.panel_height - kTitleHeight - 2 * margin;
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(1e-300);
  const double pixels = std::min(usable_w / extent.x(), usable_h / extent.y());

  const int width = int(panels.size()) * options.panel_width + (scale.bar ? kBarWidth : 0);
  const int height = options.panel_height + kCaptionHeight;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  for (size_t i = 0; i < panels.size(); ++i) {
    DrawPanel(cr, panels[i], camera, pixels, centre, double(i) * options.panel_width, 0, scale,
              options);
  }
  const double bar_top = kTitleHeight + 40;
  if (scale.bar) {
    DrawColorBar(cr, double(panels.size()) * options.panel_width + 20, bar_top,
                 options.panel_height - bar_top - 40, scale);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  Text(cr, 12, height - 12,
       !scale.bar ? "faces grey: " + scale.label
                  : "colour: " + scale.label + (scale.units.empty() ? "" : " [" + scale.units + "]") +
                        "; red at " + Number(scale.red_at) +
                        (scale.red_from.empty() ? "" : " (" + scale.red_from + ")"),
       13);
  std::FILE* file = FopenNoFollow(path);
  const int open_error = errno;
  const cairo_status_t status =
      file == nullptr ? CAIRO_STATUS_WRITE_ERROR
                      : cairo_surface_write_to_png_stream(surface, &WritePngBytes, file);
  const bool closed = file != nullptr && std::fclose(file) == 0;
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (file == nullptr) {
    throw InputError(path, 0, key,
                     std::string("cannot open for writing: ") + std::strerror(open_error));
  }
  if (status != CAIRO_STATUS_SUCCESS || !closed) {
    throw InputError(path, 0, key,
                     std::string("cannot write the PNG picture: ") +
                         cairo_status_to_string(status == CAIRO_STATUS_SUCCESS
                                                    ? CAIRO_STATUS_WRITE_ERROR
                                                    : status));
  }
}

}  // namespace archgeo
