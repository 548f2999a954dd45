#include "io/tree_svg_writer.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_xml_arrays.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace hoct {
namespace {

const char *colour(NodeType t) {
  switch (t) {
  case NodeType::Maximum:
    return "#d62728";
  case NodeType::Minimum:
    return "#1f77b4";
  case NodeType::Saddle:
    return "#2ca02c";
  default:
    return "#7f7f7f";
  }
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Per arc, whether it lies on a cycle of the graph (is no bridge): Tarjan's low points by an
// iterative depth-first search, each arc skipped only as the one its node was entered by, so
// parallel arcs are cycles.
std::vector<uint8_t> arcs_on_loops(std::size_t nodes,
                                   const std::vector<std::array<int64_t, 2>> &arcs) {
  std::vector<std::vector<std::pair<int64_t, int64_t>>> adj(nodes); // (neighbour, arc)
  for (std::size_t a = 0; a < arcs.size(); ++a) {
    adj[arcs[a][0]].push_back({arcs[a][1], static_cast<int64_t>(a)});
    adj[arcs[a][1]].push_back({arcs[a][0], static_cast<int64_t>(a)});
  }
  std::vector<int64_t> order(nodes, -1), low(nodes, 0);
  std::vector<uint8_t> on_loop(arcs.size(), 1);
  struct Frame {
    int64_t v, via;
    std::size_t next;
  };
  std::vector<Frame> stack;
  int64_t time = 0;
  for (std::size_t root = 0; root < nodes; ++root) {
    if (order[root] >= 0)
      continue;
    order[root] = low[root] = time++;
    stack.push_back({static_cast<int64_t>(root), -1, 0});
    while (!stack.empty()) {
      Frame &f = stack.back();
      if (f.next < adj[f.v].size()) {
        const auto [u, a] = adj[f.v][f.next++];
        if (a == f.via)
          continue;
        if (order[u] < 0) {
          order[u] = low[u] = time++;
          stack.push_back({u, a, 0});
        } else {
          low[f.v] = std::min(low[f.v], order[u]);
        }
        continue;
      }
      const Frame done = f;
      stack.pop_back();
      if (!stack.empty()) {
        const int64_t p = stack.back().v;
        low[p] = std::min(low[p], low[done.v]);
        if (low[done.v] > order[p])
          on_loop[done.via] = 0; // a bridge
      }
    }
  }
  return on_loop;
}

// A Reeb graph with loops: every node at its value, x from a spanning forest (leaves in
// depth-first order, inner nodes at their children's mean), every arc a straight line, the arcs
// on loops in their own colour.
// The value axis at x = left from y = top to y = bottom, with six ticks from lo to hi placed by Y.
template <class Place>
void value_axis(std::ostream &s, double left, double top, double bottom, double lo, double hi,
                const Place &Y) {
  s << "<line x1=\"" << num(left) << "\" y1=\"" << num(top) << "\" x2=\"" << num(left) << "\" y2=\""
    << num(bottom) << "\" stroke=\"#444\"/>\n";
  for (int k = 0; k <= 5; ++k) {
    const double v = lo + (hi - lo) * k / 5;
    s << "<line x1=\"" << num(left - 5) << "\" y1=\"" << num(Y(v)) << "\" x2=\"" << num(left)
      << "\" y2=\"" << num(Y(v)) << "\" stroke=\"#444\"/><text x=\"" << num(left - 8) << "\" y=\""
      << num(Y(v) + 4) << "\" font-size=\"11\" text-anchor=\"end\">" << num(v) << "</text>\n";
  }
}

// The legend of the node types from x = lx along the top; returns where the next entry goes.
double node_legend(std::ostream &s, double lx) {
  for (auto [type, label] :
       {std::pair{NodeType::Maximum, "maximum"}, std::pair{NodeType::Saddle, "saddle"},
        std::pair{NodeType::Minimum, "minimum"}}) {
    s << "<circle cx=\"" << num(lx) << "\" cy=\"40\" r=\"5\" fill=\"" << colour(type)
      << "\" stroke=\"black\" stroke-width=\"0.6\"/><text x=\"" << num(lx + 9)
      << "\" y=\"44\" font-size=\"12\">" << label << "</text>\n";
    lx += 80;
  }
  return lx;
}

void write_graph_svg(const std::string &path, const TreeResult &t, const std::string &title) {
  const std::size_t n = t.nodes.size();
  std::vector<std::vector<int64_t>> adj(n);
  for (const auto &a : t.arcs) {
    adj[a[0]].push_back(a[1]);
    adj[a[1]].push_back(a[0]);
  }
  std::vector<int64_t> parent(n, -2), preorder;
  std::vector<std::vector<int64_t>> children(n);
  for (std::size_t root = 0; root < n; ++root) {
    if (parent[root] != -2)
      continue;
    parent[root] = -1;
    std::vector<int64_t> stack = {static_cast<int64_t>(root)};
    while (!stack.empty()) {
      const int64_t v = stack.back();
      stack.pop_back();
      preorder.push_back(v);
      for (auto it = adj[v].rbegin(); it != adj[v].rend(); ++it)
        if (parent[*it] == -2) {
          parent[*it] = v;
          children[v].push_back(*it);
          stack.push_back(*it);
        }
    }
  }
  std::vector<double> column(n, 0);
  int leaves = 0;
  for (int64_t v : preorder)
    if (children[v].empty())
      column[v] = leaves++;
  for (auto it = preorder.rbegin(); it != preorder.rend(); ++it)
    if (!children[*it].empty()) {
      double sum = 0;
      for (int64_t c : children[*it])
        sum += column[c];
      column[*it] = sum / static_cast<double>(children[*it].size());
    }
  const double lo = t.nodes.front().value, hi = t.nodes.back().value;
  const double W = std::max(520.0, 90.0 + 14.0 * leaves), H = 640, top = 64, bottom = 40, left = 80;
  const double dx = (W - left - 30) / std::max(1, leaves - 1);
  auto X = [&](int64_t v) { return left + 15 + column[v] * (leaves > 1 ? dx : 0); };
  auto Y = [&](double v) {
    return hi > lo ? top + (hi - v) / (hi - lo) * (H - top - bottom) : H / 2;
  };
  const std::vector<uint8_t> on_loop = arcs_on_loops(n, t.arcs);
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(W) << "\" height=\"" << num(H)
    << "\" viewBox=\"0 0 " << num(W) << " " << num(H) << "\" font-family=\"sans-serif\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << num(left) << "\" y=\"24\" font-size=\"15\">" << xml_escape(title)
    << "</text>\n<text x=\"" << num(left) << "\" y=\"52\" font-size=\"11\">Reeb graph: " << t.loops
    << " loop" << (t.loops == 1 ? "" : "s") << ", " << t.arcs.size() << " arcs</text>\n";
  value_axis(s, left, top, H - bottom, lo, hi, Y);
  // Parallel arcs bow apart, so that a loop of two arcs shows as two.
  std::map<std::array<int64_t, 2>, int> seen;
  s << "<g stroke-width=\"1.5\" fill=\"none\">\n";
  for (std::size_t a = 0; a < t.arcs.size(); ++a) {
    const auto &arc = t.arcs[a];
    const int k = seen[arc]++;
    const double x0 = X(arc[0]), y0 = Y(t.nodes[arc[0]].value);
    const double x1 = X(arc[1]), y1 = Y(t.nodes[arc[1]].value);
    const double bow = (k % 2 == 0 ? 1 : -1) * 12.0 * ((k + 1) / 2);
    s << "<path class=\"" << (on_loop[a] ? "loop" : "arc") << "\" stroke=\""
      << (on_loop[a] ? "#ff7f0e" : "#555") << "\" d=\"M " << num(x0) << " " << num(y0) << " Q "
      << num((x0 + x1) / 2 + bow) << " " << num((y0 + y1) / 2) << " " << num(x1) << " " << num(y1)
      << "\"/>\n";
  }
  s << "</g>\n<g stroke=\"black\" stroke-width=\"0.6\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    const TreeNode &node = t.nodes[i];
    s << "<circle cx=\"" << num(X(static_cast<int64_t>(i))) << "\" cy=\"" << num(Y(node.value))
      << "\" r=\"4.5\" fill=\"" << colour(node.type) << "\"><title>" << to_string(node.type) << " "
      << i << ": value " << num(node.value) << ", " << to_string(node.location) << " of cell "
      << node.cell << "</title></circle>\n";
  }
  s << "</g>\n";
  const double lx = node_legend(s, W - 330);
  s << "<line x1=\"" << num(lx - 6) << "\" y1=\"40\" x2=\"" << num(lx + 6)
    << "\" y2=\"40\" stroke=\"#ff7f0e\" stroke-width=\"2\"/><text x=\"" << num(lx + 10)
    << "\" y=\"44\" font-size=\"12\">arc on a loop</text>\n";
  s << "</svg>\n";
  const std::string text = s.str();
  write_file_atomic(
      path, [&](std::ostream &out) { out << text; }, false);
}

} // namespace

