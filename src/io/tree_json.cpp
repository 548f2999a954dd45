#include "io/tree_json.hpp"

#include "error.hpp"
#include "io/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace hoct {
namespace {

using json = nlohmann::ordered_json;

json to_json(const TreeResult &t) {
  json j;
  j["format"] = "hoct-contour-tree";
  j["version"] = 1;
  j["method"] = t.method;
  j["augmented"] = t.augmented;
  if (!t.forced.empty()) {
    j["forced"] = true;
    j["forced_reasons"] = t.forced;
  }
  json nodes = json::array();
  std::map<std::string, int64_t> by_type, by_location;
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const TreeNode &n = t.nodes[i];
    nodes.push_back({{"id", i},
                     {"type", to_string(n.type)},
                     {"value", n.value},
                     {"position", n.position},
                     {"cell", n.cell},
                     {"uv", n.uv},
                     {"location", to_string(n.location)},
                     {"fallback", n.fallback}});
    if (n.merged > 1)
      nodes.back()["merged"] = n.merged;
    ++by_type[to_string(n.type)];
    ++by_location[to_string(n.location)];
  }
  j["nodes"] = std::move(nodes);
  json arcs = json::array();
  for (const auto &a : t.arcs)
    arcs.push_back({a[0], a[1]});
  j["arcs"] = std::move(arcs);
  json pairs = json::array();
  for (const auto &p : t.pairs)
    pairs.push_back({{"birth", p.birth},
                     {"death", p.death},
                     {"persistence", p.persistence()},
                     {"kind", to_string(p.kind)}});
  j["pairs"] = std::move(pairs);
  json branches = json::array();
  for (std::size_t b = 0; b < t.branches.size(); ++b) {
    const Branch &br = t.branches[b];
    branches.push_back({{"id", b},
                        {"extremum", br.extremum},
                        {"saddle", br.saddle},
                        {"persistence", br.persistence},
                        {"parent", br.parent},
                        {"depth", br.depth}});
  }
  j["branches"] = std::move(branches);
  json stats;
  stats["nodes"] = t.nodes.size();
  stats["arcs"] = t.arcs.size();
  stats["nodes_by_type"] = by_type;
  stats["nodes_by_location"] = by_location;
  for (const auto &[k, v] : t.stats)
    stats[k] = v;
  j["stats"] = std::move(stats);
  return j;
}

NodeType parse_type(const std::string &s) {
  if (s == "minimum")
    return NodeType::Minimum;
  if (s == "maximum")
    return NodeType::Maximum;
  if (s == "saddle")
    return NodeType::Saddle;
  if (s == "regular")
    return NodeType::Regular;
  throw std::invalid_argument("unknown node type '" + s + "'");
}

NodeLocation parse_location(const std::string &s) {
  for (auto l :
       {NodeLocation::Vertex, NodeLocation::Edge, NodeLocation::Interior, NodeLocation::Unknown})
    if (s == to_string(l))
      return l;
  throw std::invalid_argument("unknown node location '" + s + "'");
}

PersistencePair::Kind parse_kind(const std::string &s) {
  for (auto k :
       {PersistencePair::Kind::Join, PersistencePair::Kind::Split, PersistencePair::Kind::Global})
    if (s == to_string(k))
      return k;
  throw std::invalid_argument("unknown pair kind '" + s + "'");
}

} // namespace

std::string tree_to_json(const TreeResult &tree, int indent) { return to_json(tree).dump(indent); }

void write_tree_json(const std::string &path, const TreeResult &tree) {
  const std::string text = tree_to_json(tree);
  write_file_atomic(
      path, [&](std::ostream &out) { out << text << "\n"; }, false);
}

TreeResult read_tree_json(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error &e) {
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
  try {
    if (!j.is_object() || j.value("format", "") != "hoct-contour-tree")
      throw std::invalid_argument("not a hoct contour-tree file (missing \"format\": "
                                  "\"hoct-contour-tree\")");
    TreeResult t;
    t.method = j.value("method", "");
    t.augmented = j.value("augmented", false);
    if (j.value("forced", false))
      t.forced = j.value("forced_reasons", std::vector<std::string>{"forced"});
    const auto &nodes = j.at("nodes");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto &n = nodes.at(i);
      if (n.at("id").get<int64_t>() != static_cast<int64_t>(i))
        throw std::invalid_argument("node " + std::to_string(i) + " has id " + n.at("id").dump() +
                                    " (ids must be 0, 1, 2, ...)");
      TreeNode node;
      node.type = parse_type(n.at("type").get<std::string>());
      node.value = n.at("value").get<double>();
      if (!std::isfinite(node.value))
        throw std::invalid_argument("node " + std::to_string(i) + " has a non-finite value");
      node.position = n.at("position").get<Vec3>();
      node.cell = n.value("cell", int64_t{-1});
      if (n.contains("uv"))
        node.uv = n.at("uv").get<std::array<double, 2>>();
      node.location = parse_location(n.value("location", std::string("unknown")));
      node.fallback = n.value("fallback", false);
      node.merged = n.value("merged", int64_t{1});
      if (node.merged < 1)
        throw std::invalid_argument("node " + std::to_string(i) + " has \"merged\" < 1");
      t.nodes.push_back(node);
    }
    const int64_t nn = static_cast<int64_t>(t.nodes.size());
    auto check_id = [&](int64_t id, const std::string &what) {
      if (id < 0 || id >= nn)
        throw std::invalid_argument(what + " refers to node " + std::to_string(id) +
                                    ", but there are " + std::to_string(nn) + " nodes");
      return id;
    };
    for (const auto &a : j.at("arcs")) {
      auto ab = a.get<std::array<int64_t, 2>>();
      check_id(ab[0], "an arc");
      check_id(ab[1], "an arc");
      if (ab[0] > ab[1])
        std::swap(ab[0], ab[1]);
      t.arcs.push_back(ab);
      ++t.nodes[ab[0]].up;
      ++t.nodes[ab[1]].down;
    }
    for (const auto &p : j.at("pairs")) {
      PersistencePair pair;
      pair.kind = parse_kind(p.value("kind", std::string("global")));
      pair.birth = check_id(p.at("birth").get<int64_t>(), "a pair");
      pair.death = check_id(p.at("death").get<int64_t>(), "a pair");
      pair.birth_value = t.nodes[pair.birth].value;
      pair.death_value = t.nodes[pair.death].value;
      t.pairs.push_back(pair);
    }
    if (j.contains("branches"))
      for (const auto &b : j.at("branches")) {
        Branch br;
        br.extremum = check_id(b.at("extremum").get<int64_t>(), "a branch");
        br.saddle = check_id(b.at("saddle").get<int64_t>(), "a branch");
        br.persistence = b.at("persistence").get<double>();
        br.parent = b.at("parent").get<int64_t>();
        br.depth = b.value("depth", 0);
        t.branches.push_back(br);
      }
    if (j.contains("stats"))
      for (const auto &[k, v] : j.at("stats").items())
        if (v.is_number())
          t.stats.emplace_back(k, v.get<double>());
    return t;
  } catch (const json::exception &e) {
    throw InputError(path + ": malformed contour-tree file: " + e.what());
  } catch (const std::invalid_argument &e) {
    throw InputError(path + ": malformed contour-tree file: " + e.what());
  }
}

} // namespace hoct
