#include "poly/sample_fit.hpp"

#include "poly/binomial.hpp"
#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

namespace hoct {

BernsteinTriangle bernstein_from_samples(const std::vector<Vec2> &positions,
                                         const std::vector<double> &values, int degree,
                                         const SampleFitOptions &options) {
  const int n = lattice_size(degree);
  const int m = static_cast<int>(positions.size());
  if (degree < 1)
    throw Error("sample fit: degree must be >= 1");
  if (static_cast<int>(values.size()) != m)
    throw Error("sample fit: " + std::to_string(m) + " positions but " +
                std::to_string(values.size()) + " values");
  if (m < n)
    throw Error("sample fit: a degree-" + std::to_string(degree) + " polynomial needs " +
                std::to_string(n) + " samples, got " + std::to_string(m));
  Eigen::MatrixXd v(m, n);
  Eigen::VectorXd f(m);
  for (int i = 0; i < m; ++i) {
    const auto l = barycentric(positions[i][0], positions[i][1]);
    if (!std::isfinite(values[i]) || !std::isfinite(l[1]) || !std::isfinite(l[2]))
      throw Error("sample fit: sample " + std::to_string(i) + " is not finite");
    f(i) = values[i];
    for (int j = 0; j < n; ++j) {
      const auto q = lattice_point(degree, j);
      const int a = q[0], b = q[1], k = degree - a - b;
      v(i, j) = trinomial(k, a, b) * std::pow(l[0], k) * std::pow(l[1], a) * std::pow(l[2], b);
    }
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(v, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto &s = svd.singularValues();
  const double cond = s(n - 1) > 0 ? s(0) / s(n - 1) : INFINITY;
  if (!(cond <= options.max_condition)) {
    std::ostringstream msg;
    msg << "sample fit: the " << m << " sample positions do not determine a degree-" << degree
        << " polynomial (condition number " << cond << " > " << options.max_condition
        << "; samples coincide or lie on a curve of degree <= " << degree << ")";
    throw Error(msg.str());
  }
  Eigen::VectorXd c = svd.solve(f);
  if (m > n) {
    const double range = f.maxCoeff() - f.minCoeff();
    const double residual = (v * c - f).cwiseAbs().maxCoeff();
    if (residual > options.max_relative_residual * std::max(range, 1e-300)) {
      std::ostringstream msg;
      msg << "sample fit: the samples are not values of a degree-" << degree
          << " polynomial (least-squares residual " << residual << ", value range " << range << ")";
      throw Error(msg.str());
    }
  }
  return BernsteinTriangle(degree, std::vector<double>(c.data(), c.data() + n));
}

} // namespace hoct
