// HOCT_NO_VECTORIZE marks a function to be compiled without GCC's loop and straight-line (SLP)
// vectorisers. For the small fixed-degree kernels of the box search (de Casteljau splits, Taylor
// expansions) they pack scalar steps into vector loads of small stack arrays that scalar stores
// have just written, and on this project's machines (AMD EPYC) each such load stalls on store
// forwarding, which costs far more than the vector operations save. The operations, and so the
// results to the bit, are the same either way.
#pragma once

#if defined(__GNUC__) && !defined(__clang__)
#define HOCT_NO_VECTORIZE __attribute__((optimize("no-tree-vectorize", "no-tree-slp-vectorize")))
#else
#define HOCT_NO_VECTORIZE
#endif