void write_tree_svg(const std::string &path, const TreeResult &t, const std::string &title) {
  if (t.loops > 0)
    return write_graph_svg(path, t, title);
  const auto &b = t.branches;
  if (b.empty())
    throw Error("write_tree_svg: the tree has no branch decomposition");
  // Columns: depth-first from the root, children by decreasing persistence.
  const auto children = branch_children(b);
  std::vector<int> column(b.size(), 0);
  int next = 0;
  std::vector<int64_t> stack = {0};
  while (!stack.empty()) {
    const int64_t i = stack.back();
    stack.pop_back();
    column[i] = next++;
    for (auto it = children[i].rbegin(); it != children[i].rend(); ++it)
      stack.push_back(*it);
  }
  const double lo = t.nodes.front().value, hi = t.nodes.back().value;
  const double W = std::max(520.0, 90.0 + 14.0 * next), H = 640, top = 64, bottom = 40, left = 80;
  const double dx = (W - left - 30) / std::max(1, next - 1 > 0 ? next - 1 : 1);
  auto X = [&](int64_t branch) { return left + 15 + column[branch] * (next > 1 ? dx : 0); };
  auto Y = [&](double v) {
    return hi > lo ? top + (hi - v) / (hi - lo) * (H - top - bottom) : H / 2;
  };
  // Persistence per node, for the titles.
  std::vector<double> node_pers(t.nodes.size(), 0.0);
  for (const auto &br : b) {
    node_pers[br.extremum] = std::max(node_pers[br.extremum], br.persistence);
    node_pers[br.saddle] = std::max(node_pers[br.saddle], br.persistence);
  }
  // Where each node is drawn: extrema in their branch's column, saddles in the parent's.
  std::vector<double> nx(t.nodes.size(), -1);
  for (std::size_t i = 0; i < b.size(); ++i) {
    nx[b[i].extremum] = X(static_cast<int64_t>(i));
    if (i == 0)
      nx[b[i].saddle] = X(0);
    else if (nx[b[i].saddle] < 0)
      nx[b[i].saddle] = X(b[i].parent);
  }
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(W) << "\" height=\"" << num(H)
    << "\" viewBox=\"0 0 " << num(W) << " " << num(H) << "\" font-family=\"sans-serif\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << num(left) << "\" y=\"24\" font-size=\"15\">" << xml_escape(title)
    << "</text>\n";
  // Value axis.
  value_axis(s, left, top, H - bottom, lo, hi, Y);
  // Branches: vertical segments, joined to the parent at the saddle.
  s << "<g stroke=\"#555\" stroke-width=\"1.5\" fill=\"none\">\n";
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double x = X(static_cast<int64_t>(i));
    s << "<line x1=\"" << num(x) << "\" y1=\"" << num(Y(t.nodes[b[i].extremum].value)) << "\" x2=\""
      << num(x) << "\" y2=\"" << num(Y(t.nodes[b[i].saddle].value)) << "\"/>";
    if (i > 0)
      s << "<line x1=\"" << num(x) << "\" y1=\"" << num(Y(t.nodes[b[i].saddle].value)) << "\" x2=\""
        << num(X(b[i].parent)) << "\" y2=\"" << num(Y(t.nodes[b[i].saddle].value)) << "\"/>";
    s << "\n";
  }
  s << "</g>\n<g stroke=\"black\" stroke-width=\"0.6\">\n";
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    if (nx[i] < 0)
      continue;
    const TreeNode &n = t.nodes[i];
    s << "<circle cx=\"" << num(nx[i]) << "\" cy=\"" << num(Y(n.value)) << "\" r=\"4.5\" fill=\""
      << colour(n.type) << "\"><title>" << to_string(n.type) << " " << i << ": value "
      << num(n.value) << ", persistence " << num(node_pers[i]) << ", " << to_string(n.location)
      << " of cell " << n.cell << "</title></circle>\n";
  }
  s << "</g>\n";
  node_legend(s, W - 250);
  s << "</svg>\n";
  const std::string text = s.str();
  write_file_atomic(
      path, [&](std::ostream &out) { out << text; }, false);
}

} // namespace hoct
