// Binomial coefficients and multinomial weights for Bernstein bases, exact in double up to n = 60.
#pragma once

namespace hoct {

// C(n, k) as a double; 0 outside 0 <= k <= n.
double binomial(int n, int k);

// Trinomial d! / (i! j! k!) for i + j + k = d.
double trinomial(int i, int j, int k);

} // namespace hoct
