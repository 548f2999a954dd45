#include "vtkio/exodus_reader.hpp"

#include "io/vtk_cells.hpp"
#include "util/error.hpp"
#include "vtkio/exodus_blocks.hpp"

#include <vtk_exodusII.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace hoct {

namespace {

struct ExodusFile {
  int id = -1;
  ~ExodusFile() {
    if (id >= 0)
      ex_close(id);
  }
};

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

void check(int status, const std::string &path, const std::string &what) {
  if (status < 0)
    throw InputError(path + ": the Exodus library cannot read its " + what + " (error " +
                     std::to_string(status) + ")");
}

// The nodal variables the field is made of: one (a scalar), or the components NAME_x, NAME_y,
// NAME_z (any case) for --component.
std::vector<int> chosen_variables(const std::string &path, const std::vector<std::string> &names,
                                  const FieldSelection &field, std::string *chosen) {
  auto index = [&](const std::string &n) -> int {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == n)
        return static_cast<int>(i);
    return -1;
  };
  std::string listed;
  for (const std::string &n : names)
    listed += (listed.empty() ? "" : ", ") + n;
  if (listed.empty())
    listed = "none";
  if (field.component == FieldSelection::kScalar) {
    if (!field.name.empty()) {
      const int i = index(field.name);
      if (i < 0)
        throw InputError(path + ": no nodal variable '" + field.name +
                         "' (nodal variables: " + listed + ")");
      *chosen = field.name;
      return {i};
    }
    for (std::size_t i = 0; i < names.size(); ++i)
      if (!is_bookkeeping_array(names[i])) {
        *chosen = names[i];
        return {static_cast<int>(i)};
      }
    throw InputError(path + ": no nodal variable to take as the field (nodal variables: " + listed +
                     ")");
  }
  // Components: NAME_x ... of the named vector, or of the first name with a _x component.
  std::string base = field.name;
  if (base.empty())
    for (const std::string &n : names)
      if (n.size() > 2 && upper(n.substr(n.size() - 2)) == "_X") {
        base = n.substr(0, n.size() - 2);
        break;
      }
  std::vector<int> parts;
  for (const char *suffix : {"_x", "_y", "_z"}) {
    int i = index(base + suffix);
    if (i < 0)
      i = index(base + upper(suffix));
    if (i < 0)
      break;
    parts.push_back(i);
  }
  if (parts.empty())
    throw InputError(path + ": --component: no nodal variables " +
                     (base.empty() ? std::string("NAME_x, NAME_y") : base + "_x, " + base + "_y") +
                     " (nodal variables: " + listed + ")");
  if (field.component >= 0) {
    if (field.component >= static_cast<int>(parts.size()))
      throw InputError(path + ": --component " + std::to_string(field.component) + ": '" + base +
                       "' has " + std::to_string(parts.size()) + " components");
    *chosen = names[static_cast<std::size_t>(parts[static_cast<std::size_t>(field.component)])];
    return {parts[static_cast<std::size_t>(field.component)]};
  }
  *chosen = "|" + base + "|";
  return parts;
}

// TRI7 -> cubic: the TRI7 interpolant q + (u_c - q(c)) b (q the P2 part, b = 27 l0 l1 l2) at the
// cubic lattice points. On an edge the bubble vanishes: the points 1/3 and 2/3 along it depend on
// the edge's three nodes only, and are shared by the two cells (keyed by the edge's node ids).
class Tri7ToCubic {
public:
  explicit Tri7ToCubic(MeshInput &m) : m_(m) {}

