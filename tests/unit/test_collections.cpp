// The collection readers (.pvtu pieces, .pvd time series): pieces joined (ghost cells dropped,
// shared points merged by global id or position), steps chosen, and a clear error naming the
// file for every malformed collection (issue 28, item 2).
#include "io/pvd_reader.hpp"
#include "io/pvtu_reader.hpp"
#include "io/read_limits.hpp"
#include "io/read_mesh.hpp"
#include "io/vtu_reader.hpp"
#include "util/error.hpp"

#include "test_temp_dir.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

namespace hoct {
namespace {

namespace fs = std::filesystem;

struct TempDir : testing::TempDir {
  TempDir() : testing::TempDir("hoct-pvd", "sub") {}
};

// The unit square as two linear triangles, T = x + 2y + k; a piece holds some of them.
struct Square {
  double k = 0;
  std::string field = "T";
};
const double kX[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const int kTri[2][3] = {{0, 1, 3}, {1, 2, 3}};

// A .vtu of the triangles `cells` of the square (its points those they use, in their order),
// `ghost` the cells marked DUPLICATECELL; with `ids`, the square's point indices times 10 as
// GlobalIds (`shift` moves the ids, to break them).
std::string piece(const std::vector<int> &cells, const std::vector<int> &ghost = {},
                  bool ids = false, const Square &sq = {}, int shift = 0) {
  std::vector<int> points;
  for (int c : cells)
    for (int v : kTri[c])
      if (std::find(points.begin(), points.end(), v) == points.end())
        points.push_back(v);
  std::ostringstream s;
  s.precision(17);
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\""
    << cells.size() << "\">\n<PointData>\n<DataArray type=\"Float64\" Name=\"" << sq.field
    << "\" format=\"ascii\">";
  for (int p : points)
    s << " " << kX[p][0] + 2 * kX[p][1] + sq.k;
  s << "</DataArray>\n";
  if (ids) {
    s << "<DataArray type=\"Int64\" Name=\"GlobalIds\" format=\"ascii\">";
    for (int p : points)
      s << " " << 10 * p + shift;
    s << "</DataArray>\n";
  }
  s << "</PointData>\n";
  if (!ghost.empty()) {
    s << "<CellData>\n<DataArray type=\"UInt8\" Name=\"vtkGhostType\" format=\"ascii\">";
    for (int c : cells)
      s << " " << (std::find(ghost.begin(), ghost.end(), c) != ghost.end() ? 1 : 0);
    s << "</DataArray>\n</CellData>\n";
  }
  s << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">";
  for (int p : points)
    s << " " << kX[p][0] << " " << kX[p][1] << " 0";
  s << "</DataArray>\n</Points>\n<Cells>\n"
    << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">";
  for (int c : cells)
    for (int v : kTri[c])
      s << " " << std::find(points.begin(), points.end(), v) - points.begin();
  s << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">";
  for (std::size_t c = 0; c < cells.size(); ++c)
    s << " " << 3 * (c + 1);
  s << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">";
  for (std::size_t c = 0; c < cells.size(); ++c)
    s << " 5";
  s << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return s.str();
}

std::string pvtu(const std::vector<std::string> &sources, const std::string &extra = "") {
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\">\n"
                  "<PUnstructuredGrid GhostLevel=\"1\">\n" +
                  extra;
  for (const std::string &src : sources)
    s += "<Piece Source=\"" + src + "\"/>\n";
  return s + "</PUnstructuredGrid>\n</VTKFile>\n";
}

// datasets: (timestep attribute or "" for none, part, file).
std::string pvd(const std::vector<std::array<std::string, 3>> &datasets) {
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                  "<Collection>\n";
  for (const auto &[t, part, file] : datasets)
    s += "<DataSet" + (t.empty() ? std::string() : " timestep=\"" + t + "\"") + " part=\"" + part +
         "\" file=\"" + file + "\"/>\n";
  return s + "</Collection>\n</VTKFile>\n";
}

void expect_error(const std::function<void()> &read, const std::string &path,
                  const std::vector<std::string> &phrases) {
  try {
    read();
    ADD_FAILURE() << "no error for " << path;
  } catch (const InputError &e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
    for (const std::string &phrase : phrases)
      EXPECT_NE(msg.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << msg;
  }
}

void expect_square(const MeshInput &m, double k = 0) {
  EXPECT_EQ(m.num_cells(), 2u);
  ASSERT_EQ(m.num_points(), 4u);
  for (std::size_t i = 0; i < m.num_points(); ++i)
    EXPECT_DOUBLE_EQ(m.values[i], m.points[i][0] + 2 * m.points[i][1] + k);
  std::set<int64_t> used(m.cell_nodes.begin(), m.cell_nodes.end());
  EXPECT_EQ(used.size(), 4u);
}

TEST(VtuCollections, PvtuJoinsPiecesByIdsOrPosition) {
  TempDir tmp;
  // No ghosts, no ids: the two shared points merged by position.
  tmp.write("a.vtu", piece({0}));
  tmp.write("b.vtu", piece({1}));
  expect_square(read_mesh(tmp.write("plain.pvtu", pvtu({"a.vtu", "b.vtu"}))));
  // Ghost cells (each piece has the other's triangle too) and ids.
  tmp.write("ga.vtu", piece({0, 1}, {1}, true));
  tmp.write("sub/gb.vtu", piece({0, 1}, {0}, true));
  const MeshInput m = read_mesh(tmp.write("ghosts.pvtu", pvtu({"ga.vtu", "sub/./gb.vtu"})));
  expect_square(m);
  EXPECT_TRUE(m.warnings.empty());
  // An idle rank's empty piece is nothing.
  tmp.write("empty.vtu",
            "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"0\" "
            "NumberOfCells=\"0\"/></UnstructuredGrid></VTKFile>");
  expect_square(read_mesh(tmp.write("idle.pvtu", pvtu({"empty.vtu", "a.vtu", "b.vtu"}))));
  // Ids of other points than the positions say: refused, not joined wrong.
  tmp.write("shifted.vtu", piece({1}, {}, true, {}, 10));
  tmp.write("ia.vtu", piece({0}, {}, true));
  const std::string bad = tmp.write("bad-ids.pvtu", pvtu({"ia.vtu", "shifted.vtu"}));
  expect_error([&] { read_mesh(bad); }, bad, {"global id", "ia.vtu", "shifted.vtu"});
  // Pieces that disagree on a shared point's value.
  tmp.write("other-k.vtu", piece({1}, {}, false, {.k = 1}));
  const std::string jump = tmp.write("jump.pvtu", pvtu({"a.vtu", "other-k.vtu"}));
  expect_error([&] { read_mesh(jump); }, jump, {"disagree", "a.vtu", "other-k.vtu"});
  // Only ghost cells.
  tmp.write("all-ghost.vtu", piece({0, 1}, {0, 1}));
  const std::string ghosts = tmp.write("all-ghost.pvtu", pvtu({"all-ghost.vtu"}));
  expect_error([&] { read_mesh(ghosts); }, ghosts, {"no cells but ghost cells"});
}

TEST(VtuCollections, OnePieceAloneWarns) {
  TempDir tmp;
  const std::string a = tmp.write("whole_0.vtu", piece({0, 1}, {1}));
  MeshInput m = read_mesh(a);
  EXPECT_EQ(m.num_cells(), 2u); // the ghost cell kept
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_EQ(m.warnings[0], a + " holds one piece of a partitioned output (it has ghost cells: 1, "
                               "copies of its neighbours' cells, kept); its tree is that "
                               "piece's, not the whole domain's: read the .pvtu that lists its "
                               "pieces for the whole");
  tmp.write("whole.pvtu", pvtu({"whole_0.vtu", "whole_1.vtu"}));
  m = read_mesh(a);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("read " + tmp.file("whole.pvtu") + " for the whole"),
            std::string::npos)
      << m.warnings[0];
  EXPECT_TRUE(read_mesh(tmp.write("plain.vtu", piece({0, 1}))).warnings.empty());
}

TEST(VtuCollections, MalformedPvtuNamesTheFile) {
  TempDir tmp;
  tmp.write("a.vtu", piece({0}));
  tmp.write("u.vtu", piece({1}, {}, false, {.field = "U"}));
  auto refused = [&](const std::string &name, const std::string &text,
                     const std::vector<std::string> &phrases, const FieldSelection &field = {}) {
    const std::string path = tmp.write(name, text);
    expect_error([&] { read_mesh(path, field); }, path, phrases);
  };
  refused("missing.pvtu", pvtu({"a.vtu", "nowhere.vtu"}),
          {"piece 1 of 2: " + tmp.file("nowhere.vtu") + ": cannot open"});
  refused("field.pvtu", pvtu({"a.vtu", "u.vtu"}),
          {tmp.file("u.vtu") + ": field 'U' differs from " + tmp.file("a.vtu") + "'s 'T'"});
  refused("named.pvtu", pvtu({"a.vtu", "u.vtu"}), {"piece 1 of 2", "no point-data array named 'T'"},
          FieldSelection("T"));
  refused("outside.pvtu", pvtu({"a.vtu", "../a.vtu"}),
          {"piece 1 Source '../a.vtu' is outside the collection's directory"});
  refused("outside2.pvtu", pvtu({"sub/../../x.vtu"}), {"outside the collection's directory"});
  refused("absolute.pvtu", pvtu({tmp.file("a.vtu")}), {"is an absolute path"});
  refused("self.pvtu", pvtu({"self.pvtu"}), {"Source 'self.pvtu' is the collection itself"});
  refused("nested.pvtu", pvtu({"missing.pvtu"}), {"is not a .vtu file"});
  refused("no-source.pvtu", pvtu({""}), {"piece 0 Source is empty or missing"});
  refused("twice.pvtu", pvtu({"a.vtu", "./a.vtu"}), {"pieces 0 and 1 are both"});
  refused("none.pvtu", pvtu({}), {"no <Piece> in <PUnstructuredGrid>"});
  refused("level.pvtu",
          "<VTKFile type=\"PUnstructuredGrid\"><PUnstructuredGrid GhostLevel=\"x\"><Piece "
          "Source=\"a.vtu\"/></PUnstructuredGrid></VTKFile>",
          {"GhostLevel 'x'"});
  refused("type.pvtu", pvd({{"0", "0", "a.vtu"}}), {"VTK file type is 'Collection'"});
  refused("xml.pvtu", "<VTKFile type=\"PUnstructuredGrid\"><PUnstructured", {"not valid XML"});
  refused("attr.pvtu",
          "<VTKFile type=\"PUnstructuredGrid\" type=\"X\"><PUnstructuredGrid/></VTKFile>",
          {"attribute type twice"});
  refused("empty.pvtu", "", {"the file is empty"});
  refused("step.pvtu", pvtu({"a.vtu"}), {"--step / --time: a .pvtu file holds one time step"}, [] {
    FieldSelection f;
    f.step = 0;
    return f;
  }());
  // A broken piece: its own error, after the collection and the piece.
  tmp.write("broken.vtu", "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>");
  refused("broken.pvtu", pvtu({"a.vtu", "broken.vtu"}),
          {"piece 1 of 2: " + tmp.file("broken.vtu") + ": not valid XML"});
}

// The piece element of a piece's text.
std::string piece_element(const std::string &text) {
  const std::size_t begin = text.find("<Piece "), end = text.find("</Piece>") + 8;
  return text.substr(begin, end - begin);
}

TEST(VtuCollections, GhostArraysOfSeveralPiecesInOneFile) {
  TempDir tmp;
  // A file of two <Piece>s, the second only with ghost levels: zeros for the first's cells.
  const std::string two = piece({0});
  const std::size_t at = two.find("</UnstructuredGrid>");
  tmp.write("two.vtu",
            two.substr(0, at) + piece_element(piece({0, 1}, {0})) + "\n" + two.substr(at));
  const MeshInput m = read_mesh(tmp.write("two.pvtu", pvtu({"two.vtu"})));
  EXPECT_EQ(m.num_cells(), 2u);  // the ghost cell dropped
  EXPECT_EQ(m.num_points(), 6u); // its point 0 too; a file's own pieces are not merged
  // A ghost flag that is none.
  std::string bad = piece({0}, {0});
  const std::string flag = "Name=\"vtkGhostType\" format=\"ascii\"> 1<";
  bad.replace(bad.find(flag), flag.size(), "Name=\"vtkGhostType\" format=\"ascii\"> 300<");
  tmp.write("bad.vtu", bad);
  const std::string path = tmp.write("bad.pvtu", pvtu({"bad.vtu"}));
  expect_error([&] { read_mesh(path); }, path, {"value 0 is 300, not a ghost flag (0 to 255)"});
}

TEST(VtuCollections, BudgetCoversAllPieces) {
  TempDir tmp;
  tmp.write("a.vtu", piece({0}));
  tmp.write("b.vtu", piece({1}));
  const std::string path = tmp.write("two.pvtu", pvtu({"a.vtu", "b.vtu"}));
  ReadLimits limits;
  limits.max_memory_bytes = estimate_memory_bytes(4, 1, 4); // one piece fits, not both
  EXPECT_EQ(read_vtu(tmp.file("a.vtu"), {}, limits).num_cells(), 1u);
  expect_error([&] { read_mesh(path, {}, limits); }, path,
               {"piece 1 of 2", "6 points and 2 cells (with the pieces read before) need"});
}

TEST(VtuCollections, PvdChoosesAStep) {
  TempDir tmp;
  tmp.write("s0.vtu", piece({0, 1}, {}, false, {.k = 0}));
  tmp.write("s1a.vtu", piece({0}, {}, false, {.k = 1}));
  tmp.write("s1b.vtu", piece({1}, {}, false, {.k = 1}));
  tmp.write("s1.pvtu", pvtu({"s1a.vtu", "s1b.vtu"}));
  tmp.write("s2.vtu", piece({0, 1}, {}, false, {.k = 2}));
  // Out of time order; step 0.5 in two parts.
  const std::string path = tmp.write("series.pvd", pvd({{"1e0", "0", "s2.vtu"},
                                                        {"0", "0", "s0.vtu"},
                                                        {" 0.5 ", "0", "s1a.vtu"},
                                                        {"0.5", "1", "s1b.vtu"}}));
  const std::vector<PvdStep> steps = read_pvd_steps(path);
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[1].time, 0.5);
  EXPECT_EQ(steps[1].listed, (std::vector<std::string>{"s1a.vtu", "s1b.vtu"}));
  MeshInput m = read_mesh(path);
  expect_square(m, 2);
  EXPECT_EQ(m.field_detail, "(step 2 of 3, time 1: s2.vtu)");
  FieldSelection f;
  f.step = 1;
  m = read_mesh(path, f);
  expect_square(m, 1);
  EXPECT_EQ(m.field_detail, "(step 1 of 3, time 0.5: 2 parts)");
  f.step = -3;
  expect_square(read_mesh(path, f), 0);
  f.time = 0.5 * (1 + 1e-12);
  expect_square(read_mesh(path, f), 1);
  f.time = 0.25;
  expect_error([&] { read_mesh(path, f); }, path,
               {"--time 0.25: no step at that time (the 3 steps' times: 0, 0.5, 1)"});
  f.time.reset();
  f.step = 3;
  expect_error([&] { read_mesh(path, f); }, path,
               {"--step 3: the collection has 3 steps (0 to 2, or -3 to -1 from the end)"});
  // A .pvtu step, and a step without a time.
  const std::string one = tmp.write("pvtu.pvd", pvd({{"", "0", "s1.pvtu"}}));
  m = read_mesh(one);
  expect_square(m, 1);
  EXPECT_EQ(m.field_detail, "(step 0 of 1: s1.pvtu)");
  f.step = -1;
  f.time = 0;
  expect_error([&] { read_mesh(one, f); }, one, {"have no timestep"});
}

TEST(VtuCollections, MalformedPvdNamesTheFile) {
  TempDir tmp;
  tmp.write("a.vtu", piece({0, 1}));
  auto refused = [&](const std::string &name, const std::string &text,
                     const std::vector<std::string> &phrases) {
    const std::string path = tmp.write(name, text);
    expect_error([&] { read_mesh(path); }, path, phrases);
  };
  refused("self.pvd", pvd({{"0", "0", "self.pvd"}}), {"file 'self.pvd' is the collection itself"});
  tmp.write("other.pvd", pvd({{"0", "0", "cycle.pvd"}}));
  refused("cycle.pvd", pvd({{"0", "0", "other.pvd"}}),
          {"is not a .vtu or .pvtu file (collections of collections are not read)"});
  refused("empty.pvd", pvd({}), {"no <DataSet> in <Collection>"});
  refused("bad-time.pvd", pvd({{"abc", "0", "a.vtu"}}),
          {"DataSet 0: timestep 'abc' is not a finite number"});
  refused("nan-time.pvd", pvd({{"0", "0", "a.vtu"}, {"nan", "0", "a.vtu"}}),
          {"DataSet 1: timestep 'nan'"});
  refused("some-time.pvd", pvd({{"0", "0", "a.vtu"}, {"", "0", "a.vtu"}}),
          {"DataSet 1 has no timestep and DataSet 0 has one"});
  refused("same-part.pvd", pvd({{"0", "0", "a.vtu"}, {"0", "0", "a.vtu"}}),
          {"DataSets 0 and 1 are both part '0' of timestep 0"});
  refused("outside.pvd", pvd({{"0", "0", "../a.vtu"}}), {"outside the collection's directory"});
  refused("vtp.pvd", pvd({{"0", "0", "a.vtp"}}), {"'a.vtp' is not a .vtu or .pvtu file"});
  refused("missing.pvd", pvd({{"0", "0", "a.vtu"}, {"1", "0", "gone.vtu"}}),
          {"step 1 of 2, time 1: " + tmp.file("gone.vtu") + ": cannot open"});
  refused("type.pvd", pvtu({"a.vtu"}),
          {"VTK file type is 'PUnstructuredGrid', expected Collection"});
}

} // namespace
} // namespace hoct
