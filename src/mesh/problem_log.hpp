// A bounded record of the problems found in a mesh: every occurrence is counted by kind, and the
// first few messages of each kind are kept, so millions of bad cells do not flood the output.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace hoct {

enum class Severity { Warning, Error };

// Every kind of problem the mesh build reports, in the order of their names (the summary's).
enum class Problem : uint8_t {
  BadCell,
  BadSampleSet,
  CoordinateOutOfRange,
  RepeatedCorner,
  RepeatedEdge,
  ZeroArea,
  DiscontinuousEdge,
  DiscontinuousVertex,
  DuplicateVertices,
  EmptyMesh,
  GeometricGap,
  InconsistentArrays,
  InconsistentNodes,
  InvertedCell,
  FoldedCell,
  MissingNode,
  NonFiniteCoordinate,
  NonFiniteValue,
  NonManifoldEdge,
  NonManifoldVertex,
  NonOrientable,
  UnsupportedDegree,
  ValueOutOfRange,
  ValueRangeTooSmall,
};

struct ProblemInfo {
  const char *name; // as reports print it, e.g. "non-manifold edge"
  Severity severity;
  // A contour tree is still well defined past it (hoct tree --force): the algorithm works in
  // each cell's reference triangle, so inverted or folded cells do not change the field's tree,
  // unmerged duplicate vertices only cut the surface along cracks, and a gap between cells
  // (a curved edge next to a straight one) leaves the cells' shared edge one edge of the field.
  bool forceable;
};
const ProblemInfo &problem_info(Problem p);
inline const char *to_string(Problem p) { return problem_info(p).name; }

struct ProblemRecord {
  Severity severity = Severity::Error;
  int64_t count = 0;
  std::vector<std::string> examples; // at most ProblemLog::kMaxExamples
};

class ProblemLog {
public:
  static constexpr int kMaxExamples = 5;

  void add(Problem kind, const std::string &message);
  // Adds everything `later` recorded, as if its add calls had come after this log's: logs kept
  // per block of a parallel loop and appended in block order equal one serial log.
  void append(const ProblemLog &later);
  // The same for one kind's record (a log sent from another process).
  void append(Problem kind, const ProblemRecord &record);
  // Forgets every problem of this kind.
  void erase(Problem kind) { kinds_.erase(kind); }
  bool has_errors() const;
  bool empty() const { return kinds_.empty(); }
  int64_t count(Problem kind) const;
  const std::map<Problem, ProblemRecord> &kinds() const { return kinds_; }
  // Rewrites every kept message (e.g. to name the input's cells instead of the mesh's).
  void rewrite_examples(const std::function<std::string(const std::string &)> &rewrite);
  // Multi-line human-readable summary ("error: 3 x non-manifold edge ..."), errors first.
  std::string summary() const;

private:
  std::map<Problem, ProblemRecord> kinds_;
};

// Problems found by the blocks of a parallel loop, one log per block, appended in block order:
// with fixed blocks (problem_blocks), the same report on any thread count.
class BlockProblems {
public:
  explicit BlockProblems(int64_t blocks) : logs_(static_cast<std::size_t>(blocks)) {}
  ProblemLog &operator[](int64_t b) { return logs_[static_cast<std::size_t>(b)]; }
  void append_to(ProblemLog &problems) const {
    for (const ProblemLog &log : logs_)
      problems.append(log);
  }

private:
  std::vector<ProblemLog> logs_;
};

// Fixed blocks for a loop over n items whose problems are reported: at most 256, of at least
// 4096 items each.
inline int64_t problem_blocks(int64_t n) {
  return n / 4096 < 1 ? 1 : n / 4096 > 256 ? 256 : n / 4096;
}

} // namespace hoct