  // nodes: TRI7 node ids from 0 (corners 0 1 2, midpoints 01 12 20, centroid).
  void add(const int64_t *n) {
    // Canonical lattice order of a cubic (poly/lattice.hpp), from the VTK order: corners, edge
    // 01 from 0, edge 12 from 1, edge 20 from 2, centre.
    std::array<int64_t, 10> vtk{};
    vtk[0] = n[0];
    vtk[1] = n[1];
    vtk[2] = n[2];
    const int edges[3][3] = {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};
    for (int e = 0; e < 3; ++e) {
      const int64_t a = n[edges[e][0]], b = n[edges[e][1]], mid = n[edges[e][2]];
      vtk[static_cast<std::size_t>(3 + 2 * e)] = edge_point(a, b, mid, 1);
      vtk[static_cast<std::size_t>(4 + 2 * e)] = edge_point(a, b, mid, 2);
    }
    // The centre: the centroid node itself (the cubic's centre is the centroid).
    vtk[9] = n[6];
    int64_t lattice[kMaxVtkCellNodes];
    int degree = 0;
    CellKind kind = CellKind::LagrangeTriangle;
    std::string problem;
    vtk_cell_nodes(69, vtk.data(), 10, static_cast<int64_t>(m_.points.size()), 0, lattice, &degree,
                   &kind, &problem);
    m_.add_cell(3, lattice);
  }

private:
  // The point k/3 of the way from a to b on the quadratic edge (a, mid, b).
  int64_t edge_point(int64_t a, int64_t b, int64_t mid, int k) {
    const bool flip = a > b;
    const auto key = std::make_tuple(std::min(a, b), std::max(a, b), flip ? 3 - k : k);
    if (auto it = made_.find(key); it != made_.end())
      return it->second;
    const double t = k / 3.0;
    const double wa = (1 - t) * (1 - 2 * t), wb = t * (2 * t - 1), wm = 4 * t * (1 - t);
    const auto at = [&](std::size_t i) { return m_.points[i]; };
    const Vec3 pa = at(static_cast<std::size_t>(a)), pb = at(static_cast<std::size_t>(b)),
               pm = at(static_cast<std::size_t>(mid));
    Vec3 p;
    for (int c = 0; c < 3; ++c)
      p[c] = wa * pa[c] + wb * pb[c] + wm * pm[c];
    const double v = wa * m_.values[static_cast<std::size_t>(a)] +
                     wb * m_.values[static_cast<std::size_t>(b)] +
                     wm * m_.values[static_cast<std::size_t>(mid)];
    const int64_t id = static_cast<int64_t>(m_.points.size());
    m_.points.push_back(p);
    m_.values.push_back(v);
    made_.emplace(key, id);
    return id;
  }

  MeshInput &m_;
  std::map<std::tuple<int64_t, int64_t, int>, int64_t> made_;
};

// The nodes no cell uses (a TRI7's edge midpoints, once its cubic nodes are made) are left out,
// the cells renumbered: every point of the mesh is a node of a cell.
void drop_unused_points(MeshInput &m) {
  std::vector<int64_t> index(m.points.size(), -1);
  for (int64_t n : m.cell_nodes)
    index[static_cast<std::size_t>(n)] = 0;
  int64_t kept = 0;
  for (int64_t &i : index)
    if (i == 0)
      i = kept++;
  if (kept == static_cast<int64_t>(m.points.size()))
    return;
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] >= 0) {
      m.points[static_cast<std::size_t>(index[i])] = m.points[i];
      m.values[static_cast<std::size_t>(index[i])] = m.values[i];
    }
  m.points.resize(static_cast<std::size_t>(kept));
  m.values.resize(static_cast<std::size_t>(kept));
  for (int64_t &n : m.cell_nodes)
    n = index[static_cast<std::size_t>(n)];
}

} // namespace

