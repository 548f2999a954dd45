// Compiles in the exact module's layer: every module below it.
#include "cell/certified_path.hpp"
#include "mesh/mesh.hpp"
#include "pl/cell_refinement.hpp"
#include "poly/bernstein_triangle.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/parallel_for.hpp"
