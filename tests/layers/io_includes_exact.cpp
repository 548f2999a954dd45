// Must not compile in the io module's layer: readers and writers know no algorithm.
#include "exact/exact_contour_tree.hpp"