MeshInput read_exodus(const std::string &path, const FieldSelection &field,
                      const ReadLimits &limits, FileContents *contents) {
  const std::vector<ExodusBlock> declared = exodus_element_blocks(path); // extents checked
  ex_opts(0); // no messages on stderr: failures come back as statuses
  int cpu_word = 8, io_word = 0;
  float version = 0;
  ExodusFile f;
  f.id = ex_open(path.c_str(), EX_READ, &cpu_word, &io_word, &version);
  if (f.id < 0)
    throw InputError(path + ": the Exodus library cannot open it");
  ex_init_params init{};
  check(ex_get_init_ext(f.id, &init), path, "header");
  const int64_t nodes = init.num_nodes;
  if (nodes <= 0 || init.num_elem_blk <= 0)
    throw InputError(path + ": no nodes or no element blocks");
  if (init.num_dim < 1 || init.num_dim > 3)
    throw InputError(path + ": " + std::to_string(init.num_dim) + " dimensions");

  // Nodal variables and time steps.
  int nvars = 0;
  check(ex_get_variable_param(f.id, EX_NODAL, &nvars), path, "nodal variables");
  std::vector<std::string> names;
  if (nvars > 0) {
    const int len = static_cast<int>(ex_inquire_int(f.id, EX_INQ_MAX_READ_NAME_LENGTH));
    std::vector<std::vector<char>> buf(static_cast<std::size_t>(nvars),
                                       std::vector<char>(static_cast<std::size_t>(len) + 1, 0));
    std::vector<char *> ptr;
    for (auto &b : buf)
      ptr.push_back(b.data());
    check(ex_get_variable_names(f.id, EX_NODAL, nvars, ptr.data()), path, "variable names");
    for (auto &b : buf)
      names.emplace_back(b.data());
  }
  const int64_t nsteps = ex_inquire_int(f.id, EX_INQ_TIME);
  std::vector<double> times(static_cast<std::size_t>(std::max<int64_t>(nsteps, 0)));
  if (nsteps > 0)
    check(ex_get_all_times(f.id, times.data()), path, "times");
  if (contents)
    for (const std::string &n : names) {
      FileField ff;
      ff.name = n;
      ff.kind = "nodal variable";
      for (std::size_t k = 0; k < times.size(); ++k)
        ff.steps.push_back({static_cast<int64_t>(k + 1), times[k]});
      contents->fields.push_back(std::move(ff));
    }
  std::string chosen;
  const std::vector<int> vars = chosen_variables(path, names, field, &chosen);
  if (nsteps <= 0)
    throw InputError(path + ": nodal variable '" + chosen + "' has no time step written");
  std::size_t step = times.size() - 1;
  std::string detail;
  if (times.size() > 1 || !field.default_step()) {
    step = choose_step(path, {times.begin(), times.end()}, field, "the file");
    if (times.size() > 1)
      detail = "(" + step_description(step, times.size(), times[step]) + ")";
  }

  // Count what the blocks hold before allocating it.
  int64_t cells = 0, conn = 0;
  for (const ExodusBlock &b : declared) {
    cells += b.elements;
    conn += b.elements * b.nodes_per_element;
  }
  check_memory(limits, static_cast<uint64_t>(nodes) * 2, static_cast<uint64_t>(cells),
               static_cast<uint64_t>(conn) * 2, path);

  MeshInput m;
  m.source = path;
  m.field_name = chosen;
  m.field_detail = detail;
  std::vector<double> x(static_cast<std::size_t>(nodes), 0), y(x), z(x);
  check(ex_get_coord(f.id, x.data(), init.num_dim > 1 ? y.data() : nullptr,
                     init.num_dim > 2 ? z.data() : nullptr),
        path, "coordinates");
  m.points.resize(static_cast<std::size_t>(nodes));
  for (int64_t i = 0; i < nodes; ++i)
    m.points[static_cast<std::size_t>(i)] = {x[static_cast<std::size_t>(i)],
                                             y[static_cast<std::size_t>(i)],
                                             z[static_cast<std::size_t>(i)]};
  m.values.assign(static_cast<std::size_t>(nodes), 0.0);
  std::vector<double> part(static_cast<std::size_t>(nodes));
  for (int v : vars) {
    check(ex_get_var(f.id, static_cast<int>(step) + 1, EX_NODAL, v + 1, 1, nodes, part.data()),
          path,
          "variable '" + names[static_cast<std::size_t>(v)] + "' at step " + std::to_string(step));
    for (std::size_t i = 0; i < part.size(); ++i)
      m.values[i] += vars.size() == 1 ? part[i] : part[i] * part[i];
  }
  if (vars.size() > 1)
    for (double &v : m.values)
      v = std::sqrt(v);

  std::vector<ex_entity_id> ids(static_cast<std::size_t>(init.num_elem_blk));
  check(ex_get_ids(f.id, EX_ELEM_BLOCK, ids.data()), path, "block ids");
  Tri7ToCubic tri7(m);
  std::vector<int> node_ids;
  for (std::size_t bi = 0; bi < ids.size(); ++bi) {
    ex_block block{};
    block.id = ids[bi];
    block.type = EX_ELEM_BLOCK;
    check(ex_get_block_param(f.id, &block), path, "element block " + std::to_string(ids[bi]));
    const std::string where = path + ": element block " + std::to_string(ids[bi]) + " ('" +
                              block.topology + "', " + std::to_string(block.num_entry) +
                              " elements)";
    if (block.num_entry == 0)
      continue;
    const std::string type = upper(block.topology);
    const int64_t k = block.num_nodes_per_entry;
    // Point and line blocks (boundary markers some meshers add) have no area: skipped, as the
    // VTK readers skip vertex and line cells.
    if (type.rfind("BAR", 0) == 0 || type.rfind("BEAM", 0) == 0 || type.rfind("TRUSS", 0) == 0 ||
        type.rfind("EDGE", 0) == 0 || type.rfind("SPHERE", 0) == 0 || type.rfind("CIRCLE", 0) == 0)
      continue;
    // Exodus numbers TRI3/TRI6 and QUAD4/QUAD8/QUAD9 nodes as VTK does its types 5, 22, 9, 23
    // and 28 (corners, then edge midpoints from edge 1-2 on, then the centre).
    const bool triangle = type.rfind("TRI", 0) == 0;
    const bool quad = type.rfind("QUAD", 0) == 0 || type.rfind("SHELL", 0) == 0;
    if (!(triangle && (k == 3 || k == 6 || k == 7)) && !(quad && (k == 4 || k == 8 || k == 9)))
      throw InputError(where + ": not triangles of 3, 6 or 7 nodes or quadrilaterals of 4, 8 or " +
                       "9 nodes (" + std::to_string(k) + " nodes per element)");
    const int vtk_type = triangle ? (k == 3 ? 5 : 22) : (k == 4 ? 9 : (k == 8 ? 23 : 28));
    node_ids.assign(static_cast<std::size_t>(block.num_entry * k), 0);
    check(ex_get_conn(f.id, EX_ELEM_BLOCK, ids[bi], node_ids.data(), nullptr, nullptr), where,
          "connectivity");
    int64_t cell[9];
    for (int64_t e = 0; e < block.num_entry; ++e) {
      for (int64_t j = 0; j < k; ++j) {
        const int64_t id = node_ids[static_cast<std::size_t>(e * k + j)] - 1;
        if (id < 0 || id >= nodes)
          throw InputError(where + ": element " + std::to_string(e + 1) + " names node " +
                           std::to_string(id + 1) + " (the file has " + std::to_string(nodes) +
                           ")");
        cell[j] = id;
      }
      if (k == 7) {
        tri7.add(cell);
        continue;
      }
      std::string problem;
      if (add_vtk_cell(m, vtk_type, cell, k, nodes, 0, &problem) != VtkCellResult::Added)
        throw InputError(where + ": element " + std::to_string(e + 1) + problem);
    }
  }
  if (m.num_cells() == 0)
    throw InputError(path + ": no triangle or quadrilateral elements in its " +
                     std::to_string(ids.size()) + " element block(s)");
  drop_unused_points(m);
  return m;
}

} // namespace hoct
