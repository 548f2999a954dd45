#include "mesh/problem_log.hpp"

#include <sstream>

namespace hoct {

void ProblemLog::add(const std::string &kind, Severity severity, const std::string &message) {
  auto &k = kinds_[kind];
  if (k.count == 0 || severity == Severity::Error)
    k.severity = severity;
  ++k.count;
  if (static_cast<int>(k.examples.size()) < kMaxExamples)
    k.examples.push_back(message);
}

void ProblemLog::append(const ProblemLog &later) {
  for (const auto &[name, l] : later.kinds_) {
    auto &k = kinds_[name];
    if (k.count == 0 || l.severity == Severity::Error)
      k.severity = l.severity;
    k.count += l.count;
    for (std::size_t i = 0; i < l.examples.size() && k.examples.size() < kMaxExamples; ++i)
      k.examples.push_back(l.examples[i]);
  }
}

bool ProblemLog::has_errors() const {
  for (const auto &[name, k] : kinds_)
    if (k.severity == Severity::Error)
      return true;
  return false;
}

int64_t ProblemLog::count(const std::string &kind) const {
  auto it = kinds_.find(kind);
  return it == kinds_.end() ? 0 : it->second.count;
}

std::string ProblemLog::summary() const {
  std::ostringstream out;
  for (Severity pass : {Severity::Error, Severity::Warning})
    for (const auto &[name, k] : kinds_) {
      if (k.severity != pass)
        continue;
      out << (pass == Severity::Error ? "error" : "warning") << ": " << k.count << " x " << name
          << "\n";
      for (const auto &e : k.examples)
        out << "    " << e << "\n";
      if (k.count > static_cast<int64_t>(k.examples.size()))
        out << "    ... and " << (k.count - static_cast<int64_t>(k.examples.size())) << " more\n";
    }
  return out.str();
}

} // namespace hoct
