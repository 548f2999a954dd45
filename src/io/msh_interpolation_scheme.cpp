#include "io/msh_interpolation_scheme.hpp"

#include "poly/lagrange_node_order.hpp"
#include "poly/lattice.hpp"

#include <charconv>
#include <cmath>

namespace hoct {

namespace {

std::string shortest(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

} // namespace

int nodal_lagrange_degree(const MshInterpolationScheme &s, std::string *why) {
  if (s.rows == 0) {
    *why = "it has no matrices for triangles";
    return -1;
  }
  const int d = degree_from_node_count(s.rows);
  if (d < 1 || s.cols != s.rows || s.exponent_columns < 2) {
    *why = "its triangle matrices (" + std::to_string(s.rows) + " x " + std::to_string(s.cols) +
           ") are not those of a complete Lagrange triangle";
    return -1;
  }
  const std::vector<int> &lattice = node_order_to_lattice(NodeOrdering::Gmsh, d);
  for (int k = 0; k < s.rows; ++k) { // Gmsh's node k
    const std::array<int, 2> ab = lattice_point(d, lattice[static_cast<std::size_t>(k)]);
    const double u = static_cast<double>(ab[0]) / d, v = static_cast<double>(ab[1]) / d;
    for (int i = 0; i < s.rows; ++i) { // basis function i at node k
      double sum = 0;
      for (int j = 0; j < s.cols; ++j) {
        const std::size_t e = static_cast<std::size_t>(j * s.exponent_columns);
        sum += s.coefficients[static_cast<std::size_t>(i * s.cols + j)] *
               std::pow(u, s.exponents[e]) * std::pow(v, s.exponents[e + 1]);
      }
      if (std::abs(sum - (i == k ? 1.0 : 0.0)) > 1e-9) {
        *why = "its basis function " + std::to_string(i) + " is " + shortest(sum) + " at node " +
               std::to_string(k) + " of a degree-" + std::to_string(d) + " triangle, not " +
               (i == k ? "1" : "0") + ": it is not the Lagrange basis of the element's nodes";
        return -1;
      }
    }
  }
  return d;
}

} // namespace hoct
