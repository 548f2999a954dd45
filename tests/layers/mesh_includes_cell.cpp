// Must not compile in the mesh module's layer: cell sits above mesh.
#include "cell/edge_nodes.hpp"
