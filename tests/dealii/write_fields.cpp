// Writes, with deal.II itself, .vtu files of f(x, y) = sin(3x + 0.5) cos(2y + 0.5) + 0.3x on
// [0, 2]^2, interpolated (VectorTools::interpolate) into Lagrange spaces and written by DataOut
// with write_higher_order_cells = true:
//   simplex_p1.vtu, simplex_p2.vtu  FE_SimplexP of degree 1 and 2 on
//                                   subdivided_hyper_rectangle_with_simplices (MappingFE)
//   quad_q1.vtu, quad_q2.vtu, quad_q3.vtu  FE_Q of degree 1, 2, 3 on subdivided_hyper_rectangle
// deal.II 9.4 writes them as VTK_LAGRANGE_TRIANGLE (69) and VTK_LAGRANGE_QUADRILATERAL (70)
// cells, every cell with its own points (a point shared by k cells is written k times), points and
// values as Float32.
//
//   write_fields OUTDIR [N]   (N x N squares, default 8)

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
using namespace dealii;

class Field : public Function<2> {
public:
  double value(const Point<2> &p, const unsigned int = 0) const override {
    return std::sin(3.0 * p[0] + 0.5) * std::cos(2.0 * p[1] + 0.5) + 0.3 * p[0];
  }
};

void write(const std::string &path, const Mapping<2> &mapping, const DoFHandler<2> &dofs,
           const unsigned int degree) {
  Vector<double> u(dofs.n_dofs());
  VectorTools::interpolate(mapping, dofs, Field(), u);
  DataOut<2> out;
  DataOutBase::VtkFlags flags;
  flags.write_higher_order_cells = true;
  out.set_flags(flags);
  out.attach_dof_handler(dofs);
  out.add_data_vector(u, "f");
  out.build_patches(mapping, degree);
  std::ofstream file(path);
  out.write_vtu(file);
  if (!file)
    throw std::runtime_error("cannot write " + path);
  std::cout << path << ": " << dofs.get_triangulation().n_active_cells() << " cells, "
            << dofs.n_dofs() << " dofs\n";
}
} // namespace

int main(int argc, char **argv) {
  if (argc < 2) {
    std::cerr << "usage: write_fields OUTDIR [N]\n";
    return 2;
  }
  const std::string dir = argv[1];
  const int n = argc > 2 ? std::atoi(argv[2]) : 8;
  if (n < 1 || n > 1000) {
    std::cerr << "write_fields: N must be in 1..1000\n";
    return 2;
  }
  const Point<2> lo(0.0, 0.0), hi(2.0, 2.0);
  try {
    Triangulation<2> simplices;
    GridGenerator::subdivided_hyper_rectangle_with_simplices(simplices, {unsigned(n), unsigned(n)},
                                                             lo, hi);
    const MappingFE<2> simplex_mapping(FE_SimplexP<2>(1));
    for (const unsigned int degree : {1u, 2u}) {
      const FE_SimplexP<2> fe(degree);
      DoFHandler<2> dofs(simplices);
      dofs.distribute_dofs(fe);
      write(dir + "/simplex_p" + std::to_string(degree) + ".vtu", simplex_mapping, dofs, degree);
    }

    Triangulation<2> quads;
    GridGenerator::subdivided_hyper_rectangle(quads, {unsigned(n), unsigned(n)}, lo, hi);
    const MappingQ<2> quad_mapping(1);
    for (const unsigned int degree : {1u, 2u, 3u}) {
      const FE_Q<2> fe(degree);
      DoFHandler<2> dofs(quads);
      dofs.distribute_dofs(fe);
      write(dir + "/quad_q" + std::to_string(degree) + ".vtu", quad_mapping, dofs, degree);
    }
  } catch (const std::exception &e) {
    std::cerr << "write_fields: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
