#include "mesh/mesh.hpp"

#include "mesh/duplicate_points.hpp"
#include "mesh/mesh_checks.hpp"
#include "poly/sample_fit.hpp"
#include "util/error.hpp"
#include "util/page_pool.hpp"
#include "util/stopwatch.hpp"

namespace hoct {

namespace {

void throw_if_invalid(const Mesh &m, const MeshInput &input, const MeshBuildOptions &options) {
  if (options.throw_on_error && m.problems.has_errors())
    throw Error((input.source.empty() ? std::string("mesh") : input.source) +
                ": the mesh is not valid:\n" + m.problems.summary());
}

// Both build_mesh: with `consumed` (the input itself), its arrays are released along the way.
// The geometry is built before the field: the field needs every array but the points.
Mesh build(const MeshInput &input, MeshInput *consumed, const MeshBuildOptions &options) {
  // The topology's large temporaries (its edge records: 48 bytes per cell) give their pages to
  // the geometry and the field built after them.
  const PageReuseScope reuse_pages;
  Mesh m;
  m.source = input.source;
  m.field_name = input.field_name;
  m.field_detail = input.field_detail;
  m.num_points = static_cast<int64_t>(input.points.size());
  m.fingerprint = mesh_fingerprint(input);
  MeshBuildTimes &times = m.build_times;
  Stopwatch step;
  auto step_done = [&step](double &seconds) { seconds = step.lap(); };
  const bool structural_ok = check_input(input, m.problems, options.threads);
  step_done(times.input_checks);
  if (structural_ok) {
    m.topology = Topology::build(input, m.problems, options.threads);
    step_done(times.topology);
    // The points' bounding box, once for both (a pass over every point).
    const std::array<Vec3, 2> box = bounding_box(input.points, options.threads);
    check_duplicate_vertices(input, m.topology, m.problems, options.threads, &box);
    step_done(times.duplicate_vertices);
    m.geometry = Geometry::build(input, options.threads, &box);
    if (consumed)
      PooledVector<Vec3>().swap(consumed->points);
    step_done(times.geometry);
    m.field = Field::build(input, m.topology, m.problems, options.threads);
    step_done(times.field);
    check_geometry(m.geometry, m.topology, m.problems, options.threads);
    check_edge_geometry(m.geometry, m.topology, m.problems, options.threads);
    step_done(times.geometry_checks);
    m.complete = true;
  }
  if (consumed) {
    MeshInput names;
    names.source = std::move(consumed->source);
    names.field_name = std::move(consumed->field_name);
    names.field_detail = std::move(consumed->field_detail);
    *consumed = std::move(names);
  }
  throw_if_invalid(m, input, options);
  return m;
}

} // namespace

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
      m.field = Field::build_from_polynomials(m.topology, polys, m.problems);
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
