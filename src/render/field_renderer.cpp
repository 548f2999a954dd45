#include "render/field_renderer.hpp"

#include "io/atomic_file.hpp"
#include "poly/lattice.hpp"
#include "poly/root_isolation.hpp"
#include "render/colormap.hpp"
#include "util/error.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <random>

namespace hoct {
namespace {

struct SubTriangle {
  int64_t cell;
  std::array<Vec2, 3> uv;  // parametric corners
  std::array<Vec3, 3> xyz; // positions
  std::array<double, 3> f; // exact values
  double depth;            // along the view direction (larger = nearer)
  bool facing = true;      // its outward side faces the viewer (closed surfaces)
};

Vec3 cross(const Vec3 &a, const Vec3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized(const Vec3 &a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

// Cairo's output callback: appends to the std::ostream passed as closure.
cairo_status_t write_to_stream(void *closure, const unsigned char *data, unsigned int length) {
  auto *out = static_cast<std::ostream *>(closure);
  out->write(reinterpret_cast<const char *>(data), length);
  return *out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

} // namespace

void render_field(const std::string &path, const Mesh &mesh, const std::vector<TreeNode> &nodes,
                  const RenderOptions &o) {
  namespace fs = std::filesystem;
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext != ".png" && ext != ".svg")
    throw Error(path + ": the picture must be .png or .svg");
  if (o.width < 100 || o.height < 100 || o.width > 10000 || o.height > 10000)
    throw Error("picture size must be between 100 and 10000 pixels");
  const Topology &topo = mesh.topology;
  const Field &field = mesh.field;
  const Geometry &geom = mesh.geometry;
  const int64_t nc = topo.num_cells();
  // View frame: w towards the viewer, e1 and e2 across the picture.
  const Vec3 w = normalized(mesh.geometry.planar() ? Vec3{0, 0, 1} : o.view);
  const Vec3 helper = std::abs(w[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  const Vec3 e1 = normalized(cross(helper, w)), e2 = cross(w, e1);
  // Sub-triangles, at most ~2M in all.
  int k = o.subdivision;
  if (k <= 0) {
    // Sub-triangles of a few pixels: about 2e5 in all, at least 2 per degree per edge.
    const int fine =
        static_cast<int>(std::sqrt(2e5 / std::max<double>(1, static_cast<double>(nc))));
    k = std::clamp(std::max(2 * field.max_degree(), fine), 2, 64);
    while (k > 1 && static_cast<double>(nc) * k * k > 2e6)
      --k;
  }
  std::vector<SubTriangle> tris;
  tris.reserve(static_cast<std::size_t>(nc) * k * k);
  std::vector<Vec3> pos(lattice_size(k));
  std::vector<double> val(lattice_size(k));
  for (int64_t c = 0; c < nc; ++c) {
    const BernsteinTriangle g = field.cell_polynomial(c);
    for (int i = 0; i < lattice_size(k); ++i) {
      const auto q = lattice_point(k, i);
      const double u = static_cast<double>(q[0]) / k, v = static_cast<double>(q[1]) / k;
      pos[i] = geom.position(c, u, v);
      val[i] = g(u, v);
    }
    auto add = [&](int a0, int b0, int a1, int b1, int a2, int b2) {
      SubTriangle t;
      t.cell = c;
      const int idx[3] = {lattice_index(k, a0, b0), lattice_index(k, a1, b1),
                          lattice_index(k, a2, b2)};
      const int ab[3][2] = {{a0, b0}, {a1, b1}, {a2, b2}};
      t.depth = 0;
      for (int j = 0; j < 3; ++j) {
        t.uv[j] = {static_cast<double>(ab[j][0]) / k, static_cast<double>(ab[j][1]) / k};
        t.xyz[j] = pos[idx[j]];
        t.f[j] = val[idx[j]];
        t.depth += dot(t.xyz[j], w) / 3;
      }
      tris.push_back(t);
    };
    for (int b = 0; b < k; ++b)
      for (int a = 0; a + b < k; ++a) {
        add(a, b, a + 1, b, a, b + 1);
        if (a + b + 1 < k)
          add(a + 1, b, a + 1, b + 1, a, b + 1);
      }
  }
  // On a closed surface, isolines are drawn only on sub-triangles facing the viewer: normals made
  // consistent with the cells' orientation parity, and outward by majority vote.
  if (!geom.planar() && topo.boundary_loops() == 0 && topo.orientable()) {
    Vec3 centre{0, 0, 0};
    for (int a = 0; a < 3; ++a)
      centre[a] = 0.5 * (geom.bounds()[0][a] + geom.bounds()[1][a]);
    std::vector<Vec3> normal(tris.size());
    int64_t outward = 0;
    for (std::size_t i = 0; i < tris.size(); ++i) {
      const auto &t = tris[i];
      const Vec3 a = {t.xyz[1][0] - t.xyz[0][0], t.xyz[1][1] - t.xyz[0][1],
                      t.xyz[1][2] - t.xyz[0][2]};
      const Vec3 b = {t.xyz[2][0] - t.xyz[0][0], t.xyz[2][1] - t.xyz[0][1],
                      t.xyz[2][2] - t.xyz[0][2]};
      Vec3 n = cross(a, b);
      const double sgn = topo.cell_parity(t.cell);
      n = {sgn * n[0], sgn * n[1], sgn * n[2]};
      normal[i] = n;
      const Vec3 d = {t.xyz[0][0] - centre[0], t.xyz[0][1] - centre[1], t.xyz[0][2] - centre[2]};
      outward += dot(n, d) > 0 ? 1 : -1;
    }
    const double flip = outward >= 0 ? 1 : -1;
    for (std::size_t i = 0; i < tris.size(); ++i)
      tris[i].facing = flip * dot(normal[i], w) > 0;
  }
  std::stable_sort(tris.begin(), tris.end(),
                   [](const SubTriangle &a, const SubTriangle &b) { return a.depth < b.depth; });
  // Picture frame.
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const auto &t : tris)
    for (const auto &p : t.xyz) {
      xmin = std::min(xmin, dot(p, e1)), xmax = std::max(xmax, dot(p, e1));
      ymin = std::min(ymin, dot(p, e2)), ymax = std::max(ymax, dot(p, e2));
    }
  const double margin = 40, bar = 90, title_h = o.title.empty() ? 0 : 30;
  const double sx = (o.width - 2 * margin - bar) / std::max(xmax - xmin, 1e-300);
  const double sy = (o.height - 2 * margin - title_h) / std::max(ymax - ymin, 1e-300);
  const double scale = std::min(sx, sy);
  const double ox = margin + (o.width - 2 * margin - bar - scale * (xmax - xmin)) / 2;
  const double oy =
      margin + title_h + (o.height - 2 * margin - title_h - scale * (ymax - ymin)) / 2;
  auto px = [&](const Vec3 &p) {
    return std::array<double, 2>{ox + scale * (dot(p, e1) - xmin),
                                 oy + scale * (ymax - dot(p, e2))};
  };
  const double lo = field.min_value(), hi = field.max_value();
  auto colour = [&](double f) { return viridis(hi > lo ? (f - lo) / (hi - lo) : 0.5); };

  // Drawn straight into the atomic file's stream (io/atomic_file: temporary file, then rename).
  write_file_atomic(path, [&](std::ostream &out) {
    cairo_surface_t *surface =
        ext == ".svg"
            ? cairo_svg_surface_create_for_stream(write_to_stream, &out, o.width, o.height)
            : cairo_image_surface_create(CAIRO_FORMAT_RGB24, o.width, o.height);
    if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
      const std::string why = cairo_status_to_string(cairo_surface_status(surface));
      cairo_surface_destroy(surface);
      throw Error(path + ": cannot create the picture (" + why + ")");
    }
    cairo_t *cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    // Isolevels.
    std::vector<double> levels;
    for (int i = 1; i <= o.isolines; ++i)
      levels.push_back(lo + (hi - lo) * i / (o.isolines + 1));
    std::vector<std::array<double, 2>> crossing;
    // Critical points as glyphs, drawn in depth order with the sub-triangles, so that surfaces in
    // front of them hide them.
    auto glyph = [&](const TreeNode &n) {
      const auto p = px(n.position);
      const double rad = n.type == NodeType::Saddle ? 3.5 : 4.5;
      switch (n.type) {
      case NodeType::Maximum:
        cairo_set_source_rgb(cr, 0.84, 0.15, 0.16);
        break;
      case NodeType::Minimum:
        cairo_set_source_rgb(cr, 0.12, 0.47, 0.71);
        break;
      default:
        cairo_set_source_rgb(cr, 0.17, 0.63, 0.17);
      }
      cairo_arc(cr, p[0], p[1], rad, 0, 2 * M_PI);
      cairo_fill_preserve(cr);
      cairo_set_source_rgb(cr, 0, 0, 0);
      cairo_set_line_width(cr, 0.8);
      cairo_stroke(cr);
    };
    std::vector<std::pair<double, std::size_t>> glyph_order;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      glyph_order.push_back({dot(nodes[i].position, w), i});
    std::sort(glyph_order.begin(), glyph_order.end());
    std::size_t next_glyph = 0;
    // A glyph sits on the surface: draw it once the sub-triangles around it are drawn.
    const double lift = geom.planar() ? INFINITY : 0.01 * geom.extent();
    for (const auto &t : tris) {
      while (next_glyph < glyph_order.size() && glyph_order[next_glyph].first + lift < t.depth)
        glyph(nodes[glyph_order[next_glyph++].second]);
      // Smooth colour: a mesh-gradient patch with the exact values at the corners.
      cairo_pattern_t *pat = cairo_pattern_create_mesh();
      cairo_mesh_pattern_begin_patch(pat);
      for (int j = 0; j < 3; ++j) {
        const auto p = px(t.xyz[j]);
        (j == 0 ? cairo_mesh_pattern_move_to : cairo_mesh_pattern_line_to)(pat, p[0], p[1]);
      }
      for (int j = 0; j < 3; ++j) {
        const auto c = colour(t.f[j]);
        cairo_mesh_pattern_set_corner_color_rgb(pat, j, c[0], c[1], c[2]);
      }
      cairo_mesh_pattern_end_patch(pat);
      cairo_set_source(cr, pat);
      cairo_new_path(cr);
      for (int j = 0; j < 3; ++j) {
        const auto p = px(t.xyz[j]);
        (j == 0 ? cairo_move_to : cairo_line_to)(cr, p[0], p[1]);
      }
      cairo_close_path(cr);
      // Without antialiasing, sub-triangles tile the picture exactly: no hairline seams.
      cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
      cairo_fill(cr);
      cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
      cairo_pattern_destroy(pat);
      // Isolines right after their sub-triangle (nearer ones drawn later hide them): exact
      // crossing points on the sub-edges, from the cell's polynomial.
      if (!t.facing)
        continue;
      const double fmin = std::min({t.f[0], t.f[1], t.f[2]}),
                   fmax = std::max({t.f[0], t.f[1], t.f[2]});
      BernsteinTriangle g;
      bool have_g = false;
      for (double level : levels) {
        if (level < fmin || level > fmax)
          continue;
        if (!have_g) {
          g = field.cell_polynomial(t.cell);
          have_g = true;
        }
        crossing.clear();
        for (int j = 0; j < 3; ++j) {
          const int jn = (j + 1) % 3;
          if ((t.f[j] < level) == (t.f[jn] < level))
            continue;
          BernsteinPoly r = g.restrict_to_segment(t.uv[j], t.uv[jn]);
          for (double &c : r.coefficients())
            c -= level;
          const auto roots = find_roots(r);
          double s = roots.empty() ? (level - t.f[j]) / (t.f[jn] - t.f[j]) : roots.front().t;
          const Vec2 uv = {t.uv[j][0] + s * (t.uv[jn][0] - t.uv[j][0]),
                           t.uv[j][1] + s * (t.uv[jn][1] - t.uv[j][1])};
          crossing.push_back(px(geom.position(t.cell, uv[0], uv[1])));
        }
        if (crossing.size() == 2) {
          cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
          cairo_set_line_width(cr, 1.1);
          cairo_move_to(cr, crossing[0][0], crossing[0][1]);
          cairo_line_to(cr, crossing[1][0], crossing[1][1]);
          cairo_stroke(cr);
        }
      }
    }
    while (next_glyph < glyph_order.size())
      glyph(nodes[glyph_order[next_glyph++].second]);
    // Colour bar and title.
    const double bx = o.width - bar + 20, by = margin + title_h,
                 bh = o.height - 2 * margin - title_h;
    for (int i = 0; i < 256; ++i) {
      const auto c = viridis(i / 255.0);
      cairo_set_source_rgb(cr, c[0], c[1], c[2]);
      cairo_rectangle(cr, bx, by + bh * (1 - (i + 1) / 256.0), 18, bh / 256.0 + 0.5);
      cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 11);
    for (int i = 0; i <= 4; ++i) {
      char label[32];
      std::snprintf(label, sizeof label, "%.3g", lo + (hi - lo) * i / 4);
      cairo_move_to(cr, bx + 22, by + bh * (1 - i / 4.0) + 4);
      cairo_show_text(cr, label);
    }
    if (!o.title.empty()) {
      cairo_set_font_size(cr, 15);
      cairo_move_to(cr, margin, margin);
      cairo_show_text(cr, o.title.c_str());
    }
    cairo_destroy(cr);
    cairo_status_t status;
    if (ext == ".png")
      status = cairo_surface_write_to_png_stream(surface, write_to_stream, &out);
    else {
      cairo_surface_finish(surface);
      status = cairo_surface_status(surface);
    }
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS)
      throw Error(path + ": writing the picture failed (" + cairo_status_to_string(status) + ")");
  });
}

} // namespace hoct
