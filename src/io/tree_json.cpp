#include "io/tree_json.hpp"

#include "io/atomic_file.hpp"
#include "io/json_numbers.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
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
  // Into a string (`sink` null; `bytes`: about what the document will take, reserved at once,
  // as growing a string of hundreds of megabytes by doubling copies it), or streamed to `sink`
  // a megabyte at a time (a file never needs the whole text in memory).
  TreeJsonWriter(std::size_t bytes, std::ostream *sink, int threads)
      : sink_(sink), threads_(threads) {
    out_.reserve(sink ? kChunk + 4096 : bytes);
  }
  void field(const std::string &key, const json &value) {
    open_field(key);
    out_ += value.dump(1);
    indent_nested();
  }
  // An array whose element i is written by element(out, i) (compact JSON), one per line. Long
  // arrays are formatted in blocks on `threads` threads (each block into its own string, the
  // blocks appended in order: the same text for any thread count); `element` must then be safe
  // to call concurrently.
  template <class Element> void array(const std::string &key, std::size_t n, Element element) {
    open_field(key);
    if (n == 0) {
      out_ += "[]";
      return;
    }
    out_ += "[\n";
    const auto line = [&](std::string &o, std::size_t i) {
      o += "  ";
      element(o, i);
      o += i + 1 < n ? ",\n" : "\n";
    };
    constexpr std::size_t kBlock = 8192;
    if (threads_ < 2 || n < 4 * kBlock) {
      for (std::size_t i = 0; i < n; ++i) {
        line(out_, i);
        flush_if_full();
      }
    } else {
      // Rounds of a few blocks per thread, so that a round's text stays small.
      const std::size_t per_round = 4 * static_cast<std::size_t>(threads_);
      std::vector<std::string> blocks(per_round);
      for (std::size_t first = 0; first < n; first += per_round * kBlock) {
        const std::size_t count = std::min(per_round, (n - first + kBlock - 1) / kBlock);
        parallel_for(static_cast<int64_t>(count), threads_, [&](int64_t b0, int64_t b1, int) {
          for (int64_t b = b0; b < b1; ++b) {
            std::string &o = blocks[b];
            o.clear();
            const std::size_t begin = first + b * kBlock, end = std::min(n, begin + kBlock);
            for (std::size_t i = begin; i < end; ++i)
              line(o, i);
          }
        });
        for (std::size_t b = 0; b < count; ++b) {
          out_ += blocks[b];
          flush_if_full();
        }
      }
    }
    out_ += " ]";
  }
  // The rest of the text (all of it without a sink).
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

  void flush_if_full() {
    if (sink_ && out_.size() >= kChunk) {
      sink_->write(out_.data(), static_cast<std::streamsize>(out_.size()));
      out_.clear();
    }
  }

  static constexpr std::size_t kChunk = 1 << 20;
  std::ostream *sink_;
  int threads_;
  std::string out_;
  std::size_t field_start_ = 0;
};

std::string to_json_text(const TreeResult &t, bool timings, int threads,
                         std::ostream *sink = nullptr) {
  // A node line takes up to about 250 bytes, an arc's 20, a pair's 90, a branch's 100.
  TreeJsonWriter w(4096 + 256 * t.nodes.size() + 24 * t.arcs.size() + 96 * t.pairs.size() +
                       112 * t.branches.size(),
                   sink, threads);
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
  // The elements' text is written directly (io/json_numbers: the numbers as nlohmann writes
  // them); their names and enumerations are plain ASCII, nothing to escape.
  const auto integer = [](std::string &o, int64_t v) { append_json_int(o, v); };
  const auto real = [](std::string &o, double v) { append_json_double(o, v); };
  std::map<std::string, int64_t> by_type, by_location;
  std::array<int64_t, 4> type_count{}, location_count{};
  for (const TreeNode &n : t.nodes) {
    ++type_count[static_cast<int>(n.type)];
    ++location_count[static_cast<int>(n.location)];
  }
  w.array("nodes", t.nodes.size(), [&](std::string &o, std::size_t i) {
    const TreeNode &n = t.nodes[i];
    o += "{\"id\":";
    integer(o, static_cast<int64_t>(i));
    o += ",\"type\":\"";
    o += to_string(n.type);
    o += "\",\"value\":";
    real(o, n.value);
    o += ",\"position\":[";
    real(o, n.position[0]);
    o += ',';
    real(o, n.position[1]);
    o += ',';
    real(o, n.position[2]);
    o += "],\"cell\":";
    integer(o, n.cell);
    o += ",\"uv\":[";
    real(o, n.uv[0]);
    o += ',';
    real(o, n.uv[1]);
    o += "],\"location\":\"";
    o += to_string(n.location);
    o += n.fallback ? "\",\"fallback\":true" : "\",\"fallback\":false";
    if (n.merged > 1) {
      o += ",\"merged\":";
      integer(o, n.merged);
    }
    o += '}';
  });
  for (NodeType k : {NodeType::Minimum, NodeType::Maximum, NodeType::Saddle, NodeType::Regular})
    if (type_count[static_cast<int>(k)] > 0)
      by_type[to_string(k)] = type_count[static_cast<int>(k)];
  for (NodeLocation k :
       {NodeLocation::Vertex, NodeLocation::Edge, NodeLocation::Interior, NodeLocation::Unknown})
    if (location_count[static_cast<int>(k)] > 0)
      by_location[to_string(k)] = location_count[static_cast<int>(k)];
  w.array("arcs", t.arcs.size(), [&](std::string &o, std::size_t i) {
    o += '[';
    integer(o, t.arcs[i][0]);
    o += ',';
    integer(o, t.arcs[i][1]);
    o += ']';
  });
  // A pair at or below the input's precision, or within the fallback stand-in's slack, says so
  // ("uncertain": true).
  w.array("pairs", t.pairs.size(), [&](std::string &o, std::size_t i) {
    const PersistencePair &p = t.pairs[i];
    o += "{\"birth\":";
    integer(o, p.birth);
    o += ",\"death\":";
    integer(o, p.death);
    o += ",\"persistence\":";
    real(o, p.persistence());
    o += ",\"kind\":\"";
    o += to_string(p.kind);
    o += t.uncertain(p) ? "\",\"uncertain\":true}" : "\"}";
  });
  w.array("branches", t.branches.size(), [&](std::string &o, std::size_t b) {
    const Branch &br = t.branches[b];
    o += "{\"id\":";
    integer(o, static_cast<int64_t>(b));
    o += ",\"extremum\":";
    integer(o, br.extremum);
    o += ",\"saddle\":";
    integer(o, br.saddle);
    o += ",\"persistence\":";
    real(o, br.persistence);
    o += ",\"parent\":";
    integer(o, br.parent);
    o += ",\"depth\":";
    integer(o, br.depth);
    o += '}';
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

std::string tree_to_json(const TreeResult &tree, bool timings, int threads) {
  return to_json_text(tree, timings, threads);
}

void write_tree_json(const std::string &path, const TreeResult &tree, bool timings, int threads) {
  write_file_atomic(
      path,
      [&](std::ostream &out) {
        // The arrays streamed to `out` as they are formatted, then the rest.
        const std::string rest = to_json_text(tree, timings, threads, &out);
        out << rest << "\n";
      },
      false);
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
