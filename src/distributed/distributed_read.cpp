#include "distributed/distributed_read.hpp"

#include "io/pvtu_reader.hpp"

namespace hoct {

RankRead read_pvtu_by_ranks(const std::string &path, const FieldSelection &field,
                            const ReadLimits &limits, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  std::vector<FilePiece> pieces;
  std::string failure;
  try {
    const PvtuListing listing = list_pvtu(path, field);
    const std::size_t P = listing.files.size();
    const std::size_t first = P * static_cast<std::size_t>(rank) / static_cast<std::size_t>(ranks);
    const std::size_t last =
        P * static_cast<std::size_t>(rank + 1) / static_cast<std::size_t>(ranks);
    ReadLimits budget = limits;
    for (std::size_t k = first; k < last; ++k) {
      pieces.push_back(read_pvtu_piece(listing, k, field, budget));
      const MeshInput &in = pieces.back().input;
      budget.prior_points += in.points.size();
      budget.prior_cells += in.num_cells();
      budget.prior_cell_nodes += in.cell_nodes.size();
    }
  } catch (const std::exception &e) {
    failure = e.what();
  }
  RankRead read = join_rank_pieces(std::move(pieces), failure, path, limits, comm);
  if (read.input) // collective: rank 0 reads the whole file alone
    read.input->read_whole = [path, field, limits, rank] {
      return rank == 0 ? read_pvtu(path, field, limits) : MeshInput{};
    };
  return read;
}

} // namespace hoct
