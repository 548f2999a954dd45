#include "exact/piece_codec.hpp"

#include "util/byte_codec.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace hoct {
namespace {

constexpr uint64_t kMagic = 0x686f637470696563;     // "hoctpiec"
constexpr uint64_t kReebMagic = 0x686f637472656562; // "hoctreeb"

} // namespace

std::vector<std::byte> encode_piece_trees(const PieceTrees &t) {
  static_assert(std::is_trivially_copyable_v<PieceNode>);
  static_assert(std::is_trivially_copyable_v<ExactCounts>);
  ByteWriter w;
  w.value(kMagic);
  w.value(t.first_piece);
  w.value(t.last_piece);
  w.array(t.nodes);
  w.array(t.join_parent);
  w.array(t.split_parent);
  w.value(t.counts);
  w.value<uint64_t>(t.chains.size());
  for (const SharedChain &c : t.chains) {
    w.value(c.lo);
    w.value(c.hi);
    w.value(c.span);
    w.array(c.nodes);
  }
  return std::move(w.out);
}

PieceTrees decode_piece_trees(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "decode_piece_trees");
  if (r.value<uint64_t>() != kMagic)
    throw std::runtime_error("decode_piece_trees: not an encoded PieceTrees");
  PieceTrees t;
  t.first_piece = r.value<int32_t>();
  t.last_piece = r.value<int32_t>();
  t.nodes = r.array<PieceNode>();
  t.join_parent = r.array<int64_t>();
  t.split_parent = r.array<int64_t>();
  t.counts = r.value<ExactCounts>();
  const uint64_t chains = r.value<uint64_t>();
  if (chains > bytes.size())
    throw std::runtime_error("decode_piece_trees: too many chains");
  t.chains.resize(static_cast<std::size_t>(chains));
  for (SharedChain &c : t.chains) {
    c.lo = r.value<int64_t>();
    c.hi = r.value<int64_t>();
    c.span = r.value<std::array<int32_t, 2>>();
    c.nodes = r.array<ChainNode>();
  }
  const std::size_t n = t.nodes.size();
  bool sane = r.done() && t.join_parent.size() == n && t.split_parent.size() == n &&
              t.first_piece <= t.last_piece;
  for (std::size_t i = 0; sane && i < n; ++i)
    sane = t.join_parent[i] >= -1 && t.join_parent[i] < static_cast<int64_t>(n) &&
           t.split_parent[i] >= -1 && t.split_parent[i] < static_cast<int64_t>(n);
  for (const SharedChain &c : t.chains)
    for (const auto &[pos, i] : c.nodes)
      sane = sane && i >= 0 && i < static_cast<int64_t>(n);
  if (!sane)
    throw std::runtime_error("decode_piece_trees: inconsistent arrays");
  return t;
}

std::vector<std::byte> encode_reeb_group(const ReebGroup &g) {
  ByteWriter w;
  w.value(kReebMagic);
  w.value(g.first_piece);
  w.value(g.last_piece);
  w.array(g.nodes);
  w.array(g.arcs);
  w.value(g.counts);
  w.value(g.seam_edges);
  w.value(g.nonmonotone);
  w.value<uint64_t>(g.chains.size());
  for (const ReebChain &c : g.chains) {
    w.value(c.lo);
    w.value(c.hi);
    w.value(c.span);
    w.array(c.nodes);
    w.array(c.rising);
    w.array(c.route_first);
    w.array(c.route_arcs);
  }
  return std::move(w.out);
}

ReebGroup decode_reeb_group(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "decode_reeb_group");
  if (r.value<uint64_t>() != kReebMagic)
    throw std::runtime_error("decode_reeb_group: not an encoded ReebGroup");
  ReebGroup g;
  g.first_piece = r.value<int32_t>();
  g.last_piece = r.value<int32_t>();
  g.nodes = r.array<PieceNode>();
  g.arcs = r.array<std::array<int64_t, 2>>();
  g.counts = r.value<ExactCounts>();
  g.seam_edges = r.value<int64_t>();
  g.nonmonotone = r.value<int64_t>();
  const uint64_t chains = r.value<uint64_t>();
  if (chains > bytes.size())
    throw std::runtime_error("decode_reeb_group: too many chains");
  g.chains.resize(static_cast<std::size_t>(chains));
  for (ReebChain &c : g.chains) {
    c.lo = r.value<NodeKey>();
    c.hi = r.value<NodeKey>();
    c.span = r.value<std::array<int32_t, 2>>();
    c.nodes = r.array<int64_t>();
    c.rising = r.array<uint8_t>();
    c.route_first = r.array<int64_t>();
    c.route_arcs = r.array<int64_t>();
  }
  const int64_t n = static_cast<int64_t>(g.nodes.size());
  const auto node = [&](int64_t i) { return i >= 0 && i < n; };
  bool sane = r.done() && g.first_piece <= g.last_piece;
  for (const auto &a : g.arcs)
    sane = sane && node(a[0]) && node(a[1]);
  const int64_t arcs = static_cast<int64_t>(g.arcs.size());
  for (const ReebChain &c : g.chains) {
    sane = sane && !c.nodes.empty() && c.rising.size() + 1 == c.nodes.size() &&
           c.route_first.size() == c.nodes.size() && c.route_first.front() == 0 &&
           c.route_first.back() == static_cast<int64_t>(c.route_arcs.size()) &&
           std::is_sorted(c.route_first.begin(), c.route_first.end());
    for (const int64_t i : c.nodes)
      sane = sane && node(i);
    for (const int64_t a : c.route_arcs)
      sane = sane && a >= 0 && a < arcs;
  }
  if (!sane)
    throw std::runtime_error("decode_reeb_group: inconsistent arrays");
  return g;
}

} // namespace hoct
