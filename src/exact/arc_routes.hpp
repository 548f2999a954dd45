// Rank 0's side of drawing a partitioned mesh's arcs (exact/piece_arcs): from every piece's
// report of its components, the route of each arc through the fewest components, as the
// stretches the pieces draw; then the stretches drawn, joined end to end into paths.
#pragma once

#include "exact/arc_records.hpp"
#include "util/vec.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// 3. From every piece's component_report (by piece), the stretches each piece draws (by
// piece): the route through the fewest components from one holding the lower end to one
// holding the upper end; routed[k] set for the arcs which[k] that have one.
std::vector<std::vector<Stretch>> route_arcs(std::span<const std::vector<std::byte>> reports,
                                             std::span<const int64_t> which,
                                             std::span<const ArcEnds> arcs,
                                             std::vector<uint8_t> &routed);

// The stretches of all pieces (their draw_stretches bytes) joined into paths[arc] (the arcs
// routed this round; each path was empty).
void join_stretches(std::span<const std::vector<std::byte>> drawn,
                    std::vector<std::vector<Vec3>> &paths);

// Stretches as bytes, and back (a piece's share of route_arcs' answer).
std::vector<std::byte> encode_stretches(std::span<const Stretch> stretches);
std::vector<Stretch> decode_stretches(std::span<const std::byte> bytes);

} // namespace hoct
