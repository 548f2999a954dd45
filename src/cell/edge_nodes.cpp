#include "cell/edge_nodes.hpp"

#include "poly/root_isolation.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {

EdgeNodes find_edge_nodes(const Topology &topo, const Field &field, const EdgeNodeOptions &opt) {
  const int64_t ne = topo.num_edges();
  EdgeNodes out;
  out.offset.assign(ne + 1, 0);
  out.degeneracy.assign(ne, kEdgeOk);
  const double value_scale = std::max({std::abs(field.min_value()), std::abs(field.max_value()),
                                       field.max_value() - field.min_value(), 1e-300});
  for (int64_t e = 0; e < ne; ++e) {
    const BernsteinPoly p = field.edge_polynomial(e);
    const BernsteinPoly dp = p.derivative(), ddp = dp.derivative();
    uint8_t deg = kEdgeOk;
    if (p.degree() >= 1) {
      bool zero = false;
      // A constant edge (derivative zero up to rounding of the values).
      double dscale = 0, pscale = 0;
      for (double c : dp.coefficients())
        dscale = std::max(dscale, std::abs(c));
      for (double c : p.coefficients())
        pscale = std::max(pscale, std::abs(c));
      if (dscale <= 1e-12 * pscale)
        zero = true;
      if (zero) {
        deg |= kEdgeConstant;
      } else {
        for (const Root &r : find_roots(dp)) {
          if (r.t <= opt.vertex_tolerance || r.t >= 1 - opt.vertex_tolerance) {
            deg |= kEdgeRootAtVertex;
            continue; // the vertex itself is the node
          }
          const double second = ddp(r.t);
          if (!r.simple)
            deg |= kEdgeMultipleRoot;
          else if (std::abs(second) <= opt.flat_tolerance * value_scale)
            deg |= kEdgeFlatCriticalPoint;
          out.nodes.push_back({r.t, p(r.t), second, r.simple});
        }
      }
    }
    out.degeneracy[e] = deg;
    out.offset[e + 1] = static_cast<int64_t>(out.nodes.size());
  }
  return out;
}

} // namespace hoct
