// A .vtu read by parts (io/vtu_cell_range): for 1 to 7 parts, the parts' cells put end to end
// are read_vtu's cells, node for node (the file's point ids), every part holds the points its
// cells use at read_vtu's coordinates and values, and the parts' checked points cover the file's
// points once. Files it cannot read by parts say why; a part that finds a broken cell or a NaN
// in its own range throws.
#include "datasets/datasets.hpp"
#include "io/vtu_cell_range.hpp"
#include "io/vtu_reader.hpp"
#include "io/vtu_writer.hpp"
#include "util/error.hpp"

#include "test_temp_dir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

namespace hoct {
namespace {

struct TempDir : testing::TempDir {
  TempDir() : testing::TempDir("hoct-vtu-range") {}
};

void expect_parts_are_the_whole(const std::string &path, const std::string &label) {
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
  }
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

} // namespace
} // namespace hoct
