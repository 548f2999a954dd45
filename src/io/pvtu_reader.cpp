#include "io/pvtu_reader.hpp"

#include "io/collection_xml.hpp"
#include "io/piece_join.hpp"
#include "io/vtu_reader.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <map>

namespace hoct {

namespace fs = std::filesystem;

PvtuListing list_pvtu(const std::string &path, const FieldSelection &field) {
  if (!field.default_step())
    throw InputError(path + ": --step / --time: a .pvtu file holds one time step (a .pvd "
                            "collection lists several)");
  CollectionXml xml;
  load_collection_xml(path, "PUnstructuredGrid", xml);
  const pugi::xml_node grid = xml.element;
  if (const pugi::xml_attribute g = grid.attribute("GhostLevel")) {
    const char *s = g.as_string();
    int level = -1;
    const auto r = std::from_chars(s, s + std::strlen(s), level);
    if (r.ec != std::errc() || *r.ptr != '\0' || level < 0)
      throw InputError(path + ": GhostLevel '" + std::string(s) +
                       "' is not a number of ghost layers (0, 1, ...)");
  }
  // The ids array the pieces share, as the parallel writer declares it.
  const std::string ids_name = grid.child("PPointData").attribute("GlobalIds").as_string();
  std::vector<std::string> files;
  std::map<std::string, int> seen;
  for (const pugi::xml_node piece : grid.children("Piece")) {
    const std::string what = "piece " + std::to_string(files.size()) + " Source";
    const std::string file =
        collection_member(path, piece.attribute("Source").as_string(), what, ".vtu");
    const auto [it, fresh] = seen.emplace(file, static_cast<int>(files.size()));
    if (!fresh)
      throw InputError(path + ": pieces " + std::to_string(it->second) + " and " +
                       std::to_string(files.size()) + " are both " + file +
                       " (a piece read twice would overlap itself)");
    files.push_back(file);
  }
  if (files.empty())
    throw InputError(path + ": no <Piece> in <PUnstructuredGrid>: the partitioned grid lists no "
                            "piece files");
  return PvtuListing{path, std::move(files), ids_name};
}

FilePiece read_pvtu_piece(const PvtuListing &listing, std::size_t k, const FieldSelection &field,
                          const ReadLimits &budget) {
  FilePiece p;
  p.file = listing.files[k];
  try {
    p.input = read_vtu_piece(p.file, field, budget,
                             {.global_ids_name = listing.ids_name, .allow_empty = true}, p.arrays);
  } catch (const InputError &e) {
    throw InputError(listing.path + ": piece " + std::to_string(k) + " of " +
                     std::to_string(listing.files.size()) + ": " + e.what());
  }
  return p;
}

MeshInput read_pvtu(const std::string &path, const FieldSelection &field,
                    const ReadLimits &limits) {
  const PvtuListing listing = list_pvtu(path, field);
  std::vector<FilePiece> pieces(listing.files.size());
  ReadLimits budget = limits; // each piece's counts checked with those read before
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    pieces[k] = read_pvtu_piece(listing, k, field, budget);
    const MeshInput &in = pieces[k].input;
    budget.prior_points += in.points.size();
    budget.prior_cells += in.num_cells();
    budget.prior_cell_nodes += in.cell_nodes.size();
  }
  return join_pieces(std::move(pieces), path, /*by_ids=*/true, limits.threads);
}

std::string find_listing_pvtu(const std::string &vtu_path) {
  // Collections are small and few beside their pieces; a directory of many is not searched.
  constexpr std::size_t kMaxCollections = 1000;
  constexpr uintmax_t kMaxBytes = 1u << 20;
  const fs::path given(vtu_path);
  const fs::path dir = given.parent_path();
  std::error_code ec;
  std::vector<fs::path> candidates;
  for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end;
       it.increment(ec)) {
    const fs::path &p = it->path();
    if (lowercase_extension(p.string()) != ".pvtu")
      continue;
    if (candidates.size() == kMaxCollections)
      return "";
    candidates.push_back(p);
  }
  std::sort(candidates.begin(), candidates.end());
  for (const fs::path &p : candidates) {
    std::error_code size_ec;
    const uintmax_t size = fs::file_size(p, size_ec);
    if (size_ec || size > kMaxBytes)
      continue;
    pugi::xml_document doc;
    if (!doc.load_file(p.c_str()))
      continue;
    for (const pugi::xml_node piece :
         doc.child("VTKFile").child("PUnstructuredGrid").children("Piece")) {
      const fs::path source(piece.attribute("Source").as_string());
      if (source.empty() || source.is_absolute())
        continue;
      std::error_code eq;
      if (fs::equivalent(p.parent_path() / source, given, eq))
        return (dir / p.filename()).string();
    }
  }
  return "";
}

std::string lone_piece_warning(const std::string &vtu_path, int64_t ghost_cells,
                               int64_t ghost_points) {
  const std::string pvtu = find_listing_pvtu(vtu_path);
  const std::string ghosts = ghost_cells > 0 ? "ghost cells: " + std::to_string(ghost_cells) +
                                                   ", copies of its neighbours' cells, kept"
                                             : "ghost points: " + std::to_string(ghost_points);
  return vtu_path + " holds one piece of a partitioned output (it has " + ghosts +
         "); its tree is that piece's, not the whole domain's: read " +
         (pvtu.empty() ? std::string("the .pvtu that lists its pieces") : pvtu) + " for the whole";
}

} // namespace hoct
