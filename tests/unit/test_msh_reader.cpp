// The Gmsh MSH reader on the fixtures of tests/data/msh:
//  - hand-written ascii files (degrees 1 and 2, sparse node tags, several entity blocks,
//    parametric nodes, two views, time steps and partitions, MSH 2.2), checked array by array;
//  - files written by Gmsh itself (make_gmsh_fixtures.py: 4.1 binary with parametric nodes, 4.1
//    ascii, 2.2 ascii), checked against the straight-triangle geometry and the polynomial they
//    hold;
//  - malformed files, each of which must give an InputError that starts with the file name and
//    the place (line, or byte offset in binary files) and names the problem;
//  - files written by Gmsh with $ElementNodeData (continuous and not), $ElementData, binary MSH
//    2.2 and views of several time steps (the second group of make_gmsh_fixtures.py);
//  - .pos views (ST by Gmsh, ST2 in its syntax), merged by position, and malformed ones;
//  - every truncation and many corruptions of the good files, which must fail cleanly.
#include "io/file_contents.hpp"
#include "io/msh_element_types.hpp"
#include "io/msh_reader.hpp"
#include "io/pos_reader.hpp"
#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace hoct {
namespace {

namespace fs = std::filesystem;

std::string data_path(const std::string &name) {
  return std::string(HOCT_TEST_DATA) + "/msh/" + name;
}

std::string slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A directory of this process's files, removed when the tests end.
const fs::path &temp_dir() {
  struct Dir {
    fs::path path = fs::temp_directory_path() / ("hoct-msh-test-" + std::to_string(::getpid()));
    Dir() { fs::create_directories(path); }
    ~Dir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path;
}

std::string write_temp(const std::string &name, const std::string &content) {
  const std::string path = (temp_dir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// The message of the InputError read_msh throws, or "" (with a test failure) if it does not.
std::string error_of(const std::string &path, const FieldSelection &scalar = {}) {
  try {
    read_msh(path, scalar);
  } catch (const InputError &e) {
    return e.what();
  }
  ADD_FAILURE() << path << " was accepted";
  return "";
}

void expect_error(const std::string &path, const std::string &where, const std::string &phrase,
                  const FieldSelection &scalar = {}) {
  const std::string msg = error_of(path, scalar);
  EXPECT_EQ(msg.rfind(path + where, 0), 0u)
      << "expected '" << path + where << "' first in: " << msg;
  EXPECT_NE(msg.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << msg;
}

TEST(MshReader, LinearTrianglesTwoBlocksTwoViews) {
  const std::string path = data_path("p1_two_views.msh");
  const MeshInput p = read_msh(path);
  EXPECT_EQ(p.source, path);
  EXPECT_EQ(p.field_name, "p"); // the first view by default
  EXPECT_EQ(p.values, (PooledVector<double>{5, 5, 5, 5}));
  const MeshInput t = read_msh(path, "T");
  EXPECT_EQ(t.field_name, "T");
  EXPECT_EQ(t.points, (PooledVector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(t.values, (PooledVector<double>{1.5, 2.5, 3.5, 4.5}));
  EXPECT_EQ(t.cell_offsets, (PooledVector<int64_t>{0, 3, 6}));
  EXPECT_EQ(t.cell_nodes, (PooledVector<int64_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(t.cell_degree, (PooledVector<uint8_t>{1, 1}));
  // The same file with Windows line ends.
  std::string crlf;
  for (char c : slurp(path))
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const MeshInput w = read_msh(write_temp("crlf.msh", crlf), "T");
  EXPECT_EQ(w.points, t.points);
  EXPECT_EQ(w.values, t.values);
  EXPECT_EQ(w.cell_nodes, t.cell_nodes);
}

// p2_sparse_tags.msh and its MSH 2.2 twin: A (0,0) B (2,0) C (2,2) D (0,2), z = 0.25; element 17
// is A B C, element 4 is A C D (Gmsh order: corners, then the midpoints of edges 01, 12, 20).
// Points come in the order the file defines them, without node 77 (used by a point element only):
// C A BC AB CA CD DA D B.
void expect_sparse_p2(const MeshInput &m) {
  const double z = 0.25;
  EXPECT_EQ(m.points, (PooledVector<Vec3>{{2, 2, z},
                                          {0, 0, z},
                                          {2, 1, z},
                                          {1, 0, z},
                                          {1, 1, z},
                                          {1, 2, z},
                                          {0, 1, z},
                                          {0, 2, z},
                                          {2, 0, z}}));
  EXPECT_EQ(m.field_name, "f");
  // f = x^2 + 10 y
  EXPECT_EQ(m.values, (PooledVector<double>{24, 0, 14, 1, 11, 21, 10, 20, 4}));
  EXPECT_EQ(m.cell_degree, (PooledVector<uint8_t>{2, 2}));
  EXPECT_EQ(m.cell_offsets, (PooledVector<int64_t>{0, 6, 12}));
  // Canonical order of degree 2: (0,0) (1,0) (2,0) (0,1) (1,1) (0,2) in lattice (a, b).
  // Element 17: A AB B CA BC C; element 4: A AC C DA CD D.
  EXPECT_EQ(m.cell_nodes, (PooledVector<int64_t>{1, 3, 8, 4, 2, 0, 1, 4, 0, 6, 5, 7}));
}

TEST(MshReader, QuadraticTrianglesSparseTagsParametricNodes) {
  const MeshInput f = read_msh(data_path("p2_sparse_tags.msh"));
  expect_sparse_p2(f);
  const MeshInput g = read_msh(data_path("p2_sparse_tags.msh"), "g");
  EXPECT_EQ(g.field_name, "g");
  EXPECT_EQ(g.cell_nodes, f.cell_nodes);
  // g = x - y
  EXPECT_EQ(g.values, (PooledVector<double>{0, 0, 1, 1, 0, -1, -1, -2, 2}));
}

// A component or the magnitude of a vector view (issue 28, item 1): velocity is (1, 0, 0).
TEST(MshReader, ComponentsAndMagnitudeOfVectorViews) {
  const std::string path = data_path("time_steps.msh");
  FieldSelection x("velocity");
  x.component = 0;
  const MeshInput mx = read_msh(path, x);
  EXPECT_EQ(mx.field_name, "velocity[0]");
  EXPECT_EQ(mx.values, (PooledVector<double>{1, 1, 1, 1}));
  FieldSelection y = x;
  y.component = 1;
  EXPECT_EQ(read_msh(path, y).values, (PooledVector<double>{0, 0, 0, 0}));
  FieldSelection magnitude; // no name: the first vector view
  magnitude.component = FieldSelection::kMagnitude;
  const MeshInput mm = read_msh(path, magnitude);
  EXPECT_EQ(mm.field_name, "|velocity|");
  EXPECT_EQ(mm.values, (PooledVector<double>{1, 1, 1, 1}));
  FieldSelection beyond("velocity");
  beyond.component = 3;
  EXPECT_THROW(
      {
        try {
          read_msh(path, beyond);
        } catch (const InputError &e) {
          EXPECT_NE(std::string(e.what()).find(
                        "--component 3: $NodeData 'velocity' has 3 components (0 to 2)"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      InputError);
  FieldSelection of_scalar("T");
  of_scalar.component = 0;
  EXPECT_THROW(read_msh(path, of_scalar), InputError);
}

TEST(MshReader, Msh22ReadsLikeMsh41) {
  expect_sparse_p2(read_msh(data_path("p2_sparse_tags_msh22.msh")));
}

TEST(MshReader, TimeStepsPartitionsRepeatedMeshAndVectorViews) {
  // The mesh is written twice (as Gmsh's view.write does); "velocity" has 3 components, so the
  // default is "T", whose last time step comes in two partitions.
  const std::string path = data_path("time_steps.msh");
  const MeshInput m = read_msh(path);
  EXPECT_EQ(m.field_name, "T");
  EXPECT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.values, (PooledVector<double>{11, 12, 13, 14}));
  expect_error(path, ":", "$NodeData 'velocity' has 3 components; a scalar field needs 1",
               "velocity");
  // A later time step replaces the earlier one: a node missing from it has no value (it does not
  // keep the value of step 0).
  std::string text = slurp(path);
  const std::string last = "2\n2\n30 13\n40 14\n"; // 2 values, partition 2
  ASSERT_NE(text.find(last), std::string::npos);
  text.replace(text.find(last), last.size(), "1\n2\n30 13\n");
  expect_error(write_temp("steps.msh", text), ":", "$NodeData 'T' has no value for node 40");
}

TEST(MshReader, ChoosesViewByName) {
  const std::string path = data_path("p1_two_views.msh");
  expect_error(path, ": ", "no $NodeData or $ElementNodeData named 'Q' (available: p, T)", "Q");
}

// Files written by Gmsh: a unit square of two straight triangles of order k with the view
// "f" below (make_gmsh_fixtures.py).
double gmsh_f(double x, double y) {
  return 1.0 + x - 2.0 * y + 3.0 * x * y - x * x * y + 0.5 * y * y;
}

void expect_gmsh_square(const MeshInput &m, int degree) {
  ASSERT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.field_name, "f");
  EXPECT_EQ(m.points.size(), static_cast<std::size_t>((degree + 1) * (degree + 1)));
  for (std::size_t c = 0; c < 2; ++c) {
    ASSERT_EQ(m.cell_degree[c], degree);
    const int64_t *nodes = m.cell_nodes.data() + m.cell_offsets[c];
    const Vec3 &p0 = m.points[nodes[corner_index(degree, 0)]];
    const Vec3 &p1 = m.points[nodes[corner_index(degree, 1)]];
    const Vec3 &p2 = m.points[nodes[corner_index(degree, 2)]];
    for (int i = 0; i < lattice_size(degree); ++i) {
      // Straight cells: lattice point (a, b) sits at p0 + a/d (p1 - p0) + b/d (p2 - p0).
      const auto [a, b] = lattice_point(degree, i);
      const Vec3 &p = m.points[nodes[i]];
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(p[k], p0[k] + (a * (p1[k] - p0[k]) + b * (p2[k] - p0[k])) / degree, 1e-12)
            << "cell " << c << " lattice point " << a << "," << b;
      EXPECT_NEAR(m.values[nodes[i]], gmsh_f(p[0], p[1]), 1e-12);
    }
  }
}

TEST(MshReader, FilesWrittenByGmsh) {
  const MeshInput bin = read_msh(data_path("gmsh_square_p3_binary.msh"));
  expect_gmsh_square(bin, 3);
  expect_gmsh_square(read_msh(data_path("gmsh_square_p4_ascii.msh")), 4);
  const MeshInput v22 = read_msh(data_path("gmsh_square_p3_msh22.msh"));
  expect_gmsh_square(v22, 3);
  // Binary 4.1 and ascii 2.2 of the same mesh agree (ascii prints 16 digits).
  EXPECT_EQ(bin.cell_nodes, v22.cell_nodes);
  ASSERT_EQ(bin.points.size(), v22.points.size());
  for (std::size_t i = 0; i < bin.points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(bin.points[i][k], v22.points[i][k], 1e-15);
}

TEST(MshReader, MalformedFilesGiveLocatedErrors) {
  struct Case {
    const char *file, *where, *phrase, *scalar = "";
  };
  const Case cases[] = {
      {"bad_version_40.msh", ":2: ", "MSH version '4.0' is not supported: hoct reads MSH 4.1"},
      // Binary 2.2 without the byte-order int after its format line.
      {"bad_version_22_binary.msh", ": byte 20: ", "the byte-order check is 1684948260, not 1"},
      {"bad_file_type.msh", ":2: ", "unknown file type 2"},
      {"bad_not_msh.msh", ":1: ", "expected a section such as $Nodes, got 'solid'"},
      {"empty.msh", ": ", "the file is empty"},
      {"bad_format_only.msh", ": ", "no $Nodes section"},
      {"bad_no_elements.msh", ": ", "no $Elements section"},
      {"bad_no_triangles.msh", ": ",
       "no triangles in $Elements (1 point and line elements skipped)"},
      {"bad_elements_first.msh", ":16: ", "$Elements before any $Nodes section"},
      {"bad_no_nodedata.msh", ": ", "the file has no node data"},
      {"bad_vector_only.msh", ": ",
       "no scalar $NodeData or $ElementNodeData (available: velocity (3 components))"},
      {"bad_missing_node.msh", ":35: ", "element 2 refers to node 99, which is not in $Nodes"},
      {"bad_missing_value.msh", ":37: ", "$NodeData 'p' has no value for node 40 (of element 2)"},
      {"bad_serendipity.msh",
       ":34: ", "element 1: incomplete (serendipity) triangle type 20 is not supported"},
      {"bad_tet.msh",
       ":37: ", "element 8 has element type 4 (Tetrahedron 4), which is not a surface cell"},
      {"bad_unknown_type.msh", ":37: ", "element 9 has unknown element type 999"},
      {"bad_nan_value.msh", ":46: ", "$NodeData 'p': node 10 has a non-finite value (nan)"},
      {"bad_inf_coordinate.msh", ":26: ", "node 30 has a non-finite coordinate (1 inf 0)"},
      {"bad_number.msh", ":26: ", "expected the y coordinate (a number), got 'x'"},
      {"bad_node_count.msh", ":28: ", "the $Nodes header announces 5 nodes, its blocks hold 4"},
      {"bad_block_count.msh",
       ":23: ", "the node blocks hold more nodes than the 4 the $Nodes header announces"},
      {"bad_element_short.msh",
       ":34: ", "element 1 (Triangle 3) has 2 node tags on its line, expected 3"},
      {"bad_element_long.msh",
       ":34: ", "element 1 (Triangle 3) has more than 3 node tags on its line"},
      {"bad_element_count.msh",
       ":36: ", "the $Elements header announces 4 elements, its blocks hold 3"},
      {"bad_hostile_nodes.msh",
       ":17: ", "number of nodes 1000000000000000000 is more than the remaining"},
      {"bad_hostile_blocks.msh",
       ":30: ", "number of element blocks 99999999999999999 is more than"},
      {"bad_hostile_values.msh", ":42: ", "number of values 1000000000000000000 is more than"},
      {"bad_truncated.msh", ":42: ", "number of values 4 is more than the remaining 13 bytes"},
      {"bad_missing_end_nodes.msh", ":28: ", "expected $EndNodes, got '$Elements'"},
      {"bad_missing_end_nodedata.msh", ":63: ", "unexpected end of file: expected $EndNodeData"},
      {"bad_unterminated_entities.msh", ":12: ", "section $Entities has no $EndEntities"},
      {"bad_end_without_start.msh", ":16: ", "'$EndComments' ends a section that was not started"},
      {"bad_duplicate_node.msh", ":47: ", "node 30 is defined twice, with different coordinates"},
      {"bad_duplicate_element.msh", ":43: ", "element 2 is defined twice, with different nodes"},
      {"bad_tag_zero.msh", ":20: ", "node tag 0 (tags are positive)"},
      {"bad_nodedata_ints.msh", ":42: ", "$NodeData 'p' has 2 integer tags; it needs 3"},
      {"bad_unterminated_string.msh", ":39: ", "unterminated string tag '\"p'"},
      {"bad_msh22_tet.msh", ":26: ", "element 4 has element type 4 (Tetrahedron 4)"},
      {"bad_msh22_element_count.msh",
       ":27: ", "expected an element tag (a non-negative integer), got '$EndElements'"},
      {"bad_msh22_element_tags.msh",
       ":25: ", "the line ends where an element tag (physical, elementary, ...) was expected"},
      {"p1_two_views.msh", ": ", "no $NodeData or $ElementNodeData named 'Q' (available: p, T)",
       "Q"},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.file);
    expect_error(data_path(c.file), c.where, c.phrase, c.scalar);
  }
  expect_error(data_path("no_such_file.msh"), ": ", "cannot open");
  expect_error(std::string(HOCT_TEST_DATA) + "/msh", ": ", "is a directory");
}

// ---- binary files, patched byte by byte ----

template <class T> void put(std::string &bytes, std::size_t at, T v) {
  ASSERT_LE(at + sizeof v, bytes.size());
  std::memcpy(bytes.data() + at, &v, sizeof v);
}
template <class T> T get(const std::string &bytes, std::size_t at) {
  T v{};
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

// Offsets in the binary Gmsh fixture (the first copy of the mesh).
struct BinaryLayout {
  std::size_t nodes_header, elements_header, first_triangle_block, first_triangle, first_value;
};

BinaryLayout layout_of(const std::string &b) {
  BinaryLayout l{};
  l.nodes_header = b.find("$Nodes\n") + 7;
  l.elements_header = b.find("$Elements\n") + 10;
  std::size_t at = l.elements_header + 32;
  const auto blocks = get<uint64_t>(b, l.elements_header);
  for (uint64_t k = 0; k < blocks; ++k) {
    const auto type = get<int32_t>(b, at + 8);
    const auto n = get<uint64_t>(b, at + 12);
    if (type == 21) {
      l.first_triangle_block = at;
      l.first_triangle = at + 20;
      break;
    }
    at += 20 + 8 * n * (1 + static_cast<uint64_t>(msh_element_type(type)->nodes));
  }
  const std::size_t data = b.rfind("$NodeData\n");
  l.first_value = b.find("\n16\n", data) + 4; // 16 values: the last integer tag
  return l;
}

TEST(MshReader, BinaryMalformationsGiveByteOffsets) {
  const std::string good = slurp(data_path("gmsh_square_p3_binary.msh"));
  const BinaryLayout l = layout_of(good);
  ASSERT_NE(l.first_triangle, 0u);
  ASSERT_EQ(get<int32_t>(good, l.first_value), 1); // node tag 1
  auto patched = [&](const std::function<void(std::string &)> &change) {
    std::string b = good;
    change(b);
    return write_temp("patched.msh", b);
  };
  const auto at = [](std::size_t offset) { return ": byte " + std::to_string(offset) + ": "; };

  expect_error(
      patched([&](std::string &b) { put<uint64_t>(b, l.nodes_header + 8, 1000000000000000000); }),
      at(l.nodes_header), "number of nodes 1000000000000000000 is more than the remaining");
  expect_error(
      patched([&](std::string &b) { put<uint64_t>(b, l.nodes_header, uint64_t(1) << 62); }),
      at(l.nodes_header), "number of node blocks 4611686018427387904 is more than");
  expect_error(
      patched([&](std::string &b) { put<uint64_t>(b, l.first_triangle_block + 12, ~uint64_t(0)); }),
      at(l.first_triangle_block), "number of elements in the block 18446744073709551615");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, l.first_triangle_block + 8, 20); }),
               at(l.first_triangle), "incomplete (serendipity) triangle type 20 is not supported");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, l.first_triangle_block + 8, 4); }),
               at(l.first_triangle),
               "has element type 4 (Tetrahedron 4), which is not a surface cell");
  const auto first_tag = get<uint64_t>(good, l.first_triangle);
  expect_error(patched([&](std::string &b) { put<uint64_t>(b, l.first_triangle + 8, 999); }),
               at(l.first_triangle),
               "element " + std::to_string(first_tag) +
                   " refers to node 999, which is not in $Nodes");
  expect_error(patched([&](std::string &b) {
                 put<double>(b, l.first_value + 4, std::numeric_limits<double>::quiet_NaN());
               }),
               at(l.first_value + 4), "$NodeData 'f': node 1 has a non-finite value");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, l.first_value, -7); }),
               at(l.first_value), "node tag -7 is not positive");
  const std::size_t one = good.find("4.1 1 8\n") + 8;
  expect_error(patched([&](std::string &b) { put<int32_t>(b, one, 0x01000000); }), at(one),
               "big-endian");
  expect_error(patched([&](std::string &b) { b.replace(b.find("4.1 1 8\n"), 7, "4.1 1 4"); }),
               ":2: ", "binary data size 4 is not supported");
  // A wrong count in the $NodeData header (ascii in binary files): the binary data that follow
  // are misread and the section does not end where it should.
  expect_error(patched([&](std::string &b) { b.replace(l.first_value - 4, 4, "\n15\n"); }),
               ": byte ", "expected $EndNodeData");
}

