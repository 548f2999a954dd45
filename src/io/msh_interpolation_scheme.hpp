// A Gmsh $InterpolationScheme: the basis a view's $ElementNodeData values are coefficients of,
// per element topology as two matrices (Gmsh's "interpolation matrices"): the coefficients of
// each basis function (a row) over monomials u^p v^q, and the monomials' exponents (a row each).
// Gmsh writes one for every high-order view: the Lagrange basis of the element's own nodes, in
// which the coefficients are the values at the nodes. hoct reads a view's values as node values
// only where its scheme is that basis.
#pragma once

#include <string>
#include <vector>

namespace hoct {

struct MshInterpolationScheme {
  std::string name;
  std::size_t at = 0; // where the section starts, for messages
  // The triangle topology's matrices (empty if the scheme has none): coefficients, rows x cols
  // (a basis function per row, a monomial per column), and exponents, cols x 2 (or more).
  int rows = 0, cols = 0, exponent_columns = 0;
  std::vector<double> coefficients, exponents;
};

// The degree d such that the scheme's triangle basis is the Lagrange basis of Gmsh's degree-d
// triangle nodes in Gmsh's order (basis i is 1 at node i and 0 at the others, within 1e-9), or -1
// with *why saying what it is not.
int nodal_lagrange_degree(const MshInterpolationScheme &scheme, std::string *why);

} // namespace hoct
