// The element blocks of an Exodus II file as the file declares them (its netCDF header: each
// connectivity variable's elem_type and nodes per element), read with netCDF over a read-only
// mapping of the file, which also checks that every variable ends inside the file: netCDF
// reading a truncated classic file itself (as the Exodus library does) fills what is missing
// with zeros.
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

} // namespace hoct