// ---- $ElementNodeData, $ElementData, binary MSH 2.2 and time steps (issue 28, item 4) ----

FieldSelection view(const std::string &name, int64_t step = -1) {
  FieldSelection f(name);
  f.step = step;
  return f;
}

FieldSelection at_time(const std::string &name, double time) {
  FieldSelection f(name);
  f.time = time;
  return f;
}

void expect_same_mesh(const MeshInput &a, const MeshInput &b, double tolerance) {
  EXPECT_EQ(a.cell_nodes, b.cell_nodes);
  EXPECT_EQ(a.cell_degree, b.cell_degree);
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.values.size(), b.values.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(a.points[i][k], b.points[i][k], tolerance) << i;
    EXPECT_NEAR(a.values[i], b.values[i], tolerance) << i;
  }
}

TEST(MshReader, ContinuousElementNodeDataIsMergedIntoNodeValues) {
  // The default is "f": "area" ($ElementData) comes first but has no values at the nodes.
  const MeshInput nodes = read_msh(data_path("gmsh_square_p3_binary.msh"));
  for (const char *name : {"gmsh_elementnode_p3_ascii.msh", "gmsh_elementnode_p3_binary.msh",
                           "gmsh_elementnode_p3_msh22_binary.msh"}) {
    SCOPED_TRACE(name);
    const MeshInput m = read_msh(data_path(name));
    expect_gmsh_square(m, 3);
    EXPECT_EQ(m.field_detail, "");
    // The same mesh and values as the $NodeData route (ascii prints 16 digits).
    expect_same_mesh(m, nodes, 1e-14);
  }
}

