// Compiles in the tree module's layer: its own headers and util's.
#include "tree/contour_tree.hpp"
#include "util/vec.hpp"
