// The records of drawing a partitioned mesh's arcs (exact/piece_arcs, exact/arc_routes): the
// arcs every piece is given, the rounds, and what the pieces and rank 0 send each other.
#pragma once

#include "exact/piece_trees.hpp"

#include <array>
#include <cstdint>

namespace hoct {

// An arc of the whole tree: its lower and upper end and their values (relative). Parallel arcs
// (a Reeb graph's loops) have a group (else -1) and a level in it: each is drawn avoiding the
// graph nodes of its group's lower levels' paths, as one process draws them.
struct ArcEnds {
  NodeKey lo_key, hi_key;
  double lo = 0, hi = 0;
  int32_t group = -1, level = 0;
};

// The rounds, in order: within the arc's values, below the upper one, above the lower one,
// anywhere.
enum class ArcRound : int32_t { Band = 0, Below = 1, Above = 2, Anywhere = 3 };
constexpr int kArcRounds = 4;

// One of a piece's components touching a neighbour's (their component), at node `witness`: a
// record of component_report's bytes.
struct ComponentTouch {
  NodeKey witness;
  int32_t piece = 0, theirs = 0, mine = 0, unused = 0;
};

// A piece's stretch of an arc: its place in the arc's route, and the keys it runs between.
struct Stretch {
  int64_t arc = 0;
  int32_t step = 0, steps = 0;
  NodeKey from, to;
};

// The values a round's paths stay within.
std::array<double, 2> round_values(const ArcEnds &arc, ArcRound round);

} // namespace hoct