TEST(MshReader, DiscontinuousElementNodeDataIsRefused) {
  // "jump" is 0.25 higher on one triangle: the nodes of the shared diagonal have two values.
  const std::string phrase = "the field is discontinuous there (largest jump 0.25";
  for (const char *name : {"gmsh_elementnode_p3_ascii.msh", "gmsh_elementnode_p3_binary.msh",
                           "gmsh_elementnode_p3_msh22_binary.msh"}) {
    SCOPED_TRACE(name);
    const std::string path = data_path(name);
    const std::string msg = error_of(path, "jump");
    EXPECT_NE(msg.find("$ElementNodeData 'jump': node "), std::string::npos) << msg;
    EXPECT_NE(msg.find(phrase), std::string::npos) << msg;
    EXPECT_NE(msg.find("); hoct needs a continuous field"), std::string::npos) << msg;
    EXPECT_NE(msg.find(" (element "), std::string::npos) << msg;
  }
  // The place is the view's block: a line in ascii files.
  const std::string ascii = data_path("gmsh_elementnode_p3_ascii.msh");
  const std::string text = slurp(ascii);
  const std::size_t block = text.find("$ElementNodeData\n2\n\"jump\"");
  ASSERT_NE(block, std::string::npos);
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(block), '\n');
  expect_error(ascii, ":" + std::to_string(line) + ": ", "has values ", "jump");
}

