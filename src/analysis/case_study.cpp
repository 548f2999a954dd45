#include "analysis/case_study.hpp"

#include "exact/exact_contour_tree.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/refinement.hpp"
#include "util/stopwatch.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {
namespace {

double distance(const Vec3 &a, const Vec3 &b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// Extrema whose branch persistence is at least `threshold`.
std::vector<int64_t> features(const TreeResult &t, double threshold) {
  std::vector<double> pers(t.nodes.size(), 0.0);
  for (const auto &p : t.pairs) {
    pers[p.birth] = std::max(pers[p.birth], p.persistence());
    pers[p.death] = std::max(pers[p.death], p.persistence());
  }
  std::vector<int64_t> f;
  for (std::size_t i = 0; i < t.nodes.size(); ++i)
    if ((t.nodes[i].type == NodeType::Minimum || t.nodes[i].type == NodeType::Maximum) &&
        pers[i] >= threshold)
      f.push_back(static_cast<int64_t>(i));
  return f;
}

} // namespace

std::vector<StudyRow> case_study(const Mesh &mesh, const StudyOptions &opt) {
  std::vector<StudyRow> rows;
  const double radius = opt.match_radius > 0 ? opt.match_radius : 0.05 * mesh.geometry.extent();
  ExactTreeOptions eo;
  eo.threads = opt.threads;
  Stopwatch clock;
  // Flat regions contracted in both trees, as `hoct tree` reports them.
  const TreeResult exact = contract_flat(exact_contour_tree(mesh, eo));
  StudyRow er;
  er.triangles = mesh.topology.num_cells();
  er.seconds = clock.lap();
  const auto ec = exact.type_counts();
  er.counts = {ec[0], ec[1], ec[2]};
  rows.push_back(er);
  const std::vector<int64_t> exact_features = features(exact, opt.feature_threshold);
  for (int k : opt.levels) {
    StudyRow r;
    r.k = k;
    clock.lap();
    const PlMesh pl = refine(mesh, k);
    const TreeResult t = contract_flat(pl_contour_tree(pl, false, ""));
    r.seconds = clock.lap();
    r.triangles = static_cast<int64_t>(pl.triangles.size());
    const auto c = t.type_counts();
    r.counts = {c[0], c[1], c[2]};
    for (auto kind :
         {PersistencePair::Kind::Join, PersistencePair::Kind::Split, PersistencePair::Kind::Global})
      r.bottleneck = std::max(r.bottleneck, bottleneck_distance(pair_points(exact.pairs, kind),
                                                                pair_points(t.pairs, kind)));
    // Nearest PL critical point of the same type for every exact one.
    double sum = 0;
    int64_t n = 0;
    for (const auto &e : exact.nodes) {
      double best = INFINITY;
      for (const auto &p : t.nodes)
        if (p.type == e.type)
          best = std::min(best, distance(e.position, p.position));
      if (std::isfinite(best)) {
        sum += best;
        r.max_distance = std::max(r.max_distance, best);
        ++n;
      }
    }
    r.mean_distance = n ? sum / n : 0;
    // Features: greedy one-to-one matching of same-type extrema within the radius, nearest first.
    const std::vector<int64_t> pl_features = features(t, opt.feature_threshold);
    std::vector<std::tuple<double, int64_t, int64_t>> candidates;
    for (int64_t a : exact_features)
      for (int64_t b : pl_features)
        if (exact.nodes[a].type == t.nodes[b].type) {
          const double d = distance(exact.nodes[a].position, t.nodes[b].position);
          if (d <= radius)
            candidates.push_back({d, a, b});
        }
    std::sort(candidates.begin(), candidates.end());
    std::vector<char> used_a(exact.nodes.size(), 0), used_b(t.nodes.size(), 0);
    int64_t matched = 0;
    for (const auto &[d, a, b] : candidates)
      if (!used_a[a] && !used_b[b]) {
        used_a[a] = used_b[b] = 1;
        ++matched;
      }
    r.missed = static_cast<int64_t>(exact_features.size()) - matched;
    r.spurious = static_cast<int64_t>(pl_features.size()) - matched;
    rows.push_back(r);
  }
  return rows;
}

} // namespace hoct
