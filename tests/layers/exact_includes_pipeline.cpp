// Must not compile in the exact module's layer: the pipeline sits above it.
#include "pipeline/compute_tree.hpp"