TEST(MshReader, ElementDataIsListedAndRefused) {
  const std::string path = data_path("gmsh_elementnode_p3_ascii.msh");
  expect_error(path, ":",
               "$ElementData 'area' holds one value per element: a piecewise-constant "
               "field has no contour tree of this kind",
               "area");
  expect_error(path, ": ",
               "no $NodeData or $ElementNodeData named 'Q' (available: area ($ElementData), f "
               "($ElementNodeData), jump ($ElementNodeData))",
               "Q");
  // A file whose only view is $ElementData: no default.
  std::string text = slurp(path);
  text = text.substr(0, text.find("$ElementNodeData"));
  expect_error(write_temp("element_data_only.msh", text), ": ",
               "no scalar $NodeData or $ElementNodeData (available: area ($ElementData))");
}

TEST(MshReader, Msh22BinaryReadsLikeMsh22Ascii) {
  const MeshInput bin = read_msh(data_path("gmsh_square_p3_msh22_binary.msh"));
  expect_gmsh_square(bin, 3);
  expect_same_mesh(bin, read_msh(data_path("gmsh_square_p3_msh22.msh")), 1e-15);
  // And like 4.1 binary, bit for bit.
  const MeshInput b41 = read_msh(data_path("gmsh_square_p3_binary.msh"));
  EXPECT_EQ(bin.points, b41.points);
  EXPECT_EQ(bin.values, b41.values);
  EXPECT_EQ(bin.cell_nodes, b41.cell_nodes);
}

