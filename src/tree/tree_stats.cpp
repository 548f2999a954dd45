#include "tree/tree_stats.hpp"

#include <functional>

namespace hoct {

const char *stat_name(FallbackReason r) {
  static constexpr const char *kNames[kFallbackReasons] = {
      "fallback_constant_cell",       "fallback_critical_curve",  "fallback_uncertified_zero",
      "fallback_zero_near_boundary",  "fallback_degenerate_edge", "fallback_degenerate_edge_node",
      "fallback_certification_failed"};
  return kNames[static_cast<int>(r)];
}

namespace {

// One table for both directions: each entry's name and where it lives in TreeStats.
struct Entry {
  const char *name;
  std::function<std::optional<double>(const TreeStats &)> get;
  std::function<void(TreeStats &, double)> set;
};

template <class T> std::optional<double> opt(const std::optional<T> &v) {
  return v ? std::optional<double>(static_cast<double>(*v)) : std::nullopt;
}

template <class T> Entry exact_entry(const char *name, T ExactCounts::*field) {
  return {name,
          [field](const TreeStats &s) {
            return s.exact ? std::optional<double>(static_cast<double>((*s.exact).*field))
                           : std::nullopt;
          },
          [field](TreeStats &s, double v) {
            if (!s.exact)
              s.exact.emplace();
            (*s.exact).*field = static_cast<T>(v);
          }};
}

Entry reason_entry(FallbackReason r) {
  const int i = static_cast<int>(r);
  return {stat_name(r),
          [i](const TreeStats &s) {
            return s.exact
                       ? std::optional<double>(static_cast<double>(s.exact->fallback_by_reason[i]))
                       : std::nullopt;
          },
          [i](TreeStats &s, double v) {
            if (!s.exact)
              s.exact.emplace();
            s.exact->fallback_by_reason[i] = static_cast<int64_t>(v);
          }};
}

Entry pl_entry(const char *name, int64_t PlCounts::*field) {
  return {name,
          [field](const TreeStats &s) {
            return s.pl ? std::optional<double>(static_cast<double>((*s.pl).*field)) : std::nullopt;
          },
          [field](TreeStats &s, double v) {
            if (!s.pl)
              s.pl.emplace();
            (*s.pl).*field = static_cast<int64_t>(v);
          }};
}

template <class T> Entry plain_entry(const char *name, std::optional<T> TreeStats::*field) {
  return {name, [field](const TreeStats &s) { return opt(s.*field); },
          [field](TreeStats &s, double v) { s.*field = static_cast<T>(v); }};
}

Entry time_entry(const char *name, std::optional<double> TreeTimings::*field) {
  return {name, [field](const TreeStats &s) { return s.time.*field; },
          [field](TreeStats &s, double v) { s.time.*field = v; }};
}

const std::vector<Entry> &table() {
  static const std::vector<Entry> t = [] {
    std::vector<Entry> e = {
        exact_entry("cells", &ExactCounts::cells),
        exact_entry("graph_nodes", &ExactCounts::graph_nodes),
        exact_entry("edge_critical_points", &ExactCounts::edge_critical_points),
        exact_entry("level_edges", &ExactCounts::level_edges),
        exact_entry("interior_critical_points", &ExactCounts::interior_critical_points),
        exact_entry("connections_direct", &ExactCounts::connections_direct),
        exact_entry("connections_traced", &ExactCounts::connections_traced),
        exact_entry("connections_failed", &ExactCounts::connections_failed),
        exact_entry("descent_steps", &ExactCounts::descent_steps),
        exact_entry("fallback_cells", &ExactCounts::fallback_cells)};
    for (int r = 0; r < kFallbackReasons; ++r)
      e.push_back(reason_entry(static_cast<FallbackReason>(r)));
    e.push_back(exact_entry("fallback_error", &ExactCounts::fallback_error));
    e.push_back(exact_entry("fallback_arcs_contracted", &ExactCounts::fallback_arcs_contracted));
    e.push_back(exact_entry("unresolved_interior_zeros", &ExactCounts::unresolved_interior_zeros));
    e.push_back(exact_entry("degenerate_points", &ExactCounts::degenerate_points));
    e.push_back(exact_entry("critical_corners", &ExactCounts::critical_corners));
    e.push_back(exact_entry("critical_curves", &ExactCounts::critical_curves));
    e.push_back(exact_entry("degenerate_slack", &ExactCounts::degenerate_slack));
    e.push_back(pl_entry("pl_vertices", &PlCounts::vertices));
    e.push_back(pl_entry("pl_triangles", &PlCounts::triangles));
    e.push_back(plain_entry("input_cells", &TreeStats::input_cells));
    e.push_back(plain_entry("flat_nodes_merged", &TreeStats::flat_nodes_merged));
    e.push_back(
        plain_entry("nodes_before_simplification", &TreeStats::nodes_before_simplification));
    e.push_back(plain_entry("simplification_threshold", &TreeStats::simplification_threshold));
    e.push_back(plain_entry("loops_removed", &TreeStats::loops_removed));
    e.push_back(plain_entry("precision", &TreeStats::precision));
    e.push_back(plain_entry("pairs_below_precision", &TreeStats::pairs_below_precision));
    e.push_back(
        plain_entry("pairs_within_fallback_slack", &TreeStats::pairs_within_fallback_slack));
    e.push_back(
        plain_entry("pairs_within_degenerate_slack", &TreeStats::pairs_within_degenerate_slack));
    e.push_back(plain_entry("seam_edges", &TreeStats::seam_edges));
    e.push_back(plain_entry("seam_paths_nonmonotone", &TreeStats::seam_paths_nonmonotone));
    // The phases in the order they run.
    e.push_back(time_entry("time_read_s", &TreeTimings::read));
    e.push_back(time_entry("time_check_s", &TreeTimings::check));
    e.push_back(time_entry("time_cell_split_s", &TreeTimings::cell_split));
    e.push_back(time_entry("time_topology_s", &TreeTimings::topology));
    e.push_back(time_entry("time_geometry_s", &TreeTimings::geometry));
    e.push_back(time_entry("time_bernstein_s", &TreeTimings::bernstein));
    e.push_back(time_entry("time_geometry_checks_s", &TreeTimings::geometry_checks));
    e.push_back(time_entry("time_cut_s", &TreeTimings::cut));
    e.push_back(time_entry("time_pl_mesh_s", &TreeTimings::pl_mesh));
    e.push_back(time_entry("time_edge_nodes_s", &TreeTimings::edge_nodes));
    e.push_back(time_entry("time_cells_s", &TreeTimings::cells));
    e.push_back(
        time_entry("time_interior_critical_points_s", &TreeTimings::interior_critical_points));
    e.push_back(time_entry("time_connections_s", &TreeTimings::connections));
    e.push_back(time_entry("time_graph_assembly_s", &TreeTimings::graph_assembly));
    e.push_back(time_entry("time_graph_s", &TreeTimings::graph));
    e.push_back(time_entry("time_sweeps_s", &TreeTimings::sweeps));
    e.push_back(time_entry("time_merge_s", &TreeTimings::merge));
    e.push_back(time_entry("time_gluing_s", &TreeTimings::gluing));
    e.push_back(time_entry("time_pairs_s", &TreeTimings::pairs));
    e.push_back(time_entry("time_output_s", &TreeTimings::output));
    e.push_back(time_entry("time_tree_s", &TreeTimings::tree));
    e.push_back(time_entry("time_branches_s", &TreeTimings::branches));
    e.push_back(time_entry("time_arc_paths_s", &TreeTimings::arc_paths));
    return e;
  }();
  return t;
}

// The timings, and the size of a Reeb graph's cut: how the run went, not what it found (one
// process and the pieces of a partitioned mesh cut the surface differently).
bool is_timing(const std::string &name) {
  return name.rfind("time_", 0) == 0 || name == "seam_edges";
}

} // namespace

std::vector<std::pair<std::string, double>> TreeStats::entries(bool timings) const {
  std::vector<std::pair<std::string, double>> out;
  for (const Entry &e : table())
    if (timings || !is_timing(e.name))
      if (const auto v = e.get(*this))
        out.emplace_back(e.name, *v);
  for (const auto &[name, v] : other)
    if (timings || !is_timing(name))
      out.emplace_back(name, v);
  return out;
}

TreeStats TreeStats::from_entries(const std::vector<std::pair<std::string, double>> &entries) {
  TreeStats s;
  for (const auto &[name, v] : entries) {
    bool known = false;
    for (const Entry &e : table())
      if (name == e.name) {
        e.set(s, v);
        known = true;
        break;
      }
    if (!known)
      s.other.emplace_back(name, v);
  }
  return s;
}

} // namespace hoct
