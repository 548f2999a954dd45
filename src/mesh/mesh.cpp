#include "mesh/mesh.hpp"

#include "mesh/duplicate_points.hpp"
#include "mesh/mesh_checks.hpp"
#include "poly/sample_fit.hpp"
#include "util/error.hpp"
#include "util/page_pool.hpp"
#include "util/stopwatch.hpp"

#include <regex>

namespace hoct {

namespace {

void throw_if_invalid(const Mesh &m, const MeshInput &input, const MeshBuildOptions &options) {
  if (options.throw_on_error && m.problems.has_errors())
    throw Error((input.source.empty() ? std::string("mesh") : input.source) +
                ": the mesh is not valid:\n" + m.problems.summary());
}

// A message about the split mesh's cells ("cell 12", "cells 7 and 12") about the input's.
std::string name_input_cells(const std::string &message, const CellOrigins &origins) {
  static const std::regex cells(R"(\b(cells?) (\d+)(?: and (\d+))?)");
  std::string out;
  auto number = [&](const std::string &digits) { return origins.input_cell(std::stoll(digits)); };
  std::sregex_iterator it(message.begin(), message.end(), cells), end;
  std::size_t last = 0;
  bool renamed = false;
  for (; it != end; ++it) {
    const std::smatch &mt = *it;
    out.append(message, last, static_cast<std::size_t>(mt.position(0)) - last);
    const int64_t a = number(mt[2].str());
    if (!mt[3].matched) {
      out += (origins.quadrilateral(a) ? "quadrilateral " : "cell ") + std::to_string(a);
    } else {
      const int64_t b = number(mt[3].str());
      auto named = [&](int64_t c) {
        return std::to_string(c) + (origins.quadrilateral(c) ? " (a quadrilateral)" : "");
      };
      out += "cells " + named(a) + " and " + named(b);
    }
    last = static_cast<std::size_t>(mt.position(0) + mt.length(0));
    renamed = true;
  }
  out.append(message, last, std::string::npos);
  if (renamed)
    out += " [the input's cell numbers; a quadrilateral of order p is checked as two triangles "
           "of degree 2p]";
  return out;
}

// Both build_mesh: with `consumed` (the input itself), its arrays are released along the way.
// The geometry is built before the field: the field needs every array but the points.
Mesh build(const MeshInput &original, MeshInput *consumed, const MeshBuildOptions &options) {
  // The topology's large temporaries (its edge records: 48 bytes per cell) give their pages to
  // the geometry and the field built after them.
  const PageReuseScope reuse_pages;
  Mesh m;
  m.source = original.source;
  m.field_name = original.field_name;
  m.field_detail = original.field_detail;
  m.num_points = static_cast<int64_t>(original.points.size());
  m.fingerprint = mesh_fingerprint(original);
  MeshBuildTimes &times = m.build_times;
  Stopwatch step;
  auto step_done = [&step](double &seconds) { seconds = step.lap(); };
  const bool structural_ok = check_input(original, m.problems, options.threads);
  if (structural_ok) {
    // Counted in a flat table, not by a map lookup per cell: this runs over every input cell.
    constexpr int kKinds = static_cast<int>(CellKind::SerendipityQuadrilateral) + 1;
    std::vector<int64_t> counts(static_cast<std::size_t>(kKinds) * 256, 0);
    for (std::size_t c = 0; c < original.num_cells(); ++c)
      ++counts[static_cast<std::size_t>(original.kind(c)) * 256 + original.cell_degree[c]];
    for (std::size_t k = 0; k < counts.size(); ++k)
      if (counts[k] > 0)
        m.input_cell_kinds[{static_cast<CellKind>(k / 256), static_cast<int>(k % 256)}] = counts[k];
  }
  step_done(times.input_checks);
  // Quadrilaterals and Bezier cells become Lagrange triangles first (mesh/cell_split); from
  // then on `input` is the triangles, consumed in the original's place.
  SplitCells split;
  const MeshInput *working = &original;
  if (structural_ok && !original.lagrange_triangles_only()) {
    split = split_cells(original, m.problems, options.threads);
    m.origins = std::move(split.origins);
    m.input_quadrilaterals = split.quadrilaterals;
    m.input_bezier_cells = split.bezier_cells;
    working = &split.mesh;
    if (consumed) {
      MeshInput names;
      names.source = std::move(consumed->source);
      names.field_name = std::move(consumed->field_name);
      names.field_detail = std::move(consumed->field_detail);
      *consumed = std::move(names);
      consumed = &split.mesh;
    }
    step_done(times.cell_split);
  }
  const MeshInput &input = *working;
  // A piece of a larger mesh: the whole mesh's scales (every piece gets here, broken or not).
  std::optional<MeshScales> whole;
  if (options.whole_scales) {
    MeshScales own;
    if (structural_ok) {
      if (!input.values.empty()) {
        auto [lo, hi] = std::minmax_element(input.values.begin(), input.values.end());
        own.min_value = *lo;
        own.max_value = *hi;
      }
      for (const uint8_t d : input.cell_degree)
        own.max_degree = std::max(own.max_degree, static_cast<int>(d));
      if (!input.points.empty())
        own.box = bounding_box(input.points, options.threads);
    }
    whole = options.whole_scales(own);
  }
  // What the build finds in a split mesh names its triangles: kept apart, then renamed.
  ProblemLog split_problems;
  ProblemLog &problems = m.origins.identity() ? m.problems : split_problems;
  if (structural_ok) {
    m.topology = Topology::build(input, problems, options.threads, options.open_points);
    step_done(times.topology);
    // The points' bounding box, once for both (a pass over every point).
    const std::array<Vec3, 2> box =
        whole ? whole->box : bounding_box(input.points, options.threads);
    check_duplicate_vertices(input, m.topology, problems, options.threads, &box);
    step_done(times.duplicate_vertices);
    m.geometry = Geometry::build(input, options.threads, &box);
    if (consumed)
      PooledVector<Vec3>().swap(consumed->points);
    step_done(times.geometry);
    m.field = Field::build(input, m.topology, problems, options.threads, whole ? &*whole : nullptr);
    step_done(times.field);
    check_geometry(m.geometry, m.topology, problems, options.threads);
    check_edge_geometry(m.geometry, m.topology, problems, options.threads);
    step_done(times.geometry_checks);
    m.complete = true;
  }
  if (!m.origins.identity()) {
    split_problems.rewrite_examples(
        [&](const std::string &message) { return name_input_cells(message, m.origins); });
    m.problems.append(split_problems);
  }
  if (consumed && consumed != &split.mesh) {
    MeshInput names;
    names.source = std::move(consumed->source);
    names.field_name = std::move(consumed->field_name);
    names.field_detail = std::move(consumed->field_detail);
    *consumed = std::move(names);
  }
  throw_if_invalid(m, original, options);
  return m;
}

} // namespace

std::string Mesh::describe_input_cells() const {
  bool triangles_only = true;
  for (const auto &[key, n] : input_cell_kinds)
    triangles_only = triangles_only && key.first == CellKind::LagrangeTriangle;
  std::string out;
  for (const auto &[key, n] : input_cell_kinds) {
    if (!out.empty())
      out += ", ";
    if (!triangles_only)
      out += std::string(cell_kind_name(key.first)) + " ";
    out += (is_quadrilateral(key.first) ? "order " : "degree ") + std::to_string(key.second) +
           ": " + std::to_string(n);
  }
  return out;
}

void MeshScales::include(const MeshScales &o) {
  min_value = std::min(min_value, o.min_value);
  max_value = std::max(max_value, o.max_value);
  max_degree = std::max(max_degree, o.max_degree);
  for (int k = 0; k < 3; ++k) {
    box[0][k] = std::min(box[0][k], o.box[0][k]);
    box[1][k] = std::max(box[1][k], o.box[1][k]);
  }
}

Mesh build_mesh(const MeshInput &input, const MeshBuildOptions &options) {
  return build(input, nullptr, options);
}

Mesh build_mesh(MeshInput &&input, const MeshBuildOptions &options) {
  return build(input, &input, options);
}

Mesh build_mesh_from_samples(const MeshInput &input, const std::vector<CellSamples> &samples,
                             const MeshBuildOptions &options) {
  Mesh m;
  m.source = input.source;
  m.field_name = input.field_name;
  m.field_detail = input.field_detail;
  m.num_points = static_cast<int64_t>(input.points.size());
  m.fingerprint = mesh_fingerprint(input); // of the file's data, as for every other mesh
  if (samples.size() != input.num_cells())
    m.problems.add(Problem::InconsistentArrays, std::to_string(samples.size()) +
                                                    " sample sets for " +
                                                    std::to_string(input.num_cells()) + " cells");
  else if (check_input(input, m.problems, options.threads)) {
    m.topology = Topology::build(input, m.problems, options.threads);
    check_duplicate_vertices(input, m.topology, m.problems, options.threads);
    std::vector<BernsteinTriangle> polys(samples.size());
    bool fitted = true;
    for (std::size_t c = 0; c < samples.size(); ++c) {
      try {
        polys[c] =
            bernstein_from_samples(samples[c].positions, samples[c].values, samples[c].degree);
      } catch (const Error &e) {
        m.problems.add(Problem::BadSampleSet, "cell " + std::to_string(c) + ": " + e.what());
        fitted = false;
      }
    }
    if (fitted) {
      m.field = Field::build_from_polynomials(m.topology, polys, m.problems, input.value_precision);
      m.geometry = Geometry::build(input, options.threads);
      check_geometry(m.geometry, m.topology, m.problems, options.threads);
      check_edge_geometry(m.geometry, m.topology, m.problems, options.threads);
      m.complete = true;
    }
  }
  throw_if_invalid(m, input, options);
  return m;
}

} // namespace hoct