// gmsh_steps_p2*.msh: "T" at steps 0, 1, 2 (times 0, 0.1, 0.2) is f + 10 step.
void expect_step(const MeshInput &m, int step) {
  ASSERT_EQ(m.num_cells(), 2u);
  const MeshInput f = read_msh(data_path("gmsh_steps_p2.msh"), "f");
  ASSERT_EQ(m.values.size(), f.values.size());
  for (std::size_t i = 0; i < m.values.size(); ++i)
    EXPECT_NEAR(m.values[i], f.values[i] + 10 * step, 1e-12) << i;
}

TEST(MshReader, TimeStepsByIndexAndTime) {
  for (const char *name :
       {"gmsh_steps_p2.msh", "gmsh_steps_p2_binary.msh", "gmsh_elementnode_p2_msh22.msh"}) {
    SCOPED_TRACE(name);
    const std::string path = data_path(name);
    const std::string v = name == std::string("gmsh_elementnode_p2_msh22.msh") ? "f" : "T";
    const MeshInput last = read_msh(path, v);
    expect_step(last, 2);
    EXPECT_EQ(last.field_name, v);
    EXPECT_EQ(last.field_detail, "(step 2 of 3, time 0.2)");
    expect_step(read_msh(path, view(v, 0)), 0);
    expect_step(read_msh(path, view(v, 1)), 1);
    expect_step(read_msh(path, view(v, -3)), 0);
    const MeshInput t = read_msh(path, at_time(v, 0.1));
    expect_step(t, 1);
    EXPECT_EQ(t.field_detail, "(step 1 of 3, time 0.1)");
    expect_step(read_msh(path, at_time(v, 0.1 * (1 + 1e-12))), 1);
    expect_step(read_msh(path, at_time(v, 0)), 0);
    const std::string section = v == "f" ? "$ElementNodeData 'f'" : "$NodeData 'T'";
    expect_error(
        path, ": ",
        "--step 3: " + section +
            " has 3 time steps (times 0, 0.1, 0.2): steps 0 to 2, or -3 to -1 from the end",
        view(v, 3));
    expect_error(path, ": ", "--step -4: " + section + " has 3 time steps", view(v, -4));
    expect_error(path, ": ",
                 "--time 0.15: " + section +
                     " has no time step at that time (3 time steps (times 0, 0.1, 0.2))",
                 at_time(v, 0.15));
  }
  // A view of one step: no detail; --step 0 and -1 are it, 1 is out of range.
  const std::string path = data_path("gmsh_steps_p2.msh");
  EXPECT_EQ(read_msh(path, "f").field_detail, "");
  EXPECT_EQ(read_msh(path, view("f", 0)).values, read_msh(path, "f").values);
  expect_error(path, ": ", "--step 1: $NodeData 'f' has 1 time step (times 0)", view("f", 1));
  // The hand-written file: step 0, then step 1 in two partitions.
  const std::string steps = data_path("time_steps.msh");
  EXPECT_EQ(read_msh(steps, view("T", 0)).values, (PooledVector<double>{1, 2, 3, 4}));
  EXPECT_EQ(read_msh(steps, at_time("T", 0.5)).values, (PooledVector<double>{11, 12, 13, 14}));
  EXPECT_EQ(read_msh(steps, "T").field_detail, "(step 1 of 2, time 0.5)");
}

TEST(MshReader, ListsTheViewsOfTheFile) {
  FileContents c;
  read_msh(data_path("gmsh_elementnode_p2_msh22.msh"), {}, {}, &c);
  ASSERT_EQ(c.fields.size(), 2u);
  EXPECT_EQ(c.fields[0].name, "f");
  EXPECT_EQ(c.fields[0].kind, "element-node data");
  EXPECT_EQ(c.fields[0].components, 1);
  ASSERT_EQ(c.fields[0].steps.size(), 3u);
  for (int s = 0; s < 3; ++s) {
    EXPECT_EQ(c.fields[0].steps[s].tag, s);
    ASSERT_TRUE(c.fields[0].steps[s].time.has_value());
    EXPECT_DOUBLE_EQ(*c.fields[0].steps[s].time, 0.1 * s);
  }
  EXPECT_EQ(c.fields[1].name, "area");
  EXPECT_EQ(c.fields[1].kind, "element data");
  // Filled even when the chosen view is refused.
  FileContents d;
  EXPECT_THROW(read_msh(data_path("time_steps.msh"), "velocity", {}, &d), InputError);
  ASSERT_EQ(d.fields.size(), 2u);
  EXPECT_EQ(d.fields[0].name, "velocity");
  EXPECT_EQ(d.fields[0].components, 3);
  EXPECT_EQ(d.fields[1].steps.size(), 2u);
}

