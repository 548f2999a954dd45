// The Gmsh reader on hand-written files: sparse tags, several entity blocks, two views,
// MSH 2.2, binary 4.1; and a clear error for each kind of malformed file.
#include "error.hpp"
#include "io/msh_reader.hpp"
#include "poly/lattice.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace hoct {
namespace {

namespace fs = std::filesystem;

std::string write_temp(const std::string &name, const std::string &content) {
  const fs::path dir = fs::temp_directory_path() / ("hoct-msh-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// Two linear triangles (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1), node tags 10, 20, 30, 40 in two
// entity blocks, a line element that must be skipped, and two views.
struct MshFixture {
  std::string version = "4.1 0 8";
  std::string nodes = "$Nodes\n2 4 10 40\n2 1 0 2\n10\n20\n0 0 0\n1 0 0\n2 1 0 2\n30\n40\n1 1 0\n0 "
                      "1 0\n$EndNodes\n";
  std::string elements =
      "$Elements\n2 3 1 3\n1 1 1 1\n3 10 20\n2 1 2 2\n1 10 20 30\n2 10 30 40\n$EndElements\n";
  std::string data =
      "$NodeData\n1\n\"p\"\n1\n0.0\n3\n0\n1\n4\n10 5\n20 5\n30 5\n40 5\n$EndNodeData\n"
      "$NodeData\n1\n\"T\"\n1\n0.0\n3\n0\n1\n4\n10 1.5\n20 2.5\n30 3.5\n40 4.5\n$EndNodeData\n";
  std::string text() const {
    return "$MeshFormat\n" + version +
           "\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 \"plate\"\n"
           "$EndPhysicalNames\n" +
           nodes + elements + data;
  }
};

template <class F> std::string with(F &&change) {
  MshFixture f;
  change(f);
  return f.text();
}

void expect_error(const std::string &content, const std::string &phrase,
                  const std::string &scalar = "") {
  const std::string path = write_temp("bad.msh", content);
  try {
    read_msh(path, scalar);
    ADD_FAILURE() << "accepted a file that should fail with: " << phrase;
  } catch (const InputError &e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
    EXPECT_NE(msg.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << msg;
  }
}

TEST(MshReader, AsciiFixture) {
  const MeshInput m = read_msh(write_temp("ok.msh", MshFixture().text()));
  ASSERT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.field_name, "p"); // the first view by default
  const MeshInput t = read_msh(write_temp("ok.msh", MshFixture().text()), "T");
  EXPECT_EQ(t.field_name, "T");
  ASSERT_EQ(t.points.size(), 4u);
  // Nodes in first-use order: tags 10, 20, 30, 40.
  EXPECT_EQ(t.values, (std::vector<double>{1.5, 2.5, 3.5, 4.5}));
  EXPECT_EQ(t.points[2], (Vec3{1, 1, 0}));
  EXPECT_EQ(t.cell_nodes, (std::vector<int64_t>{0, 1, 2, 0, 2, 3}));
}

TEST(MshReader, Msh22AndBinary41) {
  const std::string v22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n10 0 0 0\n20 1 0 0\n"
                          "30 1 1 0\n40 0 1 0\n$EndNodes\n$Elements\n3\n1 1 2 0 1 10 20\n"
                          "2 2 2 0 1 10 20 30\n3 2 2 0 1 10 30 40\n$EndElements\n"
                          "$NodeData\n1\n\"T\"\n1\n0.0\n3\n0\n1\n4\n10 1\n20 2\n30 3\n40 4\n"
                          "$EndNodeData\n";
  const MeshInput a = read_msh(write_temp("v22.msh", v22));
  EXPECT_EQ(a.num_cells(), 2u);
  EXPECT_EQ(a.values, (std::vector<double>{1, 2, 3, 4}));
  // Binary 4.1, built byte by byte.
  std::string b = "$MeshFormat\n4.1 1 8\n";
  auto put = [&](auto v) { b.append(reinterpret_cast<const char *>(&v), sizeof v); };
  put(int32_t{1});
  b += "\n$EndMeshFormat\n$Nodes\n";
  for (uint64_t x : {1ull, 3ull, 1ull, 3ull})
    put(x);
  put(int32_t{2}), put(int32_t{1}), put(int32_t{0}), put(uint64_t{3});
  for (uint64_t t : {1ull, 2ull, 3ull})
    put(t);
  for (double c : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0})
    put(c);
  b += "\n$EndNodes\n$Elements\n";
  for (uint64_t x : {1ull, 1ull, 1ull, 1ull})
    put(x);
  put(int32_t{2}), put(int32_t{1}), put(int32_t{2}), put(uint64_t{1});
  for (uint64_t x : {7ull, 1ull, 2ull, 3ull})
    put(x);
  b += "\n$EndElements\n$NodeData\n1\n\"T\"\n1\n0.0\n3\n0\n1\n3\n";
  for (int i = 1; i <= 3; ++i)
    put(int32_t{i}), put(double(i) / 2);
  const std::string good = b + "\n$EndNodeData\n";
  const MeshInput m = read_msh(write_temp("bin.msh", good));
  EXPECT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.values, (std::vector<double>{0.5, 1.0, 1.5}));
  // Truncated binary data names a byte offset.
  expect_error(good.substr(0, good.find("$EndNodes") - 20), "(byte ");
}

TEST(MshReader, MalformedFilesGiveClearErrors) {
  expect_error(with([](MshFixture &f) { f.version = "4.0 0 8"; }), "version 4.0 is not supported");
  expect_error(with([](MshFixture &f) { f.version = "4.1 0 4"; }), "data size 4");
  expect_error(with([](MshFixture &f) { f.nodes.clear(); }), "no $Nodes section");
  expect_error(with([](MshFixture &f) { f.elements.clear(); }), "no $Elements section");
  expect_error(with([](MshFixture &f) { f.data.clear(); }), "no scalar $NodeData");
  expect_error(MshFixture().text(), "no $NodeData named 'Q' (available: p, T)", "Q");
  expect_error(with([](MshFixture &f) {
                 f.elements.replace(f.elements.find("2 10 30 40"), 10, "2 10 30 99");
               }),
               "element 2 refers to node 99");
  expect_error(with([](MshFixture &f) {
                 f.data =
                     "$NodeData\n1\n\"T\"\n1\n0.0\n3\n0\n1\n3\n10 1\n20 1\n30 1\n$EndNodeData\n";
               }),
               "node 40 (of element 2) has no value");
  expect_error(with([](MshFixture &f) {
                 f.elements = "$Elements\n1 1 1 1\n2 1 20 1\n1 10 20 30 10 20 30\n$EndElements\n";
               }),
               "incomplete (serendipity) triangle type 20");
  expect_error(with([](MshFixture &f) {
                 f.elements = "$Elements\n1 1 1 1\n2 1 3 1\n1 10 20 30 40\n$EndElements\n";
               }),
               "element type 3 (dimension 2) is not a triangle");
  expect_error(with([](MshFixture &f) { f.nodes.replace(f.nodes.find("1 1 0"), 5, "1 x 0"); }),
               "expected a number (node coordinate), got 'x'");
  expect_error(with([](MshFixture &f) {
                 f.nodes.replace(f.nodes.find("2 4 10 40"), 9, "2 99999999999999 10 40");
               }),
               "implausible number of nodes");
  expect_error(with([](MshFixture &f) { f.data.replace(f.data.find("10 1.5"), 6, "10 nan"); }),
               "node 10 has a non-finite value");
  expect_error(
      with([](MshFixture &f) { f.nodes.replace(f.nodes.find("$EndNodes"), 9, "$Endnodes"); }),
      "expected $EndNodes");
  const std::string full = MshFixture().text();
  expect_error(full.substr(0, full.find("$EndNodes") - 4), "unexpected end of file");
  expect_error("hello", "expected a section");
  expect_error("$Nodes\n1 1 1 1\n", "does not start with $MeshFormat");
  expect_error("", "the file is empty");
  // The line number of the problem is in the message.
  expect_error(with([](MshFixture &f) { f.nodes.replace(f.nodes.find("1 1 0"), 5, "1 x 0"); }),
               "bad.msh:18:");
}

} // namespace
} // namespace hoct
