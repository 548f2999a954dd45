#include "io/tree_svg_writer.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_xml_arrays.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

} // namespace

void write_tree_svg(const std::string &path, const TreeResult &t, const std::string &title) {
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
  s << "<line x1=\"" << num(left) << "\" y1=\"" << num(top) << "\" x2=\"" << num(left) << "\" y2=\""
    << num(H - bottom) << "\" stroke=\"#444\"/>\n";
  for (int k = 0; k <= 5; ++k) {
    const double v = lo + (hi - lo) * k / 5;
    s << "<line x1=\"" << num(left - 5) << "\" y1=\"" << num(Y(v)) << "\" x2=\"" << num(left)
      << "\" y2=\"" << num(Y(v)) << "\" stroke=\"#444\"/><text x=\"" << num(left - 8) << "\" y=\""
      << num(Y(v) + 4) << "\" font-size=\"11\" text-anchor=\"end\">" << num(v) << "</text>\n";
  }
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
  // Legend.
  double lx = W - 250;
  for (auto [type, label] :
       {std::pair{NodeType::Maximum, "maximum"}, std::pair{NodeType::Saddle, "saddle"},
        std::pair{NodeType::Minimum, "minimum"}}) {
    s << "<circle cx=\"" << num(lx) << "\" cy=\"40\" r=\"5\" fill=\"" << colour(type)
      << "\" stroke=\"black\" stroke-width=\"0.6\"/><text x=\"" << num(lx + 9)
      << "\" y=\"44\" font-size=\"12\">" << label << "</text>\n";
    lx += 80;
  }
  s << "</svg>\n";
  const std::string text = s.str();
  write_file_atomic(
      path, [&](std::ostream &out) { out << text; }, false);
}

} // namespace hoct
