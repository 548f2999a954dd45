#include "io/tree_json.hpp"

#include "io/atomic_file.hpp"
#include "util/error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace hoct {
namespace {

using json = nlohmann::ordered_json;

// The document, written as it is built: the header's fields and "stats" as nlohmann's
// indented dump, and each element of the four arrays (a node, an arc, a pair, a branch) compact
// on a line of its own, which reads and greps well, and is smaller and quicker to write than the
// whole document dumped with one value per line.
class TreeJsonWriter {
public:
  void field(const std::string &key, const json &value) {
    open_field(key);
    out_ += value.dump(1);
    indent_nested();
  }
  // An array whose element i is element(i), one per line.
  template <class Element> void array(const std::string &key, std::size_t n, Element element) {
    open_field(key);
    if (n == 0) {
      out_ += "[]";
      return;
    }
    out_ += "[\n";
    for (std::size_t i = 0; i < n; ++i) {
      out_ += "  ";
      out_ += element(i).dump();
      out_ += i + 1 < n ? ",\n" : "\n";
    }
    out_ += " ]";
  }
  std::string finish() {
    out_ += "\n}";
    return std::move(out_);
  }

private:
  void open_field(const std::string &key) {
    out_ += out_.empty() ? "{\n " : ",\n ";
    out_ += json(key).dump();
    out_ += ": ";
    field_start_ = out_.size();
  }
  // A nested value's own lines one level deeper (nlohmann indents from column 0).
  void indent_nested() {
    std::string shifted;
    for (std::size_t i = field_start_; i < out_.size(); ++i) {
      shifted += out_[i];
      if (out_[i] == '\n')
        shifted += ' ';
    }
    out_.replace(field_start_, std::string::npos, shifted);
  }

  std::string out_;
  std::size_t field_start_ = 0;
};

std::string to_json_text(const TreeResult &t, bool timings) {
  TreeJsonWriter w;
  w.field("format", "hoct-contour-tree");
  w.field("version", 1);
  w.field("method", t.method);
  w.field("augmented", t.augmented);
  if (t.input)
    w.field("input", {{"points", t.input->points},
                      {"cells", t.input->cells},
                      {"field", t.input->field},
                      {"fingerprint", t.input->hex()}});
  // A Reeb graph (a domain that is not a disk or a sphere) with its loops, or a contour tree.
  w.field("kind", t.reeb_graph ? "Reeb graph" : "contour tree");
  w.field("loops", t.loops);
  if (!t.forced.empty()) {
    w.field("forced", true);
    w.field("forced_reasons", t.forced);
  }
  // One object per kind of element, its fields overwritten for each (building each element
  // anew would allocate its keys and arrays every time).
  std::map<std::string, int64_t> by_type, by_location;
  json node = {{"id", 0},   {"type", ""},       {"value", 0.0},   {"position", {0.0, 0.0, 0.0}},
               {"cell", 0}, {"uv", {0.0, 0.0}}, {"location", ""}, {"fallback", false}};
  json merged_node = node;
  merged_node["merged"] = 0;
  w.array("nodes", t.nodes.size(), [&](std::size_t i) -> const json & {
    const TreeNode &n = t.nodes[i];
    json &o = n.merged > 1 ? merged_node : node;
    o["id"] = i;
    o["type"] = to_string(n.type);
    o["value"] = n.value;
    for (int k = 0; k < 3; ++k)
      o["position"][k] = n.position[k];
    o["cell"] = n.cell;
    o["uv"][0] = n.uv[0];
    o["uv"][1] = n.uv[1];
    o["location"] = to_string(n.location);
    o["fallback"] = n.fallback;
    if (n.merged > 1)
      o["merged"] = n.merged;
    ++by_type[to_string(n.type)];
    ++by_location[to_string(n.location)];
    return o;
  });
  json arc = {0, 0};
  w.array("arcs", t.arcs.size(), [&](std::size_t i) -> const json & {
    arc[0] = t.arcs[i][0];
    arc[1] = t.arcs[i][1];
    return arc;
  });
  // A pair at or below the input's precision, or within the fallback stand-in's slack, says so
  // ("uncertain": true).
  json pair = {{"birth", 0}, {"death", 0}, {"persistence", 0.0}, {"kind", ""}};
  json uncertain_pair = pair;
  uncertain_pair["uncertain"] = true;
  w.array("pairs", t.pairs.size(), [&](std::size_t i) -> const json & {
    const PersistencePair &p = t.pairs[i];
    json &o = t.uncertain(p) ? uncertain_pair : pair;
    o["birth"] = p.birth;
    o["death"] = p.death;
    o["persistence"] = p.persistence();
    o["kind"] = to_string(p.kind);
    return o;
  });
  json branch = {{"id", 0},     {"extremum", 0}, {"saddle", 0}, {"persistence", 0.0},
                 {"parent", 0}, {"depth", 0}};
  w.array("branches", t.branches.size(), [&](std::size_t b) -> const json & {
    const Branch &br = t.branches[b];
    branch["id"] = b;
    branch["extremum"] = br.extremum;
    branch["saddle"] = br.saddle;
    branch["persistence"] = br.persistence;
    branch["parent"] = br.parent;
    branch["depth"] = br.depth;
    return branch;
  });
  json stats;
  stats["nodes"] = t.nodes.size();
  stats["arcs"] = t.arcs.size();
  stats["nodes_by_type"] = by_type;
  stats["nodes_by_location"] = by_location;
  for (const auto &[k, v] : t.stats.entries(timings))
    stats[k] = v;
  w.field("stats", stats);
  return w.finish();
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
  for (auto k : {PersistencePair::Kind::Join, PersistencePair::Kind::Split,
                 PersistencePair::Kind::Global, PersistencePair::Kind::Loop})
    if (s == to_string(k))
      return k;
  throw std::invalid_argument("unknown pair kind '" + s + "'");
}

} // namespace

