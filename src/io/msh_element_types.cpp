#include "io/msh_element_types.hpp"

#include "poly/quad_basis.hpp"

#include "poly/lattice.hpp"

#include <algorithm>
#include <array>
#include <cstring>

namespace hoct {
namespace {

// Every type with a fixed node count that Gmsh 4.8 defines, sorted by type. Prisms of order >= 3
// (types 90, 91, 106-117) are left out: Gmsh itself cannot describe them, and the reader rejects
// them as unknown, as it would reject them as non-triangles.
constexpr std::array<MshElementType, 110> kTypes = {{
    {1, "Line 2", 1, 1, 2},
    {2, "Triangle 3", 2, 1, 3},
    {3, "Quadrilateral 4", 2, 1, 4},
    {4, "Tetrahedron 4", 3, 1, 4},
    {5, "Hexahedron 8", 3, 1, 8},
    {6, "Prism 6", 3, 1, 6},
    {7, "Pyramid 5", 3, 1, 5},
    {8, "Line 3", 1, 2, 3},
    {9, "Triangle 6", 2, 2, 6},
    {10, "Quadrilateral 9", 2, 2, 9},
    {11, "Tetrahedron 10", 3, 2, 10},
    {12, "Hexahedron 27", 3, 2, 27},
    {13, "Prism 18", 3, 2, 18},
    {14, "Pyramid 14", 3, 2, 14},
    {15, "Point", 0, 0, 1},
    {16, "Quadrilateral 8", 2, 2, 8},
    {17, "Hexahedron 20", 3, 2, 20},
    {18, "Prism 15", 3, 2, 15},
    {19, "Pyramid 13", 3, 2, 13},
    {20, "Triangle 9", 2, 3, 9},
    {21, "Triangle 10", 2, 3, 10},
    {22, "Triangle 12", 2, 4, 12},
    {23, "Triangle 15", 2, 4, 15},
    {24, "Triangle 15I", 2, 5, 15},
    {25, "Triangle 21", 2, 5, 21},
    {26, "Line 4", 1, 3, 4},
    {27, "Line 5", 1, 4, 5},
    {28, "Line 6", 1, 5, 6},
    {29, "Tetrahedron 20", 3, 3, 20},
    {30, "Tetrahedron 35", 3, 4, 35},
    {31, "Tetrahedron 56", 3, 5, 56},
    {32, "Tetrahedron 22", 3, 4, 22},
    {33, "Tetrahedron 28", 3, 5, 28},
    {36, "Quadrilateral 16", 2, 3, 16},
    {37, "Quadrilateral 25", 2, 4, 25},
    {38, "Quadrilateral 36", 2, 5, 36},
    {39, "Quadrilateral 12", 2, 3, 12},
    {40, "Quadrilateral 16I", 2, 4, 16},
    {41, "Quadrilateral 20", 2, 5, 20},
    {42, "Triangle 28", 2, 6, 28},
    {43, "Triangle 36", 2, 7, 36},
    {44, "Triangle 45", 2, 8, 45},
    {45, "Triangle 55", 2, 9, 55},
    {46, "Triangle 66", 2, 10, 66},
    {47, "Quadrilateral 49", 2, 6, 49},
    {48, "Quadrilateral 64", 2, 7, 64},
    {49, "Quadrilateral 81", 2, 8, 81},
    {50, "Quadrilateral 100", 2, 9, 100},
    {51, "Quadrilateral 121", 2, 10, 121},
    {52, "Triangle 18", 2, 6, 18},
    {53, "Triangle 21I", 2, 7, 21},
    {54, "Triangle 24", 2, 8, 24},
    {55, "Triangle 27", 2, 9, 27},
    {56, "Triangle 30", 2, 10, 30},
    {57, "Quadrilateral 24", 2, 6, 24},
    {58, "Quadrilateral 28", 2, 7, 28},
    {59, "Quadrilateral 32", 2, 8, 32},
    {60, "Quadrilateral 36I", 2, 9, 36},
    {61, "Quadrilateral 40", 2, 10, 40},
    {62, "Line 7", 1, 6, 7},
    {63, "Line 8", 1, 7, 8},
    {64, "Line 9", 1, 8, 9},
    {65, "Line 10", 1, 9, 10},
    {66, "Line 11", 1, 10, 11},
    {71, "Tetrahedron 84", 3, 6, 84},
    {72, "Tetrahedron 120", 3, 7, 120},
    {73, "Tetrahedron 165", 3, 8, 165},
    {74, "Tetrahedron 220", 3, 9, 220},
    {75, "Tetrahedron 286", 3, 10, 286},
    {79, "Tetrahedron 34", 3, 6, 34},
    {80, "Tetrahedron 40", 3, 7, 40},
    {81, "Tetrahedron 46", 3, 8, 46},
    {82, "Tetrahedron 52", 3, 9, 52},
    {83, "Tetrahedron 58", 3, 10, 58},
    {84, "Line 1", 1, 0, 1},
    {85, "Triangle 1", 2, 0, 1},
    {86, "Quadrilateral 1", 2, 0, 1},
    {87, "Tetrahedron 1", 3, 0, 1},
    {88, "Hexahedron 1", 3, 0, 1},
    {89, "Prism 1", 3, 0, 1},
    {92, "Hexahedron 64", 3, 3, 64},
    {93, "Hexahedron 125", 3, 4, 125},
    {94, "Hexahedron 216", 3, 5, 216},
    {95, "Hexahedron 343", 3, 6, 343},
    {96, "Hexahedron 512", 3, 7, 512},
    {97, "Hexahedron 729", 3, 8, 729},
    {98, "Hexahedron 1000", 3, 9, 1000},
    {99, "Hexahedron 32", 3, 3, 32},
    {100, "Hexahedron 44", 3, 4, 44},
    {101, "Hexahedron 56", 3, 5, 56},
    {102, "Hexahedron 68", 3, 6, 68},
    {103, "Hexahedron 80", 3, 7, 80},
    {104, "Hexahedron 92", 3, 8, 92},
    {105, "Hexahedron 104", 3, 9, 104},
    {118, "Pyramid 30", 3, 3, 30},
    {119, "Pyramid 55", 3, 4, 55},
    {120, "Pyramid 91", 3, 5, 91},
    {121, "Pyramid 140", 3, 6, 140},
    {122, "Pyramid 204", 3, 7, 204},
    {123, "Pyramid 285", 3, 8, 285},
    {124, "Pyramid 385", 3, 9, 385},
    {125, "Pyramid 21", 3, 3, 21},
    {126, "Pyramid 29", 3, 4, 29},
    {127, "Pyramid 37", 3, 5, 37},
    {128, "Pyramid 45", 3, 6, 45},
    {129, "Pyramid 53", 3, 7, 53},
    {130, "Pyramid 61", 3, 8, 61},
    {131, "Pyramid 69", 3, 9, 69},
    {132, "Pyramid 1", 3, 0, 1},
    {137, "Tetrahedron 16", 3, 3, 16},
}};

bool is_triangle(const MshElementType &t) { return std::strncmp(t.name, "Triangle", 8) == 0; }

} // namespace

int MshElementType::complete_triangle_degree() const {
  return is_triangle(*this) && order >= 1 && nodes == lattice_size(order) ? order : 0;
}

namespace {
bool is_quadrangle(const MshElementType &t) {
  return std::strncmp(t.name, "Quadrilateral", 13) == 0;
}
} // namespace

CellKind MshElementType::surface_kind() const {
  if (is_quadrangle(*this))
    return nodes == (order + 1) * (order + 1) ? CellKind::LagrangeQuadrilateral
                                              : CellKind::SerendipityQuadrilateral;
  return CellKind::LagrangeTriangle;
}

int MshElementType::surface_degree() const {
  if (is_quadrangle(*this) && order >= 1 && order <= kMaxQuadDegree &&
      (nodes == (order + 1) * (order + 1) || (order >= 2 && nodes == 4 * order)))
    return order;
  return complete_triangle_degree();
}

bool MshElementType::incomplete_triangle() const {
  return is_triangle(*this) && order >= 1 && nodes < lattice_size(order);
}

const MshElementType *msh_element_type(int type) {
  const auto it = std::lower_bound(kTypes.begin(), kTypes.end(), type,
                                   [](const MshElementType &t, int v) { return t.type < v; });
  return it != kTypes.end() && it->type == type ? &*it : nullptr;
}

} // namespace hoct
