#include "poly/monomial.hpp"

#include "poly/binomial.hpp"

#include <cmath>
#include <limits>

namespace hoct {

std::vector<double> to_monomial(const BernsteinTriangle &p) {
  const int d = p.degree();
  std::vector<double> mono((d + 1) * (d + 1), 0.0);
  for (int b = 0; b <= d; ++b)
    for (int a = 0; a + b <= d; ++a) {
      const int k = d - a - b;
      const double c = p.coefficient(a, b) * trinomial(k, a, b);
      // (1-u-v)^k = sum_{x+y<=k} k!/(x! y! (k-x-y)!) (-1)^(x+y) u^x v^y
      for (int y = 0; y <= k; ++y)
        for (int x = 0; x + y <= k; ++x) {
          const double w = trinomial(k - x - y, x, y) * (((x + y) & 1) ? -1.0 : 1.0);
          mono[(a + x) * (d + 1) + (b + y)] += c * w;
        }
    }
  return mono;
}

std::pair<double, double> monomial_range(const std::vector<double> &mono, int d, double x, double y,
                                         double rx, double ry) {
  // Taylor coefficients e_ab = sum_{i>=a, j>=b} m_ij C(i,a) C(j,b) x^(i-a) y^(j-b), with powers
  // and binomials from small tables (this runs in the inner loop of the Krawczyk test).
  constexpr int kMax = 32;
  if (d >= kMax)
    return {-INFINITY, INFINITY};
  double px[kMax], py[kMax], prx[kMax], pry[kMax], binom[kMax][kMax];
  for (int i = 0; i <= d; ++i)
    for (int a = 0; a <= i; ++a)
      binom[i][a] = binomial(i, a);
  px[0] = py[0] = prx[0] = pry[0] = 1;
  for (int i = 1; i <= d; ++i) {
    px[i] = px[i - 1] * x;
    py[i] = py[i - 1] * y;
    prx[i] = prx[i - 1] * rx;
    pry[i] = pry[i - 1] * ry;
  }
  double centre = 0, spread = 0, magnitude = 0;
  for (int a = 0; a <= d; ++a)
    for (int b = 0; a + b <= d; ++b) {
      double e = 0;
      for (int i = a; i <= d; ++i) {
        const double ci = binom[i][a] * px[i - a];
        const double *row = &mono[static_cast<std::size_t>(i) * (d + 1)];
        for (int j = b; i + j <= d; ++j) {
          const double term = row[j] * ci * binom[j][b] * py[j - b];
          e += term;
          magnitude += std::abs(term);
        }
      }
      if (a == 0 && b == 0)
        centre = e;
      else
        spread += std::abs(e) * prx[a] * pry[b];
    }
  const double round = 64 * std::numeric_limits<double>::epsilon() * magnitude;
  return {centre - spread - round, centre + spread + round};
}

} // namespace hoct
