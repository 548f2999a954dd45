// `hoct compare A.json B.json`: bottleneck distances between two trees' persistence diagrams
// and their node counts by type.
#include "commands.hpp"
#include "io/tree_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

namespace hoct::cli {
namespace {

struct CompareOptions {
  std::string a, b;
  bool json = false;
};

void run_compare(const CompareOptions &o) {
  const TreeResult a = read_tree_json(o.a), b = read_tree_json(o.b);
  const PersistencePair::Kind kinds[4] = {PersistencePair::Kind::Join, PersistencePair::Kind::Split,
                                          PersistencePair::Kind::Global,
                                          PersistencePair::Kind::Loop};
  double dist[4], overall = 0;
  for (int i = 0; i < 4; ++i) {
    dist[i] = bottleneck_distance(pair_points(a.pairs, kinds[i]), pair_points(b.pairs, kinds[i]));
    overall = std::max(overall, dist[i]);
  }
  const auto ca = a.type_counts(), cb = b.type_counts();
  if (o.json) {
    nlohmann::ordered_json j;
    j["a"] = o.a;
    j["b"] = o.b;
    j["bottleneck"] = {{"join", dist[0]},
                       {"split", dist[1]},
                       {"global", dist[2]},
                       {"loop", dist[3]},
                       {"max", overall}};
    const char *names[4] = {"minimum", "maximum", "saddle", "regular"};
    for (int i = 0; i < 4; ++i)
      j["counts"][names[i]] = {ca[i], cb[i]};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("%-22s %14s %14s\n", "", "A", "B");
  std::printf("%-22s %14s %14s\n", "method", a.method.c_str(), b.method.c_str());
  const char *names[4] = {"minima", "maxima", "saddles", "regular"};
  for (int i = 0; i < 4; ++i)
    std::printf("%-22s %14lld %14lld\n", names[i], static_cast<long long>(ca[i]),
                static_cast<long long>(cb[i]));
  std::printf("%-22s %14zu %14zu\n", "pairs", a.pairs.size(), b.pairs.size());
  std::printf("bottleneck distance: join %.6g, split %.6g, global %.6g, loop %.6g, max %.6g\n",
              dist[0], dist[1], dist[2], dist[3], overall);
}

} // namespace

void register_compare(CLI::App &app) {
  auto o = std::make_shared<CompareOptions>();
  auto *sub = app.add_subcommand("compare", "Compare two trees (JSON from hoct tree): bottleneck "
                                            "distances of their persistence diagrams, node counts");
  sub->add_option("a", o->a, "First tree (.json)")->required();
  sub->add_option("b", o->b, "Second tree (.json)")->required();
  sub->add_flag("--json", o->json, "Print JSON");
  sub->callback([o] { run_compare(*o); });
}

} // namespace hoct::cli
