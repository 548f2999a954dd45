// Unrolled code for the common low degrees: dispatch_degree(d, f) calls f with
// std::integral_constant<int, d> when 0 <= d <= 8 (so that loops over the degree have constant
// trip counts the compiler unrolls), else with std::integral_constant<int, -1> (run-time degree).
// The callee reads its degree as `D >= 0 ? D : d`.
#pragma once

#include <type_traits>

namespace hoct {

template <class F> decltype(auto) dispatch_degree(int d, F &&f) {
  switch (d) {
  case 0:
    return f(std::integral_constant<int, 0>{});
  case 1:
    return f(std::integral_constant<int, 1>{});
  case 2:
    return f(std::integral_constant<int, 2>{});
  case 3:
    return f(std::integral_constant<int, 3>{});
  case 4:
    return f(std::integral_constant<int, 4>{});
  case 5:
    return f(std::integral_constant<int, 5>{});
  case 6:
    return f(std::integral_constant<int, 6>{});
  case 7:
    return f(std::integral_constant<int, 7>{});
  case 8:
    return f(std::integral_constant<int, 8>{});
  default:
    return f(std::integral_constant<int, -1>{});
  }
}

} // namespace hoct