// Malformed $ElementNodeData and binary MSH 2.2, patched from the Gmsh fixtures.
TEST(MshReader, MalformedElementNodeDataAndMsh22Binary) {
  const std::string ascii = slurp(data_path("gmsh_elementnode_p3_ascii.msh"));
  auto edited = [&](const std::string &from, const std::string &to) {
    std::string t = ascii;
    const std::size_t at = t.rfind(from); // in the last copy (the "jump" view's)
    EXPECT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    return write_temp("edited.msh", t);
  };
  // The "jump" block's records are "TAG 10 v ... v" (10 nodes of a cubic triangle).
  const std::size_t jump = ascii.find("\"jump\"");
  const std::size_t record =
      ascii.find('\n', ascii.find("\n2\n", ascii.find("\n3\n", jump) + 1) + 3);
  const std::string first = ascii.substr(record + 1, ascii.find(' ', record + 1) - record - 1);
  {
    // The record with 6 of its 10 values.
    std::string t = ascii;
    const std::size_t line = t.find("\n" + first + " 10 ", jump) + 1;
    std::size_t cut = line;
    for (int k = 0; k < 8; ++k)
      cut = t.find(' ', cut) + 1;
    t.replace(line, t.find('\n', line) - line, t.substr(line, cut - 1 - line));
    t.replace(line + first.size() + 1, 2, "6");
    expect_error(write_temp("six.msh", t), ":",
                 "$ElementNodeData 'jump': element " + first +
                     " (a triangle of degree 3) has 10 nodes, the data give values at 6",
                 "jump");
  }
  expect_error(edited("\n" + first + " 10 ", "\n" + first + " 0 "), ":",
               "$ElementNodeData 'jump': element " + first + " has 0 nodes", "jump");
  expect_error(edited("\n" + first + " 10 ", "\n999 10 "), ":",
               "$ElementNodeData 'jump' gives values for element 999, which is not in $Elements",
               "jump");
  expect_error(edited("\n" + first + " 10 ", "\n" + first + " 10 nan "), ":", "unexpected",
               "jump"); // 11 values on a line of 10
  {
    std::string t = ascii;
    const std::size_t v = t.find(' ', t.find(' ', record + 1) + 1) + 1; // the first value
    t.replace(v, t.find(' ', v) - v, "inf");
    expect_error(write_temp("inf.msh", t), ":",
                 "$ElementNodeData 'jump': element " + first + " has a non-finite value (inf)",
                 "jump");
  }
  expect_error(edited("$EndElementNodeData", "$EndNodeData"), ":",
               "expected $EndElementNodeData, got '$EndNodeData'");
  expect_error(edited("\"jump\"", "\"f\""), ":", "$ElementNodeData 'f': node ");
  {
    std::string t = ascii;
    t.replace(t.find("$Elements"), 0,
              "$ElementNodeData\n1\n\"early\"\n0\n3\n0\n1\n0\n"
              "$EndElementNodeData\n");
    expect_error(write_temp("early.msh", t), ":", "$ElementNodeData before any $Elements section");
  }
  {
    std::string t = ascii;
    const std::size_t at = t.find("\"area\"");
    t.replace(at, 6, "\"f\"");
    expect_error(write_temp("kinds.msh", t), ":",
                 "$ElementNodeData 'f': the file gives a view of this name as $ElementData too");
  }

  // Binary 2.2: node and element records are ints and doubles after an ascii count.
  const std::string good = slurp(data_path("gmsh_elementnode_p3_msh22_binary.msh"));
  const std::size_t nodes = good.find("$Nodes\n") + 7;
  const std::size_t node_records = good.find('\n', nodes) + 1;
  const std::size_t elements = good.find("$Elements\n") + 10;
  const std::size_t element_blocks = good.find('\n', elements) + 1;
  auto patched = [&](const std::function<void(std::string &)> &change) {
    std::string b = good;
    change(b);
    return write_temp("patched22.msh", b);
  };
  const auto at = [](std::size_t offset) { return ": byte " + std::to_string(offset) + ": "; };
  expect_error(patched([&](std::string &b) { put<int32_t>(b, node_records, -3); }),
               at(node_records), "node tag -3 (tags are positive)");
  expect_error(patched([&](std::string &b) { b.replace(nodes, 2, "9999999999\n"); }), ": byte ",
               "number of nodes 9999999999 is more than the remaining");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, element_blocks, 4); }),
               at(element_blocks + 12), "has element type 4 (Tetrahedron 4)");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, element_blocks, 999); }),
               at(element_blocks + 12), "has unknown element type 999");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, element_blocks + 4, 1 << 30); }),
               at(element_blocks), "the element blocks hold more elements than the");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, element_blocks + 4, -1); }),
               at(element_blocks), "element block: -1 elements");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, element_blocks + 8, 1 << 28); }),
               at(element_blocks), "number of elements in the block");
  // The $ElementNodeData records: int tag, int node count, doubles.
  const std::string ints = "\n3\n0\n1\n2\n"; // step 0, 1 component, 2 elements
  const std::size_t data = good.find(ints, good.find("$ElementNodeData")) + ints.size();
  ASSERT_EQ(get<int32_t>(good, data + 4), 10);
  expect_error(patched([&](std::string &b) { put<int32_t>(b, data + 4, 1 << 30); }), at(data),
               "number of element nodes with values 1073741824 is more than");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, data + 4, -2); }), at(data),
               "has -2 nodes");
  expect_error(patched([&](std::string &b) { put<int32_t>(b, data, 0); }), at(data),
               "$ElementNodeData 'f': element tag 0 is not positive");
  expect_error(patched([&](std::string &b) {
                 put<double>(b, data + 16, std::numeric_limits<double>::infinity());
               }),
               at(data + 16), "has a non-finite value (inf)");
}

// ---- .pos files (parsed views) ----

std::string pos_error(const std::string &text, const FieldSelection &field = {}) {
  try {
    read_pos_buffer(text, "t.pos", field);
  } catch (const InputError &e) {
    return e.what();
  }
  ADD_FAILURE() << text << " was accepted";
  return "";
}

