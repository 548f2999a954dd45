#include "study_writers.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_xml_arrays.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace hoct {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

} // namespace

void write_study_csv(const std::string &path, const std::vector<StudyRow> &rows) {
  std::ostringstream s;
  s << "method,k,triangles,minima,maxima,saddles,bottleneck,mean_distance,max_distance,missed,"
       "spurious,seconds\n";
  for (const auto &r : rows)
    s << (r.k == 0 ? "exact" : "pl") << ',' << r.k << ',' << r.triangles << ',' << r.counts[0]
      << ',' << r.counts[1] << ',' << r.counts[2] << ',' << num(r.bottleneck) << ','
      << num(r.mean_distance) << ',' << num(r.max_distance) << ',' << r.missed << ',' << r.spurious
      << ',' << num(r.seconds) << '\n';
  const std::string text = s.str();
  write_file_atomic(
      path, [&](std::ostream &out) { out << text; }, false);
}

void write_study_json(const std::string &path, const std::vector<StudyRow> &rows,
                      const std::string &input, double threshold) {
  nlohmann::ordered_json j;
  j["input"] = input;
  j["feature_threshold"] = threshold;
  nlohmann::ordered_json arr = nlohmann::ordered_json::array();
  for (const auto &r : rows)
    arr.push_back({{"method", r.k == 0 ? "exact" : "pl"},
                   {"k", r.k},
                   {"triangles", r.triangles},
                   {"minima", r.counts[0]},
                   {"maxima", r.counts[1]},
                   {"saddles", r.counts[2]},
                   {"bottleneck", r.bottleneck},
                   {"mean_distance", r.mean_distance},
                   {"max_distance", r.max_distance},
                   {"missed", r.missed},
                   {"spurious", r.spurious},
                   {"seconds", r.seconds}});
  j["rows"] = arr;
  const std::string text = j.dump(2);
  write_file_atomic(
      path, [&](std::ostream &out) { out << text << "\n"; }, false);
}

void write_study_svg(const std::string &path, const std::vector<StudyRow> &rows,
                     const std::string &title) {
  // Two panels sharing a logarithmic x axis (triangles): the bottleneck distance (log scale),
  // and the missed and spurious features.
  std::vector<const StudyRow *> pl;
  for (const auto &r : rows)
    if (r.k > 0)
      pl.push_back(&r);
  const double W = 760, H = 620, left = 80, right = 30, top = 60, gap = 60;
  const double panel = (H - top - gap - 50) / 2;
  double tmin = rows.empty() ? 1 : static_cast<double>(rows[0].triangles), tmax = tmin;
  double emin = INFINITY, emax = 0, fmax = 1;
  for (const auto *r : pl) {
    tmin = std::min(tmin, static_cast<double>(r->triangles));
    tmax = std::max(tmax, static_cast<double>(r->triangles));
    if (r->bottleneck > 0) {
      emin = std::min(emin, r->bottleneck);
      emax = std::max(emax, r->bottleneck);
    }
    fmax = std::max(fmax, static_cast<double>(std::max(r->missed, r->spurious)));
  }
  if (!(emin < INFINITY)) {
    emin = 1e-6;
    emax = 1;
  }
  const double lx0 = std::floor(std::log10(tmin)), lx1 = std::ceil(std::log10(tmax) + 1e-9);
  const double ly0 = std::floor(std::log10(emin)), ly1 = std::ceil(std::log10(emax) + 1e-9);
  auto X = [&](double t) {
    return left + (std::log10(t) - lx0) / std::max(lx1 - lx0, 1.0) * (W - left - right);
  };
  auto YE = [&](double e) {
    return top + (ly1 - std::log10(e)) / std::max(ly1 - ly0, 1.0) * panel;
  };
  const double top2 = top + panel + gap;
  auto YF = [&](double f) { return top2 + (1 - f / fmax) * panel; };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
       "fill=\"white\"/>\n<text x=\""
    << left << "\" y=\"28\" font-size=\"15\">" << xml_escape(title) << "</text>\n";
  auto frame = [&](double y0, const std::string &label) {
    s << "<rect x=\"" << left << "\" y=\"" << y0 << "\" width=\"" << W - left - right
      << "\" height=\"" << panel << "\" fill=\"none\" stroke=\"#444\"/>\n<text x=\"" << left
      << "\" y=\"" << y0 - 8 << "\">" << label << "</text>\n";
    for (double e = lx0; e <= lx1; ++e)
      s << "<line x1=\"" << X(std::pow(10, e)) << "\" y1=\"" << y0 + panel << "\" x2=\""
        << X(std::pow(10, e)) << "\" y2=\"" << y0 + panel + 5 << "\" stroke=\"#444\"/><text x=\""
        << X(std::pow(10, e)) << "\" y=\"" << y0 + panel + 18 << "\" text-anchor=\"middle\">1e" << e
        << "</text>\n";
  };
  frame(top, "bottleneck distance, exact vs PL (log scale)");
  for (double e = ly0; e <= ly1; ++e)
    s << "<text x=\"" << left - 6 << "\" y=\"" << YE(std::pow(10, e)) + 4
      << "\" text-anchor=\"end\">1e" << e << "</text>\n";
  frame(top2, "features missed (red, solid) and spurious (orange, dashed)");
  for (int k = 0; k <= 4; ++k)
    s << "<text x=\"" << left - 6 << "\" y=\"" << YF(fmax * k / 4) + 4 << "\" text-anchor=\"end\">"
      << num(fmax * k / 4) << "</text>\n";
  auto series = [&](auto value, auto Y, const char *colour, const char *dash = "none") {
    s << "<polyline fill=\"none\" stroke=\"" << colour
      << "\" stroke-width=\"2\" stroke-dasharray=\"" << dash << "\" points=\"";
    for (const auto *r : pl)
      s << X(static_cast<double>(r->triangles)) << ',' << Y(value(*r)) << ' ';
    s << "\"/>\n";
    for (const auto *r : pl)
      s << "<circle cx=\"" << X(static_cast<double>(r->triangles)) << "\" cy=\"" << Y(value(*r))
        << "\" r=\"4\" fill=\"" << colour << "\"><title>k=" << r->k << ", " << r->triangles
        << " triangles: " << num(value(*r)) << "</title></circle>\n";
  };
  // The log-scale panel shows the levels with a non-zero error only.
  std::vector<const StudyRow *> positive;
  for (const auto *r : pl)
    if (r->bottleneck > 0)
      positive.push_back(r);
  std::swap(pl, positive);
  series([](const StudyRow &r) { return r.bottleneck; }, YE, "#1f77b4");
  std::swap(pl, positive);
  series([](const StudyRow &r) { return static_cast<double>(r.missed); }, YF, "#d62728");
  series([](const StudyRow &r) { return static_cast<double>(r.spurious); }, YF, "#ff7f0e", "6,4");
  if (!rows.empty()) {
    const double x = X(static_cast<double>(rows[0].triangles));
    s << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << top2 + panel
      << "\" stroke=\"#2ca02c\" stroke-dasharray=\"5,4\"/>\n<text x=\"" << x + 5 << "\" y=\""
      << top + 14 << "\" fill=\"#2ca02c\">exact tree: " << rows[0].triangles
      << " cells, error 0</text>\n";
  }
  s << "<text x=\"" << (W + left) / 2 << "\" y=\"" << H - 8
    << "\" text-anchor=\"middle\">triangles of the PL approximation</text>\n</svg>\n";
  const std::string text = s.str();
  write_file_atomic(
      path, [&](std::ostream &out) { out << text; }, false);
}

} // namespace hoct
