// Must not compile in the tree module's layer: the combinatorial trees know no mesh.
#include "mesh/mesh.hpp"
