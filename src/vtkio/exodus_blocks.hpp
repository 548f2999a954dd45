// The element blocks of an Exodus II file as the file declares them (its netCDF header: each
// connectivity variable's elem_type and nodes per element), read with the netCDF library VTK's
// Exodus reader uses: to refuse the blocks that reader misreads without a word.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

struct ExodusBlock {
  int index = 0;         // from 1, as the file numbers its connectivity variables (connect1, ...)
  std::string elem_type; // as written ("TRI6", "tri7", "TRIANGLE", ...)
  int64_t elements = 0;
  int nodes_per_element = 0;
};

// Throws InputError for a file netCDF cannot open or that ends before its last variable does.
std::vector<ExodusBlock> exodus_element_blocks(const std::string &path);

// InputError if a block cannot be read right: VTK 9's Exodus reader takes a 7-node triangle
// (TRI7: P2 and a cubic bubble, as MOOSE writes) for a 3-node one and walks its connectivity
// three nodes at a time, which scrambles the mesh.
void check_exodus_blocks(const std::string &path, const std::vector<ExodusBlock> &blocks);

} // namespace hoct
