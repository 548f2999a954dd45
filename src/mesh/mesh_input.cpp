#include "mesh/mesh_input.hpp"

#include "poly/lattice.hpp"

namespace hoct {

void MeshInput::add_cell(int degree, const int64_t *nodes) {
  const int n = lattice_size(degree);
  cell_nodes.insert(cell_nodes.end(), nodes, nodes + n);
  cell_offsets.push_back(static_cast<int64_t>(cell_nodes.size()));
  cell_degree.push_back(static_cast<uint8_t>(degree));
}

} // namespace hoct