TEST(MshReader, PosViewsMergeNodesByPosition) {
  // gmsh_square_p1.pos: written by Gmsh, steps f and f + 10 at times 0 and 1.
  const std::string p1 = data_path("gmsh_square_p1.pos");
  const MeshInput last = read_pos(p1);
  ASSERT_EQ(last.num_cells(), 2u);
  EXPECT_EQ(last.points.size(), 4u); // 6 nodes, 2 shared
  EXPECT_EQ(last.field_detail, "(step 1 of 2, time 1)");
  const MeshInput first = read_pos(p1, view("f", 0));
  expect_gmsh_square(first, 1);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(last.values[i], first.values[i] + 10);
  EXPECT_EQ(read_pos(p1, at_time("f", 1)).values, last.values);
  // ST2, with a text annotation (skipped) and a comment.
  const MeshInput p2 = read_pos(data_path("square_p2.pos"));
  expect_gmsh_square(p2, 2);
  FileContents c;
  read_pos(p1, {}, {}, &c);
  ASSERT_EQ(c.fields.size(), 1u);
  EXPECT_EQ(c.fields[0].steps.size(), 2u);
}

TEST(MshReader, PosMalformedAndRefusedContents) {
  const std::string tri = "ST(0,0,0,1,0,0,0,1,0){1,2,3};\n";
  const struct {
    std::string text, phrase;
  } cases[] = {
      {"View \"v\" {\n" + tri + "ST(0,0,0,0,1,0,-1,0,0){1.5,3,4};\n};\n",
       "t.pos:3: View 'v': the point (0, 0, 0) has values 1 (element 1) and 1.5 (element 2): the "
       "field is discontinuous there (largest jump 0.5 of a range 3); hoct needs a continuous "
       "field"},
      {"View \"v\" {\nVT(0,0,0,1,0,0,0,1,0){1,0,0,1,0,0,1,0,0};\n};\n",
       "t.pos:2: View 'v': VT (vector triangle) is not read: hoct reads scalar triangles"},
      {"View \"v\" {\nSQ(0,0,0,1,0,0,1,1,0,0,1,0){1,2,3,4};\n};\n", "SQ (scalar quadrangle)"},
      {"View \"v\" {\nXX(0){1};\n};\n", "t.pos:2: View 'v': unknown element type 'XX'"},
      {"View \"v\" {\nT2(1,1,0){\"only text\"};\n};\n",
       "t.pos: no View holds scalar triangles (ST, ST2, ST3) (views: v (no scalar triangles))"},
      {"View \"v\" {\nST(0,0,0,1,0,0,0,1,0){1,2,1/3};\n};\n",
       "t.pos:2: expected ',' or '}' after a value, got '/3};'"},
      {"View \"v\" {\nST(0,0,0,1,0,0,0,1,0){1,2,Sqrt(2)};\n};\n",
       "expected a value (a number; hoct does not evaluate expressions), got 'Sqrt(2)};'"},
      {"View \"v\" {\nST(0,0,0,1,0,0){1,2,3};\n};\n",
       "t.pos:2: View 'v': ST has 6 coordinates, expected 9"},
      {"View \"v\" {\nST(0,0,0,1,0,0,0,1,0){1,2};\n};\n",
       "t.pos:2: View 'v': ST has 2 values, not a multiple of its 3 nodes"},
      {"View \"v\" {\n" + tri + "ST(0,0,0,1,0,0,0,1,0){1,2,3,4,5,6};\n};\n",
       "t.pos:3: View 'v': ST has values for 2 time steps, the elements before it for 1"},
      {"View \"v\" {\nTIME{0,1};\n" + tri + "};\n",
       "t.pos:2: View 'v': TIME gives 2 times for 1 time steps"},
      {"View \"v\" {\n" + tri, "t.pos:1: View 'v' has no closing '}'"},
      {"View \"v\" {\n/* " + tri + "};\n", "t.pos:2: a /* comment is not closed"},
      {"Mesh.Algorithm = 6;\n", "t.pos:1: expected a View, got 'Mesh.Algorithm'"},
      {"View v {\n" + tri + "};\n", "t.pos:1: expected the view's name (a \"string\"), got 'v'"},
      {"View \"v\n", "t.pos:1: unterminated string"},
      {"View \"v\" {\nST(0,0,0,1,0,0,0,1,inf){1,2,3};\n};\n", "a coordinate 'inf' is not finite"},
      {"", "t.pos: the file has no View"},
  };
  for (const auto &c : cases) {
    SCOPED_TRACE(c.text);
    const std::string msg = pos_error(c.text);
    EXPECT_NE(msg.find(c.phrase), std::string::npos) << msg;
  }
  const std::string v =
      "View \"v\" {\nTIME{0,0.5};\n" + std::string("ST(0,0,0,1,0,0,0,1,0){1,2,3,4,5,6};\n};\n");
  EXPECT_NE(pos_error(v, "w").find("t.pos: no View named 'w' (available: v)"), std::string::npos);
  EXPECT_NE(pos_error(v, view("v", 2)).find("--step 2: View 'v' has 2 time steps (times 0, 0.5)"),
            std::string::npos);
  EXPECT_NE(pos_error(v, at_time("v", 1)).find("--time 1: View 'v' has no time step at that time"),
            std::string::npos);
  FieldSelection magnitude("v");
  magnitude.component = FieldSelection::kMagnitude;
  EXPECT_NE(pos_error(v, magnitude).find("--component: View 'v' holds scalar values"),
            std::string::npos);
}

// Every prefix and many corruptions of the .pos fixtures: read, or an InputError naming the file.
TEST(MshReader, PosTruncatedAndCorruptedFailCleanly) {
  for (const char *name : {"gmsh_square_p1.pos", "square_p2.pos"}) {
    SCOPED_TRACE(name);
    const std::string path = data_path(name);
    const std::string full = slurp(path);
    const std::size_t must_fail = full.rfind("};");
    for (std::size_t n = 0; n < full.size(); ++n) {
      try {
        read_pos_buffer(full.substr(0, n), path);
        ASSERT_GE(n, must_fail) << "a prefix of " << n << " bytes was accepted";
      } catch (const InputError &e) {
        ASSERT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << e.what();
      }
    }
    const char values[] = {'\0', '\xff', '9', '\n', '-', ',', '}', '"'};
    for (std::size_t i = 0, k = 0; i < full.size(); ++i, ++k) {
      std::string b = full;
      b[i] = values[k % std::size(values)] == b[i] ? 'x' : values[k % std::size(values)];
      try {
        read_pos_buffer(std::move(b), path);
      } catch (const InputError &e) {
        ASSERT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << e.what();
      }
    }
  }
}

