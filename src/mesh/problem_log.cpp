#include "mesh/problem_log.hpp"

#include <sstream>

namespace hoct {

const ProblemInfo &problem_info(Problem p) {
  static constexpr ProblemInfo kTable[] = {
      {"bad cell", Severity::Error, false},
      {"bad sample set", Severity::Error, false},
      {"coordinate out of range", Severity::Error, false},
      {"degenerate cell (repeated corner)", Severity::Error, false},
      {"degenerate cell (repeated edge)", Severity::Error, false},
      {"degenerate cell (zero area)", Severity::Error, false},
      {"discontinuous field across an edge", Severity::Error, false},
      {"discontinuous field at a vertex", Severity::Error, false},
      {"duplicate vertices", Severity::Error, true},
      {"empty mesh", Severity::Error, false},
      {"gap between cells (their shared edge differs)", Severity::Error, true},
      {"inconsistent arrays", Severity::Error, false},
      {"inconsistent nodes", Severity::Error, false},
      {"inverted cell", Severity::Error, true},
      {"inverted cell (folded curved cell)", Severity::Error, true},
      {"missing node", Severity::Error, false},
      {"non-finite point coordinate", Severity::Error, false},
      {"non-finite value", Severity::Error, false},
      {"non-manifold edge", Severity::Error, false},
      {"non-manifold vertex", Severity::Error, false},
      {"non-orientable surface", Severity::Warning, false},
      {"unsupported degree", Severity::Error, false},
      {"value out of range", Severity::Error, false},
      {"value range too small", Severity::Error, false},
  };
  return kTable[static_cast<int>(p)];
}

void ProblemLog::add(Problem kind, const std::string &message) {
  auto &k = kinds_[kind];
  k.severity = problem_info(kind).severity;
  ++k.count;
  if (static_cast<int>(k.examples.size()) < kMaxExamples)
    k.examples.push_back(message);
}

void ProblemLog::append(const ProblemLog &later) {
  for (const auto &[kind, l] : later.kinds_) {
    auto &k = kinds_[kind];
    k.severity = l.severity;
    k.count += l.count;
    for (std::size_t i = 0; i < l.examples.size() && k.examples.size() < kMaxExamples; ++i)
      k.examples.push_back(l.examples[i]);
  }
}

void ProblemLog::append(Problem kind, const ProblemRecord &l) {
  auto &k = kinds_[kind];
  k.severity = l.severity;
  k.count += l.count;
  for (std::size_t i = 0; i < l.examples.size() && k.examples.size() < kMaxExamples; ++i)
    k.examples.push_back(l.examples[i]);
}

void ProblemLog::rewrite_examples(const std::function<std::string(const std::string &)> &rewrite) {
  for (auto &[kind, k] : kinds_)
    for (std::string &e : k.examples)
      e = rewrite(e);
}

bool ProblemLog::has_errors() const {
  for (const auto &[kind, k] : kinds_)
    if (k.severity == Severity::Error)
      return true;
  return false;
}

int64_t ProblemLog::count(Problem kind) const {
  auto it = kinds_.find(kind);
  return it == kinds_.end() ? 0 : it->second.count;
}

std::string ProblemLog::summary() const {
  std::ostringstream out;
  for (Severity pass : {Severity::Error, Severity::Warning})
    for (const auto &[kind, k] : kinds_) {
      if (k.severity != pass)
        continue;
      out << (pass == Severity::Error ? "error" : "warning") << ": " << k.count << " x "
          << to_string(kind) << "\n";
      for (const auto &e : k.examples)
        out << "    " << e << "\n";
      if (k.count > static_cast<int64_t>(k.examples.size()))
        out << "    ... and " << (k.count - static_cast<int64_t>(k.examples.size())) << " more\n";
    }
  return out.str();
}

} // namespace hoct
