// A .vtu read by parts (io/vtu_cell_range): for 1 to 7 parts, the parts' cells put end to end
// are read_vtu's cells, node for node (the file's point ids), every part holds the points its
// cells use at read_vtu's coordinates and values, and the parts' checked points cover the file's
// points once. Files it cannot read by parts say why; a part that finds a broken cell or a NaN
// in its own range throws.
#include "datasets/datasets.hpp"
#include "datasets/shuffled_points.hpp"
#include "io/base64.hpp"
#include "io/vtu_cell_range.hpp"
#include "io/vtu_reader.hpp"
#include "io/vtu_writer.hpp"
#include "util/error.hpp"

#include "test_temp_dir.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <numeric>
#include <random>

namespace hoct {
namespace {

struct TempDir : testing::TempDir {
  TempDir() : testing::TempDir("hoct-vtu-range") {}
};

// `share_only`: how many parts read only their checked share (used_points_read false).
void expect_parts_are_the_whole(const std::string &path, const std::string &label,
                                int *share_only = nullptr) {
  const MeshInput whole = read_vtu(path);
  for (int parts = 1; parts <= 7; ++parts) {
    std::vector<int64_t> nodes;
    std::vector<uint8_t> degrees, kinds;
    int64_t checked = 0, cells_end = 0;
    for (int part = 0; part < parts; ++part) {
      std::string why;
      const auto r = read_vtu_cell_range(path, {}, {}, part, parts, why);
      ASSERT_TRUE(r.has_value()) << label << ": " << why;
      const MeshInput &m = r->input;
      if (share_only && !r->used_points_read)
        ++*share_only;
      EXPECT_EQ(r->cell_begin, cells_end) << label;
      cells_end = r->cell_end;
      EXPECT_EQ(r->check_begin, checked) << label << ", part " << part << " of " << parts;
      checked = r->check_end;
      for (int64_t q = r->check_begin; q < r->check_end; ++q) { // read, and the whole's
        ASSERT_GE(r->block_first[static_cast<std::size_t>(q / r->point_block)], 0);
        const std::size_t i = static_cast<std::size_t>(r->point_index(q));
        EXPECT_EQ(m.points[i], whole.points[static_cast<std::size_t>(q)]) << label;
        EXPECT_EQ(m.values[i], whole.values[static_cast<std::size_t>(q)]) << label;
      }
      EXPECT_EQ(r->file_points, static_cast<int64_t>(whole.num_points()));
      EXPECT_EQ(m.field_name, whole.field_name);
      for (std::size_t c = 0; c < m.num_cells(); ++c) {
        degrees.push_back(m.cell_degree[c]);
        kinds.push_back(static_cast<uint8_t>(m.kind(c)));
        for (int64_t k = m.cell_offsets[c]; k < m.cell_offsets[c + 1]; ++k) {
          const int64_t q = m.cell_nodes[static_cast<std::size_t>(k)];
          nodes.push_back(q);
          if (!r->used_points_read)
            continue;
          // The part holds the point, at the whole's position and value.
          ASSERT_GE(r->point_index(q), 0);
          ASSERT_LT(r->point_index(q), static_cast<int64_t>(m.points.size()));
          ASSERT_GE(r->block_first[static_cast<std::size_t>(q / r->point_block)], 0);
          const std::size_t i = static_cast<std::size_t>(r->point_index(q));
          EXPECT_EQ(m.points[i], whole.points[static_cast<std::size_t>(q)]) << label;
          EXPECT_EQ(m.values[i], whole.values[static_cast<std::size_t>(q)]) << label;
        }
      }
    }
    EXPECT_EQ(checked, static_cast<int64_t>(whole.num_points())) << label;
    EXPECT_EQ(cells_end, static_cast<int64_t>(whole.num_cells())) << label;
    EXPECT_EQ(nodes, std::vector<int64_t>(whole.cell_nodes.begin(), whole.cell_nodes.end()))
        << label << ", " << parts << " parts";
    EXPECT_EQ(degrees, std::vector<uint8_t>(whole.cell_degree.begin(), whole.cell_degree.end()));
    std::vector<uint8_t> whole_kinds;
    for (std::size_t c = 0; c < whole.num_cells(); ++c)
      whole_kinds.push_back(static_cast<uint8_t>(whole.kind(c)));
    EXPECT_EQ(kinds, whole_kinds) << label;
  }
}

// A file of inline base64 arrays (zlib blocks) rewritten with the same blocks as raw appended
// data, as VTK writes by default: what read_vtu_cell_range reads block by block.
std::string appended_zlib(const std::string &inline_file) {
  std::ifstream in(inline_file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  std::string xml, payload;
  std::size_t at = 0;
  while (true) {
    const std::size_t tag = text.find("<DataArray", at);
    if (tag == std::string::npos)
      break;
    const std::size_t close = text.find('>', tag);
    const std::size_t end = text.find("</DataArray>", close);
    std::string head = text.substr(tag, close - tag);
    const std::size_t f = head.find("format=\"binary\"");
    if (f == std::string::npos) { // not an inline binary array: as it is
      xml += text.substr(at, end - at);
      at = end;
      continue;
    }
    head.replace(f, 15, "format=\"appended\" offset=\"" + std::to_string(payload.size()) + "\"");
    const std::vector<uint8_t> raw = base64_decode(text.substr(close + 1, end - close - 1));
    payload.append(raw.begin(), raw.end());
    xml += text.substr(at, tag - at) + head + "/>";
    at = end + std::string("</DataArray>").size();
  }
  xml += text.substr(at);
  const std::size_t last = xml.rfind("</VTKFile>");
  return xml.substr(0, last) + "<AppendedData encoding=\"raw\">_" + payload +
         "</AppendedData>\n</VTKFile>\n";
}

MeshInput dataset(const std::string &name, int degree, long long cells, bool quads = false) {
  DatasetOptions o;
  o.degree = degree;
  o.cells = cells;
  o.quadrilaterals = quads;
  return generate_dataset(name, o);
}

TEST(VtuCellRange, ThePartsAreTheWholeFile) {
  TempDir tmp;
  const std::string path = tmp.file("parts.vtu");
  for (const auto &[label, in] : std::vector<std::pair<std::string, MeshInput>>{
           {"random cubic", dataset("random", 3, 300)},
           {"sphere", dataset("sphere", 2, 200)},
           {"quads", dataset("random", 2, 150, true)},
           {"two cells", dataset("two-triangle", 0, 0)}}) {
    write_vtu(path, in, VtkEncoding::AppendedRaw);
    expect_parts_are_the_whole(path, label);
    // zlib blocks of raw appended data, each part inflating the blocks over its ranges.
    const std::string inline_file = tmp.file("inline.vtu");
    write_vtu(inline_file, in, VtkEncoding::Base64Zlib);
    std::ofstream(path, std::ios::binary) << appended_zlib(inline_file);
    expect_parts_are_the_whole(path, label + ", zlib");
  }
}

TEST(VtuCellRange, PointsNumberedAtRandomAreLeftToTheirCheckers) {
  // The same cubic mesh numbered as generated (points near their cells) and at random: with
  // points at random a part's cells use nearly every block of ids, and from 4 parts on it reads
  // its checked share alone (the 2 and 3 parts of 30,000 cells still read their blocks).
  TempDir tmp;
  const std::string path = tmp.file("numbered.vtu");
  const MeshInput in = dataset("random", 3, 30000);
  write_vtu(path, in, VtkEncoding::AppendedRaw);
  int share_only = 0;
  expect_parts_are_the_whole(path, "numbered near", &share_only);
  EXPECT_EQ(share_only, 0);
  const MeshInput shuffled = with_points_shuffled(in, 11);
  write_vtu(path, shuffled, VtkEncoding::AppendedRaw);
  expect_parts_are_the_whole(path, "numbered at random", &share_only);
  EXPECT_EQ(share_only, 4 + 5 + 6 + 7);
}

TEST(VtuCellRange, SaysWhyAFileCannotBeReadByParts) {
  TempDir tmp;
  const std::string path = tmp.file("inline.vtu");
  const MeshInput in = dataset("random", 2, 100);
  for (const VtkEncoding e : {VtkEncoding::Ascii, VtkEncoding::Base64, VtkEncoding::Base64Zlib,
                              VtkEncoding::AppendedBase64}) {
    write_vtu(path, in, e);
    std::string why;
    EXPECT_FALSE(read_vtu_cell_range(path, {}, {}, 0, 2, why).has_value());
    EXPECT_EQ(why, "its arrays are not raw appended data");
  }
  std::string why;
  EXPECT_FALSE(read_vtu_cell_range(tmp.file("none.vtu"), {}, {}, 0, 2, why).has_value());
  EXPECT_EQ(why, "a rank cannot open it");
}

TEST(VtuCellRange, APartThrowsForWhatItFindsInItsRange) {
  TempDir tmp;
  const std::string path = tmp.file("nan.vtu");
  MeshInput in = dataset("random", 2, 200);
  const std::size_t bad = in.num_points() * 3 / 4; // in the last part of 2 or 4
  in.values[bad] = std::nan("");
  write_vtu(path, in, VtkEncoding::AppendedRaw);
  EXPECT_THROW(read_vtu(path), InputError);
  for (int parts : {2, 4}) {
    for (int part = 0; part < parts; ++part) {
      std::string why;
      const int64_t n = static_cast<int64_t>(in.num_points());
      const bool checks = n * part / parts <= static_cast<int64_t>(bad) &&
                          static_cast<int64_t>(bad) < n * (part + 1) / parts;
      if (checks) {
        try {
          read_vtu_cell_range(path, {}, {}, part, parts, why);
          ADD_FAILURE() << "part " << part << " of " << parts << " read a NaN";
        } catch (const InputError &e) {
          EXPECT_NE(std::string(e.what()).find("point " + std::to_string(bad) +
                                               " has a non-finite value"),
                    std::string::npos)
              << e.what();
        }
      } else {
        EXPECT_TRUE(read_vtu_cell_range(path, {}, {}, part, parts, why).has_value());
      }
    }
  }
}

// A cell's offset past its part's last one (but within the file's connectivity): refused by
// that part before it reads a node beyond what it read (the sanitizers' build checks the reads:
// with the file's last offset as the bound instead, AddressSanitizer reports the overflow).
TEST(VtuCellRange, OffsetsThatDecreaseWithinAPartAreRefused) {
  TempDir tmp;
  const std::string path = tmp.file("offsets.vtu");
  const MeshInput mesh = dataset("random", 2, 60);
  write_vtu(path, mesh, VtkEncoding::AppendedRaw);
  std::ifstream in(path, std::ios::binary);
  std::string b((std::istreambuf_iterator<char>(in)), {});
  in.close();
  const std::size_t name = b.find("Name=\"offsets\"");
  const std::size_t tag = b.rfind("<DataArray", name);
  const std::size_t attr = b.find("offset=\"", tag) + 8;
  ASSERT_LT(attr, b.find('>', tag));
  const std::size_t payload = b.find('_', b.find("<AppendedData")) + 1;
  const std::size_t at = payload + std::stoull(b.substr(attr)) + 8; // UInt64 header
  // Part 0 of 6 holds cells [0, e): cell 5 gets 66 nodes (a degree-10 Lagrange triangle's
  // count, so the node count alone does not refuse it), past cell e - 1's end but within the
  // file's connectivity.
  const std::size_t e = mesh.num_cells() / 6;
  std::vector<int64_t> offsets(mesh.num_cells());
  std::memcpy(offsets.data(), b.data() + at, offsets.size() * 8);
  const int64_t past = offsets[4] + 66;
  ASSERT_GT(past, offsets[e - 1]);
  ASSERT_LT(past, offsets.back());
  std::memcpy(b.data() + at + 5 * 8, &past, 8);
  std::ofstream(path, std::ios::binary) << b;
  std::string why;
  EXPECT_THROW(read_vtu_cell_range(path, {}, {}, 0, 6, why), InputError);
  EXPECT_THROW(read_vtu(path), InputError);
}

// Corrupted files (a byte of the appended data or a digit of the XML changed, 600 times): every
// part ends in a result or an InputError, never another exception or a crash (the sanitizers'
// build runs this too); and where every part reads its range, read_vtu reads the file to the
// same cells, points and values (the parts check together what the whole read checks).
TEST(VtuCellRange, CorruptedFilesFailCleanlyOrReadAsTheWhole) {
  TempDir tmp;
  const std::string clean = tmp.file("clean.vtu"), path = tmp.file("corrupt.vtu");
  const MeshInput mesh = dataset("random", 2, 40);
  write_vtu(clean, mesh, VtkEncoding::AppendedRaw);
  std::ifstream in(clean, std::ios::binary);
  const std::string raw_bytes((std::istreambuf_iterator<char>(in)), {});
  write_vtu(clean, mesh, VtkEncoding::Base64Zlib);
  const std::string zlib_bytes = appended_zlib(clean);
  for (const std::string &bytes : {raw_bytes, zlib_bytes}) {
    const std::size_t payload = bytes.find('_', bytes.find("<AppendedData")) + 1;
    ASSERT_NE(payload, std::string::npos);
    std::mt19937_64 rng(11);
    int all_read = 0, refused = 0;
    for (int trial = 0; trial < 600; ++trial) {
      std::string b = bytes;
      if (trial % 2 == 0) { // a byte of the payload (headers, offsets, connectivity, values)
        const std::size_t at = payload + rng() % (b.size() - payload - 20);
        b[at] = static_cast<char>(rng());
      } else { // a digit of the XML (counts, offsets, components)
        std::vector<std::size_t> digits;
        for (std::size_t i = 0; i < payload; ++i)
          if (b[i] >= '0' && b[i] <= '9')
            digits.push_back(i);
        b[digits[rng() % digits.size()]] = static_cast<char>('0' + rng() % 10);
      }
      std::ofstream(path, std::ios::binary) << b;
      constexpr int kParts = 3;
      std::vector<VtuCellRange> parts;
      bool ok = true;
      for (int part = 0; part < kParts; ++part) {
        std::string why;
        try {
          auto r = read_vtu_cell_range(path, {}, {}, part, kParts, why);
          if (!r)
            ok = false;
          else
            parts.push_back(std::move(*r));
        } catch (const InputError &) {
          ok = false;
        }
      }
      if (!ok) {
        ++refused;
        continue;
      }
      ++all_read;
      MeshInput whole;
      try {
        whole = read_vtu(path);
      } catch (const InputError &e) {
        ADD_FAILURE() << "trial " << trial << ": the parts read it, read_vtu refuses: " << e.what();
        continue;
      }
      std::vector<int64_t> nodes;
      for (const VtuCellRange &r : parts) {
        nodes.insert(nodes.end(), r.input.cell_nodes.begin(), r.input.cell_nodes.end());
        for (int64_t q = r.check_begin; q < r.check_end; ++q) {
          const std::size_t i = static_cast<std::size_t>(r.point_index(q));
          EXPECT_EQ(r.input.points[i], whole.points[static_cast<std::size_t>(q)]) << trial;
          EXPECT_EQ(r.input.values[i], whole.values[static_cast<std::size_t>(q)]) << trial;
        }
      }
      EXPECT_EQ(nodes, std::vector<int64_t>(whole.cell_nodes.begin(), whole.cell_nodes.end()))
          << "trial " << trial;
    }
    // Both outcomes were met (the corruptions are not all harmless, nor all fatal).
    EXPECT_GT(all_read, 50);
    EXPECT_GT(refused, 50);
  }
}

} // namespace
} // namespace hoct
