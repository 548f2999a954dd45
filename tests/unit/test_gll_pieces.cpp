// GLL-placed nodes (DOLFINx's degree >= 3 output) resampled piece by piece, as the ranks of a
// distributed run resample their own pieces, give every shared node the bits the whole mesh
// resampled at once gives it: an edge's nodes are computed from the edge alone, from its end of
// lower point id, whichever cell (or piece) holds it. Meshes of cubic and quartic triangles and
// cubic quadrilaterals with edges in both orientations, in 2, 3 and 5 pieces.
#include "mesh/gll_nodes.hpp"
#include "mesh/mesh_fingerprint.hpp"
#include "mesh/mesh_partition.hpp"
#include "poly/lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

namespace hoct {
namespace {

double field(double x, double y) { return std::sin(3 * x + 0.4) * std::cos(2 * y - 0.3) + x * y; }

// An n x n grid of the unit square, its nodes on GLL points of the edges; one node per edge
// position, shared by the cells on both sides.
class GllGrid {
public:
  explicit GllGrid(int d) : d_(d), g_(gll_points(d)) {}
  MeshInput in;

  int64_t corner(int i, int j, int n) {
    return node({i, j, -1, -1}, [&] { return Vec3{double(i) / n, double(j) / n, 0}; });
  }
  // Node t (0 < t < d) of the edge a-b, counted from a; the same point from b's side.
  int64_t edge_node(int64_t a, int64_t b, int t) {
    if (a > b)
      return edge_node(b, a, d_ - t);
    return node({a, b, t, -2}, [&] {
      const Vec3 &p = in.points[a], &q = in.points[b];
      const double s = g_[t];
      return Vec3{(1 - s) * p[0] + s * q[0], (1 - s) * p[1] + s * q[1], 0};
    });
  }
  int64_t inner(Vec3 x) {
    in.points.push_back(x);
    in.values.push_back(field(x[0], x[1]));
    return static_cast<int64_t>(in.points.size()) - 1;
  }

private:
  template <class F> int64_t node(std::array<int64_t, 4> key, F position) {
    auto [it, fresh] = ids_.try_emplace(key, static_cast<int64_t>(in.points.size()));
    if (fresh)
      inner(position());
    return it->second;
  }
  int d_;
  std::vector<double> g_;
  std::map<std::array<int64_t, 4>, int64_t> ids_;
};

// Triangles of degree d: each square split along a diagonal, alternating, so that edges are met
// in both orientations.
MeshInput gll_triangles(int d, int n) {
  GllGrid grid(d);
  MeshInput &in = grid.in;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int64_t a = grid.corner(i, j, n), b = grid.corner(i + 1, j, n),
                    c = grid.corner(i + 1, j + 1, n), e = grid.corner(i, j + 1, n);
      const bool flip = (i + j) % 2 == 1;
      for (const auto &tri : flip ? std::vector<std::array<int64_t, 3>>{{a, b, e}, {b, c, e}}
                                  : std::vector<std::array<int64_t, 3>>{{a, b, c}, {a, c, e}}) {
        std::vector<int64_t> nodes(static_cast<std::size_t>(lattice_size(d)));
        const Vec3 p0 = in.points[tri[0]], p1 = in.points[tri[1]], p2 = in.points[tri[2]];
        for (int k = 0; k < lattice_size(d); ++k) {
          const auto [u, v] = lattice_point(d, k);
          if (u + v == 0 || u == d || v == d) {
            nodes[k] = tri[u == d ? 1 : v == d ? 2 : 0];
          } else if (v == 0) {
            nodes[k] = grid.edge_node(tri[0], tri[1], u);
          } else if (u + v == d) {
            nodes[k] = grid.edge_node(tri[1], tri[2], v);
          } else if (u == 0) {
            nodes[k] = grid.edge_node(tri[2], tri[0], d - v);
          } else { // inside, off the equispaced lattice
            const double s = (u + 0.1) / (d + 0.3), t = (v + 0.05) / (d + 0.2);
            Vec3 x;
            for (int q = 0; q < 3; ++q)
              x[q] = (1 - s - t) * p0[q] + s * p1[q] + t * p2[q];
            nodes[k] = grid.inner(x);
          }
        }
        in.add_cell(d, nodes.data());
      }
    }
  return in;
}

// Quadrilaterals of order p, every other one's nodes listed from another corner (its edges met
// in the other orientation).
MeshInput gll_quadrilaterals(int p, int n) {
  GllGrid grid(p);
  MeshInput &in = grid.in;
  const std::vector<double> g = gll_points(p);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      std::array<int64_t, 4> c = {grid.corner(i, j, n), grid.corner(i + 1, j, n),
                                  grid.corner(i + 1, j + 1, n), grid.corner(i, j + 1, n)};
      if ((i + j) % 2 == 1) // start at another corner, the other way round
        c = {c[1], c[0], c[3], c[2]};
      std::vector<int64_t> nodes(static_cast<std::size_t>((p + 1) * (p + 1)));
      for (int b = 0; b <= p; ++b)
        for (int a = 0; a <= p; ++a) {
          int64_t id;
          if ((a == 0 || a == p) && (b == 0 || b == p))
            id = c[a == 0 ? (b == 0 ? 0 : 3) : (b == 0 ? 1 : 2)];
          else if (b == 0)
            id = grid.edge_node(c[0], c[1], a);
          else if (b == p)
            id = grid.edge_node(c[3], c[2], a);
          else if (a == 0)
            id = grid.edge_node(c[0], c[3], b);
          else if (a == p)
            id = grid.edge_node(c[1], c[2], b);
          else {
            const double s = g[a], t = g[b];
            const Vec3 &x0 = in.points[c[0]], &x1 = in.points[c[1]], &x2 = in.points[c[2]],
                       &x3 = in.points[c[3]];
            Vec3 x;
            for (int q = 0; q < 3; ++q)
              x[q] = (1 - s) * (1 - t) * x0[q] + s * (1 - t) * x1[q] + s * t * x2[q] +
                     (1 - s) * t * x3[q];
            id = grid.inner(x);
          }
          nodes[static_cast<std::size_t>(a + (p + 1) * b)] = id;
        }
      in.add_cell(CellKind::LagrangeQuadrilateral, p, nodes.data());
    }
  return in;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_pieces_agree(const MeshInput &original, const std::string &name) {
  MeshInput whole = original;
  const GllResampling all = resample_gll_cells(whole);
  ASSERT_GT(all.cells + all.quadrilaterals, 0) << name << ": no GLL cell found";
  // The whole's fingerprint is the data as read.
  EXPECT_EQ(mesh_fingerprint(whole).hash, mesh_fingerprint(original).hash) << name;
  for (int pieces : {2, 3, 5})
    for (int k = 0; k < pieces; ++k) {
      MeshPiece piece = partition_piece(original, pieces, k);
      resample_gll_cells(piece.input);
      int64_t differ = 0;
      for (std::size_t i = 0; i < piece.global_point.size(); ++i) {
        const auto w = static_cast<std::size_t>(piece.global_point[i]);
        bool same = same_bits(piece.input.values[i], whole.values[w]);
        for (int q = 0; q < 3; ++q)
          same = same && same_bits(piece.input.points[i][q], whole.points[w][q]);
        differ += !same;
      }
      EXPECT_EQ(differ, 0) << name << ", piece " << k << " of " << pieces
                           << ": nodes whose bits differ from the whole's";
    }
}

TEST(GllPieces, CubicTrianglesAgreeWithTheWhole) {
  expect_pieces_agree(gll_triangles(3, 6), "cubic triangles");
}

TEST(GllPieces, QuarticTrianglesAgreeWithTheWhole) {
  expect_pieces_agree(gll_triangles(4, 5), "quartic triangles");
}

TEST(GllPieces, CubicQuadrilateralsAgreeWithTheWhole) {
  expect_pieces_agree(gll_quadrilaterals(3, 6), "cubic quadrilaterals");
}

} // namespace
} // namespace hoct
