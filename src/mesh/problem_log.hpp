// A bounded record of the problems found in a mesh: every occurrence is counted by kind, and the
// first few messages of each kind are kept, so millions of bad cells do not flood the output.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace hoct {

enum class Severity { Warning, Error };

struct ProblemKind {
  Severity severity = Severity::Error;
  int64_t count = 0;
  std::vector<std::string> examples; // at most ProblemLog::kMaxExamples
};

class ProblemLog {
public:
  static constexpr int kMaxExamples = 5;

  void add(const std::string &kind, Severity severity, const std::string &message);
  bool has_errors() const;
  bool empty() const { return kinds_.empty(); }
  int64_t count(const std::string &kind) const;
  const std::map<std::string, ProblemKind> &kinds() const { return kinds_; }
  // Multi-line human-readable summary ("error: 3 non-manifold edge(s): ..."), errors first.
  std::string summary() const;

private:
  std::map<std::string, ProblemKind> kinds_;
};

} // namespace hoct