std::string tree_to_json(const TreeResult &tree, bool timings) {
  return to_json_text(tree, timings);
}

void write_tree_json(const std::string &path, const TreeResult &tree, bool timings) {
  const std::string text = tree_to_json(tree, timings);
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
    const std::string kind = j.value("kind", std::string("contour tree"));
    if (kind != "contour tree" && kind != "Reeb graph")
      throw std::invalid_argument("\"kind\" must be \"contour tree\" or \"Reeb graph\", got " +
                                  j.at("kind").dump());
    t.reeb_graph = kind == "Reeb graph";
    t.loops = j.value("loops", int64_t{0});
    if (j.contains("input")) {
      const auto &in = j.at("input");
      InputFingerprint f;
      f.points = in.at("points").get<int64_t>();
      f.cells = in.at("cells").get<int64_t>();
      f.field = in.value("field", std::string());
      const auto hash = InputFingerprint::parse_hex(in.at("fingerprint").get<std::string>());
      if (!hash)
        throw std::invalid_argument("\"input\": \"fingerprint\" must be 16 hexadecimal digits, "
                                    "got " +
                                    in.at("fingerprint").dump());
      f.hash = *hash;
      t.input = f;
    }
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
      if (p.contains("persistence"))
        t.recorded_persistence.push_back(p.at("persistence").get<double>());
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
    if (j.contains("stats")) {
      std::vector<std::pair<std::string, double>> entries;
      for (const auto &[k, v] : j.at("stats").items())
        if (v.is_number() && k != "nodes" && k != "arcs")
          entries.emplace_back(k, v.get<double>());
      t.stats = TreeStats::from_entries(entries);
    }
    return t;
  } catch (const json::exception &e) {
    throw InputError(path + ": malformed contour-tree file: " + e.what());
  } catch (const std::invalid_argument &e) {
    throw InputError(path + ": malformed contour-tree file: " + e.what());
  }
}

} // namespace hoct