// Prefixes of the good files (every one for the small hand-written files, a sample for Gmsh's):
// before the first complete $NodeData they must fail, after it they may succeed; nothing but an
// InputError naming the file.
TEST(MshReader, TruncatedFilesFailCleanly) {
  const std::pair<const char *, std::size_t> files[] = {{"p1_two_views.msh", 1},
                                                        {"p2_sparse_tags.msh", 1},
                                                        {"p2_sparse_tags_msh22.msh", 1},
                                                        {"time_steps.msh", 1},
                                                        {"gmsh_square_p3_binary.msh", 7},
                                                        {"gmsh_square_p4_ascii.msh", 13},
                                                        {"gmsh_square_p3_msh22.msh", 5},
                                                        {"gmsh_square_p3_msh22_binary.msh", 3},
                                                        {"gmsh_elementnode_p3_ascii.msh", 11},
                                                        {"gmsh_elementnode_p3_binary.msh", 7},
                                                        {"gmsh_elementnode_p3_msh22_binary.msh", 5},
                                                        {"gmsh_elementnode_p2_msh22.msh", 3},
                                                        {"gmsh_steps_p2_binary.msh", 5}};
  for (const auto &[name, stride] : files) {
    SCOPED_TRACE(name);
    const std::string full = slurp(data_path(name));
    const bool binary = full.find(" 1 8\n") < 20;
    // The first complete view (of the default: $ElementData is none).
    const auto end_of = [&](const std::string &marker) {
      const std::size_t at = full.find(marker);
      return at == std::string::npos ? at : at + marker.size();
    };
    const std::size_t must_fail = std::min(end_of("$EndNodeData"), end_of("$EndElementNodeData"));
    // Read from memory (read_msh_buffer names the file as read_msh does): writing a file per
    // prefix costs more than reading it.
    const std::string path = data_path(name);
    for (std::size_t n = 0; n < full.size(); n += stride) {
      try {
        read_msh_buffer(full.substr(0, n), path);
        ASSERT_GE(n, must_fail) << "a prefix of " << n << " bytes was accepted";
      } catch (const InputError &e) {
        // Binary files give byte offsets once their header has said they are binary.
        const std::string msg = e.what();
        ASSERT_EQ(msg.rfind(path + (binary && n > 30 ? ": " : ":"), 0), 0u) << msg;
      }
    }
  }
}

// Corrupted bytes (a sample of positions, several values): either read or an InputError.
TEST(MshReader, CorruptedBytesFailCleanly) {
  const std::pair<const char *, std::size_t> files[] = {{"gmsh_square_p3_binary.msh", 3},
                                                        {"p2_sparse_tags.msh", 2},
                                                        {"gmsh_square_p3_msh22.msh", 7},
                                                        {"gmsh_square_p3_msh22_binary.msh", 3},
                                                        {"gmsh_elementnode_p3_ascii.msh", 5},
                                                        {"gmsh_elementnode_p3_binary.msh", 3},
                                                        {"gmsh_elementnode_p3_msh22_binary.msh", 3},
                                                        {"gmsh_steps_p2_binary.msh", 3}};
  const char values[] = {'\0', '\xff', '9', '\n', '-'};
  for (const auto &[name, stride] : files) {
    SCOPED_TRACE(name);
    const std::string full = slurp(data_path(name));
    const std::string path = data_path(name);
    int failed = 0;
    for (std::size_t i = 0, k = 0; i < full.size(); i += stride, ++k) {
      std::string b = full;
      b[i] = values[k % std::size(values)] == b[i] ? 'x' : values[k % std::size(values)];
      try {
        read_msh_buffer(std::move(b), path);
      } catch (const InputError &e) {
        ++failed;
        ASSERT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
      }
    }
    EXPECT_GT(failed, 0);
  }
}

TEST(MshReader, ElementTypeTable) {
  // Complete triangles: Gmsh types and degrees (gmsh.model.mesh.getElementType("Triangle", d)).
  const std::pair<int, int> complete[] = {{2, 1},  {9, 2},  {21, 3}, {23, 4}, {25, 5},
                                          {42, 6}, {43, 7}, {44, 8}, {45, 9}, {46, 10}};
  for (auto [type, degree] : complete) {
    const MshElementType *t = msh_element_type(type);
    ASSERT_NE(t, nullptr) << type;
    EXPECT_EQ(t->complete_triangle_degree(), degree) << type;
    EXPECT_EQ(t->nodes, lattice_size(degree)) << type;
    EXPECT_FALSE(t->incomplete_triangle()) << type;
  }
  // Serendipity triangles (getElementType("Triangle", d, serendip=True) for d = 3..10).
  for (int type : {20, 22, 24, 52, 53, 54, 55, 56}) {
    const MshElementType *t = msh_element_type(type);
    ASSERT_NE(t, nullptr) << type;
    EXPECT_TRUE(t->incomplete_triangle()) << type;
    EXPECT_EQ(t->complete_triangle_degree(), 0) << type;
  }
  // Points and lines of orders 1 to 10, which the reader skips.
  const std::pair<int, int> lines[] = {{15, 1}, {1, 2},  {8, 3},  {26, 4},  {27, 5}, {28, 6},
                                       {62, 7}, {63, 8}, {64, 9}, {65, 10}, {66, 11}};
  for (auto [type, nodes] : lines) {
    const MshElementType *t = msh_element_type(type);
    ASSERT_NE(t, nullptr) << type;
    EXPECT_LE(t->dimension, 1) << type;
    EXPECT_EQ(t->nodes, nodes) << type;
  }
  EXPECT_EQ(msh_element_type(3)->complete_triangle_degree(), 0);  // quadrilateral
  EXPECT_EQ(msh_element_type(85)->complete_triangle_degree(), 0); // "Triangle 1"
  for (int type : {0, -1, 34, 67, 90, 138, 1000})
    EXPECT_EQ(msh_element_type(type), nullptr) << type;
}

} // namespace
} // namespace hoct
