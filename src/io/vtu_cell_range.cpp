#include "io/vtu_cell_range.hpp"

#include "io/vtk_cells.hpp"
#include "io/vtu_file.hpp"
#include "util/error.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

namespace hoct {
namespace vtu_detail {

bool VtuFile::open_for_ranges() {
  limits_.stream_appended_above = 0; // any size: the arrays are read by ranges
  return open_streamed();
}

template <class T>
PooledVector<T> VtuFile::read_array_range(const pugi::xml_node &a, std::size_t expected,
                                          std::size_t first, std::size_t count) const {
  if (a.attribute("format").as_string() != std::string("appended"))
    fail(describe(a) + " is not appended data");
  if (first > expected || count > expected - first)
    fail(describe(a) + ": values " + std::to_string(first) + " to " +
         std::to_string(first + count) + " are beyond its " + std::to_string(expected));
  const TypeInfo &ti = type_of(a);
  const uint64_t size = static_cast<uint64_t>(ti.size);
  const uint64_t offset = appended_offset(a, appended_length_);
  const uint64_t at = appended_begin_ + offset, avail = appended_length_ - offset;
  const int hs = header_size_;
  PooledVector<T> out;
  Payload raw;
  if (!compressed_) {
    value_count(a, ti, raw_array_bytes(at, avail, a), expected);
    constexpr Scalar native = std::is_same_v<T, double> ? Scalar::F64 : Scalar::I64;
    if (ti.type == native && big_endian_ == (std::endian::native == std::endian::big)) {
      resize_mapped(out, count); // straight from the file
      read_at(at + hs + first * size, count * sizeof(T), out.data());
      return out;
    }
    raw.owned.resize(static_cast<std::size_t>(count * size));
    read_at(at + hs + first * size, raw.owned.size(), raw.owned.data());
  } else {
    // The compression header (block count, block size, last block's size, compressed sizes),
    // checked as a whole array's is (decode_blocks), then the blocks over the range alone.
    if (avail < 3 * static_cast<uint64_t>(hs))
      fail(describe(a) + ": truncated compression header");
    uint8_t h[3 * 8];
    read_at(at, 3 * hs, h);
    const uint64_t nb = read_uint(h, hs, big_endian_), bs = read_uint(h + hs, hs, big_endian_),
                   last = read_uint(h + 2 * hs, hs, big_endian_);
    if (nb > avail / hs || (3 + nb) * hs > avail)
      fail(describe(a) + ": compression header claims " + std::to_string(nb) + " blocks");
    if (bs == 0 || bs > (uint64_t{1} << 31) || last > bs)
      fail(describe(a) + ": implausible compression header (block size " + std::to_string(bs) +
           ", last block " + std::to_string(last) + ")");
    std::vector<uint8_t> head(static_cast<std::size_t>((3 + nb) * hs));
    read_at(at, head.size(), head.data());
    std::vector<uint64_t> csize(nb), cstart(nb + 1, head.size());
    uint64_t out_size = 0;
    for (uint64_t b = 0; b < nb; ++b) {
      csize[b] = read_uint(head.data() + (3 + b) * hs, hs, big_endian_);
      const uint64_t want = (b + 1 == nb && last) ? last : bs;
      if (csize[b] > avail || want > kMaxZlibRatio * csize[b] + 64)
        fail(describe(a) + ": compressed block " + std::to_string(b) + " of " +
             std::to_string(csize[b]) + " bytes cannot hold " + std::to_string(want) + " bytes");
      cstart[b + 1] = cstart[b] + csize[b];
      out_size += want;
    }
    if (cstart[nb] > avail)
      fail(describe(a) + ": truncated binary data (the compressed blocks need " +
           std::to_string(cstart[nb]) + " bytes, " + std::to_string(avail) + " available)");
    if (out_size != expected * size)
      fail(describe(a) + " has " + std::to_string(out_size) + " bytes (as its compression header " +
           "declares), expected " + std::to_string(expected) + " " + ti.name + " values");
    if (count > 0) {
      const uint64_t lo = first * size, hi = (first + count) * size;
      const uint64_t b0 = lo / bs, b1 = (hi - 1) / bs;
      std::vector<uint8_t> packed(static_cast<std::size_t>(cstart[b1 + 1] - cstart[b0]));
      read_at(at + cstart[b0], packed.size(), packed.data());
      std::vector<uint8_t> inflated(static_cast<std::size_t>((b1 - b0 + 1) * bs));
      for (uint64_t b = b0; b <= b1; ++b) {
        const uint64_t want = (b + 1 == nb && last) ? last : bs;
        uLongf got = static_cast<uLongf>(want);
        const int rc =
            uncompress(inflated.data() + (b - b0) * bs, &got,
                       packed.data() + (cstart[b] - cstart[b0]), static_cast<uLong>(csize[b]));
        if (rc != Z_OK || got != want)
          fail(describe(a) + ": zlib error in block " + std::to_string(b) + " (" +
               (rc == Z_OK ? "wrong size" : zError(rc)) + ")");
      }
      raw.owned.assign(inflated.begin() + static_cast<std::ptrdiff_t>(lo - b0 * bs),
                       inflated.begin() + static_cast<std::ptrdiff_t>(hi - b0 * bs));
    }
  }
  raw.data = raw.owned.data();
  raw.size = raw.owned.size();
  convert_payload(raw, a, out);
  return out;
}

template <class T>
void VtuFile::read_range_into(const pugi::xml_node &a, std::size_t expected, std::size_t first,
                              std::size_t count, T *dst) const {
  constexpr Scalar native = std::is_same_v<T, double> ? Scalar::F64 : Scalar::I64;
  const TypeInfo &ti = type_of(a);
  if (compressed_ || ti.type != native ||
      big_endian_ != (std::endian::native == std::endian::big) ||
      a.attribute("format").as_string() != std::string("appended") || first > expected ||
      count > expected - first) {
    const PooledVector<T> v = read_array_range<T>(a, expected, first, count);
    std::copy(v.begin(), v.end(), dst);
    return;
  }
  const uint64_t offset = appended_offset(a, appended_length_);
  const uint64_t at = appended_begin_ + offset;
  value_count(a, ti, raw_array_bytes(at, appended_length_ - offset, a), expected);
  read_at(at + header_size_ + first * sizeof(T), count * sizeof(T), dst);
}

std::optional<VtuCellRange> VtuFile::read_cell_range(int part, int parts, std::string &why) {
  load();
  const pugi::xml_node grid = single_child(doc_.child("VTKFile"), "UnstructuredGrid");
  if (!grid)
    fail("no <UnstructuredGrid> element");
  // One piece with points or cells (empty ones are skipped, as read_vtu skips them).
  pugi::xml_node piece;
  int index = 0, piece_index = 0;
  for (auto p : grid.children("Piece")) {
    const long long np = parse_count(p.attribute("NumberOfPoints"));
    const long long nc = parse_count(p.attribute("NumberOfCells"));
    if (np != 0 || nc != 0) {
      if (piece) {
        why = "it has more than one piece";
        return std::nullopt;
      }
      piece = p;
      piece_index = index;
    }
    ++index;
  }
  if (!piece) {
    why = "it has no piece with cells";
    return std::nullopt;
  }
  const std::string where = "piece " + std::to_string(piece_index);
  const long long np = parse_count(piece.attribute("NumberOfPoints"));
  const long long nc = parse_count(piece.attribute("NumberOfCells"));
  if (np < 0 || nc < 0)
    fail(where + ": missing or bad NumberOfPoints / NumberOfCells");
  if (static_cast<unsigned long long>(np) > file_size_ ||
      static_cast<unsigned long long>(nc) > file_size_)
    fail(where + ": NumberOfPoints / NumberOfCells exceed what the file can hold");
  int pc = 3;
  const pugi::xml_node pa = points_array(piece, where, pc);
  const pugi::xml_node pd = single_child(piece, "PointData");
  const pugi::xml_node cd = single_child(piece, "CellData");
  if (named_array(pd, "vtkGhostType") || named_array(cd, "vtkGhostType")) {
    why = "it has ghost arrays (a piece of a partitioned output)";
    return std::nullopt;
  }
  const char *weights = pd.attribute("RationalWeights").as_string();
  if (named_array(pd, *weights ? weights : "RationalWeights")) {
    why = "it has rational weights";
    return std::nullopt;
  }
  const pugi::xml_node sa = choose_field(pd, where);
  const auto [ca, oa, ta] = cell_arrays(piece, where);
  for (const pugi::xml_node &a : {pa, sa, ca, oa, ta})
    if (a.attribute("format").as_string() != std::string("appended")) {
      why = "its arrays are not all appended data";
      return std::nullopt;
    }

  VtuCellRange r;
  r.file_points = np;
  r.file_cells = nc;
  const int64_t b = nc * part / parts, e = nc * (part + 1) / parts;
  r.cell_begin = b;
  r.cell_end = e;
  MeshInput &m = r.input;
  m.source = path_;
  m.cell_offsets.assign(1, 0);
  // The cells: offsets [b - 1, e), the last one (the connectivity's length), types [b, e).
  const std::size_t ub = static_cast<std::size_t>(b), ue = static_cast<std::size_t>(e),
                    unc = static_cast<std::size_t>(nc);
  const int64_t nconn = nc ? read_array_range<int64_t>(oa, unc, unc - 1, 1)[0] : 0;
  if (nconn < 0 || static_cast<unsigned long long>(nconn) > file_size_)
    fail(where + ": the last cell offset " + std::to_string(nconn) + " is invalid");
  const std::size_t ob = b > 0 ? ub - 1 : ub;
  const PooledVector<int64_t> offsets = read_array_range<int64_t>(oa, unc, ob, ue - ob);
  const PooledVector<int64_t> types = read_array_range<int64_t>(ta, unc, ub, ue - ub);
  auto offset_before = [&](int64_t c) { return c > 0 ? offsets[c - 1 - ob] : int64_t{0}; };
  const int64_t c0 = offset_before(b), c1 = e > b ? offsets[ue - 1 - ob] : c0;
  if (c0 < 0 || c1 < c0 || c1 > nconn)
    fail(where + ": cells " + std::to_string(b) + " to " + std::to_string(e) +
         ": offsets out of order");
  check_memory(limits_, 0, static_cast<uint64_t>(e - b), static_cast<uint64_t>(c1 - c0),
               path_ + ": " + where);
  m.cell_nodes =
      read_array_range<int64_t>(ca, static_cast<std::size_t>(nconn), static_cast<std::size_t>(c0),
                                static_cast<std::size_t>(c1 - c0));
  // Each cell's ids put in lattice order in place (as read() does).
  m.cell_offsets.reserve(ue - ub + 1);
  m.cell_degree.reserve(ue - ub);
  std::string problem;
  int64_t *nodes = m.cell_nodes.data();
  int64_t write = 0;
  int64_t cell[kMaxVtkCellNodes];
  for (int64_t c = b; c < e; ++c) {
    const int64_t begin = offset_before(c), end = offsets[static_cast<std::size_t>(c) - ob];
    if (end < begin || end > c1) // (c1 <= nconn): within the connectivity read
      fail(where + ": cell " + std::to_string(c) + ": bad offsets (" + std::to_string(begin) +
           " then " + std::to_string(end) + ")");
    int degree = 0;
    CellKind kind = CellKind::LagrangeTriangle;
    const VtkCellResult res =
        vtk_cell_nodes(types[static_cast<std::size_t>(c - b)], nodes + (begin - c0), end - begin,
                       np, 0, cell, &degree, &kind, &problem);
    if (res == VtkCellResult::Invalid)
      fail(where + ": cell " + std::to_string(c) + problem);
    if (res == VtkCellResult::Skipped)
      continue;
    std::copy(cell, cell + (end - begin), nodes + write);
    write += end - begin;
    m.cell_offsets.push_back(write);
    m.cell_degree.push_back(static_cast<uint8_t>(degree));
    m.set_kind(m.cell_degree.size() - 1, kind);
  }
  m.cell_nodes.resize(static_cast<std::size_t>(write));

  // The points: the blocks of those the cells use and of this part's share of all, which it
  // checks; at most 65,536 blocks (what distributed/vtu_by_ranks gathers of every rank).
  r.check_begin = np * part / parts;
  r.check_end = np * (part + 1) / parts;
  const int64_t block = std::max<int64_t>(1024, (np + 65535) / 65536);
  const std::size_t blocks = static_cast<std::size_t>((np + block - 1) / block);
  r.point_block = block;
  r.block_first.assign(blocks, -1);
  for (const int64_t q : m.cell_nodes)
    r.block_first[static_cast<std::size_t>(q / block)] = 0;
  // Points numbered at random: the blocks hold several times the points the cells use (about
  // their share of the file's, np / nconn per connectivity entry), and the part would read most
  // of the file. It reads its checked share alone then.
  int64_t in_blocks = 0;
  for (std::size_t k = 0; k < blocks; ++k)
    if (r.block_first[k] == 0)
      in_blocks += std::min<int64_t>(block, np - static_cast<int64_t>(k) * block);
  const double uses = static_cast<double>(c1 - c0) * static_cast<double>(np) /
                      static_cast<double>(std::max<int64_t>(nconn, 1));
  if (static_cast<double>(in_blocks) > 3 * uses + 16 * static_cast<double>(block)) {
    r.used_points_read = false;
    std::fill(r.block_first.begin(), r.block_first.end(), -1);
  }
  if (r.check_end > r.check_begin)
    std::fill(r.block_first.begin() + r.check_begin / block,
              r.block_first.begin() + (r.check_end - 1) / block + 1, 0);
  int64_t n = 0;
  for (std::size_t k = 0; k < blocks; ++k)
    if (r.block_first[k] == 0) {
      r.block_first[k] = n;
      n += std::min<int64_t>(block, np - static_cast<int64_t>(k) * block);
    }
  check_memory(limits_, static_cast<uint64_t>(n), m.num_cells(), m.cell_nodes.size(),
               path_ + ": " + where);
  if (type_of(pa).type == Scalar::F32)
    m.coordinate_precision = 0x1p-24;
  const std::string field = field_.describe(sa.attribute("Name").as_string());
  m.field_name = field;
  if (type_of(sa).type == Scalar::F32)
    m.value_precision = 0x1p-24;
  const int comps = sa.attribute("NumberOfComponents").as_int(1);
  const std::size_t k = static_cast<std::size_t>(comps), unp = static_cast<std::size_t>(np);
  resize_mapped(m.points, static_cast<std::size_t>(n));
  resize_mapped(m.values, static_cast<std::size_t>(n));
  // Each run of consecutive blocks read at once.
  for (std::size_t b0 = 0; b0 < blocks;) {
    if (r.block_first[b0] < 0) {
      ++b0;
      continue;
    }
    std::size_t b1 = b0 + 1;
    while (b1 < blocks && r.block_first[b1] >= 0)
      ++b1;
    const std::size_t lo = b0 * static_cast<std::size_t>(block),
                      hi = std::min(unp, b1 * static_cast<std::size_t>(block)), count = hi - lo;
    const std::size_t at = static_cast<std::size_t>(r.block_first[b0]);
    static_assert(sizeof(Vec3) == 3 * sizeof(double));
    if (pc == 3) { // x, y, z as stored: straight into the points
      read_range_into<double>(pa, unp * 3, lo * 3, count * 3,
                              reinterpret_cast<double *>(m.points.data() + at));
    } else {
      const PooledVector<double> xy = read_array_range<double>(pa, unp * 2, lo * 2, count * 2);
      for (std::size_t i = 0; i < count; ++i)
        m.points[at + i] = {xy[i * 2], xy[i * 2 + 1], 0.0};
    }
    if (comps == 1) {
      read_range_into<double>(sa, unp, lo, count, m.values.data() + at);
    } else { // one component, or the magnitude, of a vector array
      const PooledVector<double> all = read_array_range<double>(sa, unp * k, lo * k, count * k);
      for (std::size_t i = 0; i < count; ++i) {
        const double *v = all.data() + i * k;
        if (field_.component >= 0) {
          m.values[at + i] = v[field_.component];
        } else {
          double sum = 0;
          for (std::size_t j = 0; j < k; ++j)
            sum += v[j] * v[j];
          m.values[at + i] = std::sqrt(sum);
        }
      }
    }
    b0 = b1;
  }
  for (int64_t i = r.check_begin; i < r.check_end; ++i) {
    const Vec3 &p = m.points[static_cast<std::size_t>(r.point_index(i))];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(where + ": point " + std::to_string(i) + " has a NaN or infinite coordinate");
  }
  for (int64_t i = r.check_begin; i < r.check_end; ++i)
    if (!std::isfinite(m.values[static_cast<std::size_t>(r.point_index(i))]))
      fail(where + ": point " + std::to_string(i) + " has a non-finite value of '" + field + "'");
  return r;
}

} // namespace vtu_detail

std::optional<VtuCellRange> read_vtu_cell_range(const std::string &path,
                                                const FieldSelection &field,
                                                const ReadLimits &limits, int part, int parts,
                                                std::string &why) {
  if (!field.default_step())
    throw InputError(path + ": --step / --time: a .vtu file holds one time step");
  if (!std::ifstream(path)) {
    why = "a rank cannot open it";
    return std::nullopt;
  }
  vtu_detail::VtuFile f(path, field, limits);
  if (!f.open_for_ranges()) {
    why = "its arrays are not raw appended data";
    return std::nullopt;
  }
  return f.read_cell_range(part, parts, why);
}

} // namespace hoct
