// The VTU writer and reader: exact round trips in every encoding and degree, base64 edge cases,
// and a clear error (file name and what is wrong) for every kind of malformed file.
#include "datasets/datasets.hpp"
#include "io/base64.hpp"
#include "io/vtu_reader.hpp"
#include "io/vtu_writer.hpp"
#include "poly/lattice.hpp"
#include "test_meshes.hpp"
#include "util/error.hpp"

#include "test_temp_dir.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace hoct {
namespace {

namespace fs = std::filesystem;

struct TempDir : testing::TempDir {
  TempDir() : testing::TempDir("hoct-vtu") {}
};

TEST(Base64, RoundTripAndConcatenatedStreams) {
  std::mt19937_64 rng(1);
  for (int n = 0; n < 40; ++n) {
    std::vector<uint8_t> data(n);
    for (auto &b : data)
      b = static_cast<uint8_t>(rng());
    const std::string text = base64_encode(data.data(), data.size());
    EXPECT_EQ(text.size(), base64_length(data.size()));
    EXPECT_EQ(base64_decode(text), data);
    // Two separately padded streams decode to the concatenation (VTK's header + data).
    const std::string twice = text + "\n  " + base64_encode(data.data(), data.size() / 2);
    std::vector<uint8_t> expected = data;
    expected.insert(expected.end(), data.begin(), data.begin() + n / 2);
    EXPECT_EQ(base64_decode(twice), expected);
  }
  EXPECT_EQ(base64_encode("hello", 5), "aGVsbG8=");
  try {
    base64_decode("aGVs*G8=");
    FAIL();
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("offset 4"), std::string::npos) << e.what();
  }
  EXPECT_THROW(base64_decode("aGVsbG8"), std::invalid_argument); // truncated
  EXPECT_THROW(base64_decode("a=Vs"), std::invalid_argument);    // misplaced padding
}

TEST(VtuRoundTrip, EveryEncodingAndDegree) {
  TempDir tmp;
  for (int d = 1; d <= 8; ++d) {
    std::mt19937_64 rng(d);
    std::vector<Vec3> v;
    std::vector<std::array<int64_t, 3>> t;
    testing::square_grid(2, rng, v, t);
    MeshInput in = testing::lagrange_mesh(
        v, t, [&](int64_t) { return d; }, nullptr, nullptr, rng);
    in.field_name = "p & <q>";
    for (auto enc : {VtkEncoding::Ascii, VtkEncoding::Base64, VtkEncoding::Base64Zlib,
                     VtkEncoding::AppendedRaw, VtkEncoding::AppendedBase64}) {
      const std::string path = tmp.file("rt.vtu");
      write_vtu(path, in, enc);
      // Read whole, and with raw appended arrays read from the file one by one (what files
      // above ReadLimits::stream_appended_above get).
      ReadLimits streamed;
      streamed.stream_appended_above = 0;
      for (const MeshInput &out : {read_vtu(path), read_vtu(path, "", streamed)}) {
        EXPECT_EQ(out.field_name, in.field_name);
        ASSERT_EQ(out.points.size(), in.points.size());
        EXPECT_EQ(0, std::memcmp(out.points.data(), in.points.data(), in.points.size() * 24));
        EXPECT_EQ(0, std::memcmp(out.values.data(), in.values.data(), in.values.size() * 8));
        EXPECT_EQ(out.cell_nodes, in.cell_nodes) << "degree " << d;
        EXPECT_EQ(out.cell_degree, in.cell_degree);
        EXPECT_EQ(out.source, path);
      }
    }
  }
}

// Arrays of several read parts (4 MiB each), streamed from the file in parts on 1, 2 and 3
// threads (their pages mapped in parts first): the same arrays as written.
TEST(VtuRoundTrip, LargeArraysReadInPartsOnThreads) {
  TempDir tmp;
  DatasetOptions o;
  o.cells = 80000;
  o.degree = 4;
  const MeshInput in = generate_dataset("random", o);
  // Points (24 bytes each) and connectivity (8 bytes per node) over two parts, values not.
  ASSERT_GT(in.points.size() * 24, std::size_t{12} << 20);
  ASSERT_GT(in.cell_nodes.size() * 8, std::size_t{8} << 20);
  const std::string path = tmp.file("large.vtu");
  write_vtu(path, in, VtkEncoding::AppendedRaw);
  for (int threads : {1, 2, 3}) {
    ReadLimits streamed;
    streamed.stream_appended_above = 0;
    streamed.threads = threads;
    const MeshInput out = read_vtu(path, "", streamed);
    ASSERT_EQ(out.points.size(), in.points.size());
    EXPECT_EQ(0, std::memcmp(out.points.data(), in.points.data(), in.points.size() * 24))
        << threads << " threads";
    ASSERT_EQ(out.values.size(), in.values.size());
    EXPECT_EQ(0, std::memcmp(out.values.data(), in.values.data(), in.values.size() * 8));
    EXPECT_EQ(out.cell_nodes, in.cell_nodes) << threads << " threads";
    EXPECT_EQ(out.cell_degree, in.cell_degree);
  }
}

// A valid ascii file with two quadratic triangles, to be broken in many ways.
struct Fixture {
  std::string points = "0 0 0 1 0 0 1 1 0 0 1 0 0.5 0 0 1 0.5 0 0.5 0.5 0 0.5 1 0 0 0.5 0";
  std::string conn = "0 1 2 4 5 6 0 2 3 6 7 8";
  std::string offsets = "6 12", types = "22 22", values = "0 1 2 3 4 5 6 7 8";
  std::string npoints = "9", extra_root;
  std::string text() const {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"" +
           extra_root + ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + npoints +
           "\" NumberOfCells=\"2\">\n<PointData>\n<DataArray type=\"Float64\" Name=\"T\" "
           "format=\"ascii\">" +
           values +
           "</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">" +
           points +
           "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" "
           "Name=\"connectivity\" format=\"ascii\">" +
           conn + "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
           offsets + "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" +
           types + "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  }
};

template <class F> std::string with(F &&change) {
  Fixture f;
  change(f);
  return f.text();
}

void expect_error(const TempDir &tmp, const std::string &content, const std::string &phrase,
                  const std::string &scalar = "", const ReadLimits &limits = {}) {
  const std::string path = tmp.write("bad.vtu", content);
  try {
    read_vtu(path, scalar, limits);
    ADD_FAILURE() << "accepted a file that should fail with: " << phrase;
  } catch (const InputError &e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
    EXPECT_NE(msg.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << msg;
  }
}

TEST(VtuReader, ValidFixtureReads) {
  TempDir tmp;
  const MeshInput m = read_vtu(tmp.write("ok.vtu", Fixture().text()));
  EXPECT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.field_name, "T");
  // VTK order (corners, then edge midpoints) -> lattice order (0,0) (1,0) (2,0) (0,1) (1,1) (0,2)
  const std::vector<int64_t> first(m.cell_nodes.begin(), m.cell_nodes.begin() + 6);
  EXPECT_EQ(first, (std::vector<int64_t>{0, 4, 1, 6, 5, 2}));
}

// The text of the fixture with `from` replaced by `to` (which must occur).
std::string edited(const std::string &from, const std::string &to) {
  std::string s = Fixture().text();
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

// What XML parsers let pass and would make one of two readings win silently (issue 27, item
// 13): refused with the element and its line. Empty pieces are read as nothing.
TEST(VtuReader, AmbiguousXmlIsRefused) {
  TempDir tmp;
  const std::string array_t = "<DataArray type=\"Float64\" Name=\"T\" format=\"ascii\">";
  expect_error(tmp, edited("Name=\"T\"", "Name=\"T\" Name=\"U\""),
               "<DataArray> at line 6 has the attribute Name twice ('T' and 'U'): not "
               "well-formed XML");
  expect_error(tmp, edited("NumberOfCells=\"2\"", "NumberOfCells=\"2\" NumberOfCells=\"1\""),
               "<Piece> at line 4 has the attribute NumberOfCells twice ('2' and '1')");
  expect_error(tmp, Fixture().text() + "<VTKFile type=\"UnstructuredGrid\"/>\n",
               "a second root element <VTKFile> at line 19 after <VTKFile>");
  expect_error(tmp, edited(array_t, array_t + "9 9 9 9 9 9 9 9 9</DataArray>\n" + array_t),
               "two DataArrays named 'T' in <PointData> at line 5 (<DataArray> at line 6 and "
               "<DataArray> at line 7)");
  expect_error(tmp,
               edited("<DataArray type=\"Int64\" Name=\"offsets\"",
                      "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 4 5 "
                      "6 0 2 3 6 7 8</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\""),
               "two DataArrays named 'connectivity' in <Cells>");
  expect_error(tmp, edited("</Points>", "</Points>\n<Points></Points>"),
               "a second <Points> at line 11 in <Piece> at line 4 (the first is <Points> at "
               "line 8)");
  expect_error(tmp,
               edited("</Piece>\n</UnstructuredGrid>", "</Piece>\n</UnstructuredGrid>\n"
                                                       "<UnstructuredGrid/>"),
               "a second <UnstructuredGrid>");
  expect_error(tmp,
               edited("</Points>", "<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                                   "format=\"ascii\">0 0 0</DataArray></Points>"),
               "a second <DataArray> at line 10 in <Points> at line 8");
  // Empty pieces (a parallel writer's idle ranks) before and after: read as nothing.
  const std::string empty = "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"/>\n";
  const MeshInput m = read_vtu(
      tmp.write("empty-pieces.vtu",
                edited("<Piece ", empty + "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\">\n"
                                          "</Piece>\n<Piece ")));
  EXPECT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.num_points(), 9u);
  EXPECT_EQ(m.field_name, "T");
  const MeshInput after = read_vtu(
      tmp.write("empty-after.vtu", edited("</UnstructuredGrid>", empty + "</UnstructuredGrid>")));
  EXPECT_EQ(after.num_cells(), 2u);
  expect_error(tmp,
               "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n"
               "<UnstructuredGrid>\n" +
                   empty + empty + "</UnstructuredGrid>\n</VTKFile>\n",
               "the file has no cells");
}

// The default field skips ids, ghost levels and masks, whatever their type or the active
// scalars say (DOLFINx writes vtkOriginalPointIds first: its tree is the ids'); a named one is
// read as named; vector arrays give a component or their magnitude (issue 28, item 1).
TEST(VtuReader, DefaultFieldSkipsIdsAndVectorsGiveComponents) {
  TempDir tmp;
  const std::string array_t = "<DataArray type=\"Float64\" Name=\"T\" format=\"ascii\">";
  const std::string ids =
      "<DataArray type=\"Float64\" Name=\"vtkOriginalPointIds\" format=\"ascii\">8 7 6 5 4 3 2 1 "
      "0</DataArray>\n<DataArray type=\"UInt8\" Name=\"vtkGhostType\" format=\"ascii\">0 0 0 0 0 "
      "0 0 0 0</DataArray>\n<DataArray type=\"Int32\" Name=\"GlobalIds\" format=\"ascii\">0 1 2 3 "
      "4 5 6 7 8</DataArray>\n<DataArray type=\"Float64\" Name=\"U\" NumberOfComponents=\"2\" "
      "format=\"ascii\">3 4 3 4 3 4 3 4 3 4 0 1 0 1 0 1 0 1</DataArray>\n";
  const std::string text = edited(array_t, ids + array_t);
  const MeshInput m = read_vtu(tmp.write("ids-first.vtu", text));
  EXPECT_EQ(m.field_name, "T");
  EXPECT_EQ(m.values, (PooledVector<double>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
  // Active scalars naming the ids: still T.
  std::string active = text;
  active.replace(active.find("<PointData>"), 11, "<PointData Scalars=\"vtkOriginalPointIds\">");
  EXPECT_EQ(read_vtu(tmp.write("active-ids.vtu", active)).field_name, "T");
  // Active scalars naming a real field: that one, even after another.
  std::string active_t =
      edited(array_t, "<DataArray type=\"Float64\" Name=\"S\" format=\"ascii\">1 "
                      "1 1 1 1 1 1 1 1</DataArray>\n" +
                          array_t);
  active_t.replace(active_t.find("<PointData>"), 11, "<PointData Scalars=\"T\">");
  EXPECT_EQ(read_vtu(tmp.write("active-t.vtu", active_t)).field_name, "T");
  EXPECT_EQ(read_vtu(tmp.write("first-s.vtu", edited(array_t, "<DataArray type=\"Float64\" "
                                                              "Name=\"S\" format=\"ascii\">1 1 1 "
                                                              "1 1 1 1 1 1</DataArray>\n" +
                                                                  array_t)))
                .field_name,
            "S");
  // Named: read as named, ids too.
  EXPECT_EQ(read_vtu(tmp.write("named.vtu", text), "vtkOriginalPointIds").values[0], 8);
  // Only ids: refused, saying so.
  expect_error(tmp,
               edited(array_t + "0 1 2 3 4 5 6 7 8</DataArray>",
                      ids.substr(0, ids.find("<DataArray type=\"Float64\" Name=\"U\""))),
               "no scalar (one-component) point-data array but ids, ghost levels or masks "
               "(available: vtkOriginalPointIds, vtkGhostType, GlobalIds): name one with --scalar");
  // Components of U = (3, 4) on the first five points, (0, 1) on the others.
  FieldSelection u0("U");
  u0.component = 0;
  const MeshInput c0 = read_vtu(tmp.write("u0.vtu", text), u0);
  EXPECT_EQ(c0.field_name, "U[0]");
  EXPECT_EQ(c0.values, (PooledVector<double>{3, 3, 3, 3, 3, 0, 0, 0, 0}));
  FieldSelection norm; // no name: the first vector array
  norm.component = FieldSelection::kMagnitude;
  const MeshInput n = read_vtu(tmp.write("norm.vtu", text), norm);
  EXPECT_EQ(n.field_name, "|U|");
  EXPECT_EQ(n.values, (PooledVector<double>{5, 5, 5, 5, 5, 1, 1, 1, 1}));
  expect_error(tmp, text,
               "point-data array 'U' has 2 components; a scalar field needs 1 (choose one with "
               "--component N, or --component magnitude)",
               "U");
  FieldSelection u2("U");
  u2.component = 2;
  const std::string path = tmp.write("u2.vtu", text);
  try {
    read_vtu(path, u2);
    ADD_FAILURE() << "component 2 of a 2-vector accepted";
  } catch (const InputError &e) {
    EXPECT_NE(
        std::string(e.what()).find("--component 2: point-data array 'U' has 2 components (0 to 1)"),
        std::string::npos)
        << e.what();
  }
  FieldSelection step;
  step.step = 2;
  EXPECT_THROW(read_vtu(path, step), InputError);
  EXPECT_EQ(parse_component("magnitude"), FieldSelection::kMagnitude);
  EXPECT_EQ(parse_component("y"), 1);
  EXPECT_EQ(parse_component("12"), 12);
  EXPECT_THROW(parse_component("1.5"), Error);
  EXPECT_THROW(parse_component("-1"), Error);
}

TEST(VtuReader, MalformedFilesGiveClearErrors) {
  TempDir tmp;
  const std::string ok = Fixture().text();
  expect_error(tmp, ok.substr(0, ok.size() / 2), "not valid XML");
  expect_error(tmp, "hello world", "not valid XML");
  expect_error(tmp, "", "empty");
  expect_error(tmp, "<?xml version=\"1.0\"?><VTKFile type=\"PolyData\"></VTKFile>",
               "expected UnstructuredGrid");
  expect_error(tmp, "<?xml version=\"1.0\"?><foo/>", "no <VTKFile>");
  expect_error(tmp, with([](Fixture &f) { f.points = "0 0 0 1 0 0"; }),
               "has 6 values, expected 27");
  expect_error(tmp, ok, "no point-data array named 'P' (available: T)", "P");
  expect_error(tmp, with([](Fixture &f) { f.points.replace(f.points.size() - 1, 1, "zero"); }),
               "is not a number: 'zero'");
  expect_error(tmp, with([](Fixture &f) { f.conn = "0 1 2 4 5 6 0 2 3 6 7 99"; }),
               "cell 1 refers to point 99");
  expect_error(tmp, with([](Fixture &f) { f.conn = "0 1 2 4 5 6 0 2 3 6 7 -1"; }),
               "cell 1 refers to point -1");
  expect_error(tmp, with([](Fixture &f) { f.conn = "0 1 2 4 5 6 0 2 3 6 7 1.5"; }),
               "is not an integer: '1.5'");
  expect_error(tmp, with([](Fixture &f) { f.offsets = "6 5"; }), "more values than the 5 expected");
  expect_error(tmp, with([](Fixture &f) {
                 f.offsets = "15 12";
                 f.types = "69 22";
               }),
               "cell 0: offset 15 is beyond the connectivity (12 values)");
  expect_error(tmp, with([](Fixture &f) { f.offsets = "6"; }), "has 1 values, expected 2");
  expect_error(tmp, with([](Fixture &f) { f.types = "22 10"; }),
               "VTK cell type 10, which is not a supported surface cell");
  expect_error(tmp, with([](Fixture &f) { f.types = "22 9"; }), "of type 9 has 6 nodes");
  expect_error(tmp, with([](Fixture &f) { f.types = "22 5"; }), "cell 1 of type 5 has 6 nodes");
  expect_error(tmp, with([](Fixture &f) {
                 f.conn = "0 1 2 4 5 6 7 0 2 3 6 7 8";
                 f.offsets = "7 13";
                 f.types = "69 22";
               }),
               "7-node 'bubble' triangle");
  expect_error(tmp, with([](Fixture &f) { f.values = "0 1 2 3 nan 5 6 7 8"; }),
               "point 4 has a non-finite value");
  expect_error(tmp, with([](Fixture &f) { f.values = "0 1 2 3"; }), "has 4 values, expected 9");
  expect_error(tmp, with([](Fixture &f) { f.npoints = "999999999999"; }),
               "exceed what the file can hold");
  expect_error(tmp, with([](Fixture &f) { f.npoints = "nine"; }), "bad NumberOfPoints");
  expect_error(tmp, with([](Fixture &f) { f.extra_root = " compressor=\"vtkLZ4DataCompressor\""; }),
               "unsupported compressor 'vtkLZ4DataCompressor'");
  expect_error(tmp, with([](Fixture &f) { f.extra_root = " header_type=\"UInt16\""; }),
               "unsupported header_type");
  std::string no_points = ok;
  no_points.replace(no_points.find("<Points>"), std::strlen("<Points>"), "<Pointz>");
  no_points.replace(no_points.find("</Points>"), std::strlen("</Points>"), "</Pointz>");
  expect_error(tmp, no_points, "no <Points> DataArray");
  std::string no_types = ok;
  no_types.replace(no_types.find("Name=\"types\""), 12, "Name=\"typez\"");
  expect_error(tmp, no_types, "connectivity, offsets and types");
  std::string appended = ok;
  appended.replace(appended.find("format=\"ascii\">0 1 2"), 15,
                   "format=\"appended\" offset=\"0\">");
  expect_error(tmp, appended, "no <AppendedData> section");
  EXPECT_THROW(read_vtu(tmp.file("does-not-exist.vtu")), InputError);
}

TEST(VtuReader, PiecesSkippedCellsAndStoredTypes) {
  // Two pieces, a vertex cell between the triangles of the first (skipped: the cells after it
  // close the gap), and the same piece again in base64 big-endian Float32 / Int32 / UInt8 arrays
  // (converted value by value): both read to the ascii file's cells, shifted by the first
  // piece's points in the second piece.
  TempDir tmp;
  const Fixture f;
  auto piece = [&](const std::string &points, const std::string &values, const std::string &conn,
                   const std::string &offsets, const std::string &types, const char *ncells,
                   const std::string &fmt, const char *ftype, const char *itype) {
    return "<Piece NumberOfPoints=\"9\" NumberOfCells=\"" + std::string(ncells) +
           "\">\n<PointData>\n<DataArray type=\"" + ftype + "\" Name=\"T\" format=\"" + fmt +
           "\">" + values + "</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"" + ftype +
           "\" NumberOfComponents=\"3\" format=\"" + fmt + "\">" + points +
           "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"" + itype +
           "\" Name=\"connectivity\" format=\"" + fmt + "\">" + conn +
           "</DataArray>\n<DataArray type=\"" + itype + "\" Name=\"offsets\" format=\"" + fmt +
           "\">" + offsets + "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"" +
           fmt + "\">" + types + "</DataArray>\n</Cells>\n</Piece>\n";
  };
  auto file = [](const std::string &order, const std::string &pieces) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
           "byte_order=\"" +
           order + "\">\n<UnstructuredGrid>\n" + pieces + "</UnstructuredGrid>\n</VTKFile>\n";
  };
  // Piece 0: quadratic, vertex (point 8), quadratic; piece 1: the fixture's two cells.
  const std::string first = piece(f.points, f.values, "0 1 2 4 5 6 8 0 2 3 6 7 8", "6 7 13",
                                  "22 1 22", "3", "ascii", "Float64", "Int64");
  const std::string second =
      piece(f.points, f.values, f.conn, f.offsets, f.types, "2", "ascii", "Float64", "Int64");
  const MeshInput m = read_vtu(tmp.write("pieces.vtu", file("LittleEndian", first + second)));
  ASSERT_EQ(m.num_cells(), 4u);
  ASSERT_EQ(m.points.size(), 18u);
  EXPECT_EQ(m.cell_offsets, (PooledVector<int64_t>{0, 6, 12, 18, 24}));
  EXPECT_EQ(m.cell_degree, (PooledVector<uint8_t>{2, 2, 2, 2}));
  const std::vector<int64_t> a = {0, 4, 1, 6, 5, 2}, b = {0, 6, 2, 8, 7, 3};
  PooledVector<int64_t> expected(a.begin(), a.end());
  expected.insert(expected.end(), b.begin(), b.end());
  for (int64_t x : a)
    expected.push_back(x + 9);
  for (int64_t x : b)
    expected.push_back(x + 9);
  EXPECT_EQ(m.cell_nodes, expected);
  EXPECT_EQ(m.values[9 + 4], 4.0);
  EXPECT_EQ(m.points[9 + 5], (Vec3{1, 0.5, 0}));

  // The second piece stored big-endian in 4- and 1-byte types, inline base64 (UInt32 header).
  auto encode = [](const std::vector<uint8_t> &bytes) {
    std::vector<uint8_t> all = {0, 0, 0, static_cast<uint8_t>(bytes.size())};
    all.insert(all.end(), bytes.begin(), bytes.end());
    return base64_encode(all.data(), all.size());
  };
  auto big4 = [](const std::vector<uint32_t> &words) {
    std::vector<uint8_t> out;
    for (uint32_t w : words)
      for (int k = 3; k >= 0; --k)
        out.push_back(static_cast<uint8_t>(w >> (8 * k)));
    return out;
  };
  auto floats = [&](const std::string &text) {
    std::vector<uint32_t> words;
    std::istringstream in(text);
    for (float x; in >> x;) {
      uint32_t w;
      std::memcpy(&w, &x, 4);
      words.push_back(w);
    }
    return encode(big4(words));
  };
  const std::string stored =
      piece(floats(f.points), floats(f.values), encode(big4({0, 1, 2, 4, 5, 6, 0, 2, 3, 6, 7, 8})),
            encode(big4({6, 12})), encode({22, 22}), "2", "binary", "Float32", "Int32");
  const MeshInput s = read_vtu(tmp.write("stored.vtu", file("BigEndian", stored)));
  const MeshInput t = read_vtu(tmp.write("text.vtu", file("LittleEndian", second)));
  EXPECT_EQ(s.points, t.points);
  EXPECT_EQ(s.values, t.values);
  EXPECT_EQ(s.cell_nodes, t.cell_nodes);
  EXPECT_EQ(s.cell_offsets, t.cell_offsets);
  EXPECT_EQ(s.cell_degree, t.cell_degree);
}

TEST(VtuReader, BrokenBinaryData) {
  TempDir tmp;
  std::mt19937_64 rng(3);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(2, rng, v, t);
  const MeshInput in = testing::lagrange_mesh(
      v, t, [](int64_t) { return 2; }, nullptr, nullptr, rng);
  auto written = [&](VtkEncoding enc) {
    write_vtu(tmp.file("w.vtu"), in, enc);
    std::ifstream f(tmp.file("w.vtu"), std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  // Inline base64 with a bad character.
  std::string b64 = written(VtkEncoding::Base64);
  b64[b64.find("format=\"binary\">") + 20] = '*';
  expect_error(tmp, b64, "bad base64 data");
  // Corrupted zlib stream.
  std::string z = written(VtkEncoding::Base64Zlib);
  const std::size_t at = z.find("format=\"binary\">") + 60;
  z[at] = z[at] == 'A' ? 'B' : 'A';
  expect_error(tmp, z, "DataArray");
  // Appended raw data cut short, read whole and read array by array from the file.
  ReadLimits streamed;
  streamed.stream_appended_above = 0;
  std::string raw = written(VtkEncoding::AppendedRaw);
  const std::size_t us = raw.find('_', raw.find("<AppendedData"));
  for (const ReadLimits &limits : {ReadLimits{}, streamed}) {
    expect_error(tmp, raw.substr(0, us + 40) + "\n</AppendedData></VTKFile>",
                 "outside the appended data", "", limits);
    expect_error(tmp, raw.substr(0, us + 40), "malformed <AppendedData>", "", limits);
    // A header claiming an enormous array.
    std::string huge = raw;
    const uint64_t big = uint64_t{1} << 60;
    std::memcpy(&huge[us + 1], &big, 8);
    expect_error(tmp, huge, "truncated binary data", "", limits);
    // The points' header claiming more than is left, and one byte too few for a whole value.
    const std::size_t points_at = raw.find("Name=\"Points\"");
    ASSERT_NE(points_at, std::string::npos);
    const std::size_t offset_at = raw.find("offset=\"", points_at) + 8;
    const uint64_t points_offset = std::stoull(raw.substr(offset_at));
    std::string odd = raw;
    uint64_t bytes = 0;
    std::memcpy(&bytes, &odd[us + 1 + points_offset], 8);
    bytes -= 1;
    std::memcpy(&odd[us + 1 + points_offset], &bytes, 8);
    expect_error(tmp, odd, "not a whole number of Float64 values", "", limits);
  }
}

TEST(VtuReader, AppendedRawZlibWholeAndStreamed) {
  // ParaView's usual large files: zlib-compressed blocks in a raw appended section. The
  // fixture's arrays written so (one block each, UInt32 headers), read whole and array by array
  // from the file, give the ascii fixture's mesh; a block claiming more than the payload holds
  // is refused before anything is read for it.
  TempDir tmp;
  const MeshInput expected = read_vtu(tmp.write("ascii.vtu", Fixture().text()));
  std::string payload, arrays;
  auto add = [&](const std::string &tag, const void *data, std::size_t bytes) {
    uLongf csize = compressBound(static_cast<uLong>(bytes));
    std::vector<uint8_t> z(csize);
    ASSERT_EQ(compress2(z.data(), &csize, static_cast<const Bytef *>(data), bytes, 6), Z_OK);
    const uint32_t header[4] = {1, static_cast<uint32_t>(bytes), static_cast<uint32_t>(bytes),
                                static_cast<uint32_t>(csize)};
    arrays += tag + " format=\"appended\" offset=\"" + std::to_string(payload.size()) + "\"/>\n";
    payload.append(reinterpret_cast<const char *>(header), sizeof header);
    payload.append(reinterpret_cast<const char *>(z.data()), csize);
  };
  std::vector<double> xyz;
  for (const Vec3 &p : expected.points)
    xyz.insert(xyz.end(), p.begin(), p.end());
  const std::vector<int64_t> conn = {0, 1, 2, 4, 5, 6, 0, 2, 3, 6, 7, 8}, offsets = {6, 12};
  const uint8_t types[2] = {22, 22};
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                    "byte_order=\"LittleEndian\" header_type=\"UInt32\" "
                    "compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n<Piece "
                    "NumberOfPoints=\"9\" NumberOfCells=\"2\">\n<PointData>\n";
  add("<DataArray type=\"Float64\" Name=\"T\"", expected.values.data(), 9 * 8);
  xml += arrays + "</PointData>\n<Points>\n";
  arrays.clear();
  add("<DataArray type=\"Float64\" NumberOfComponents=\"3\"", xyz.data(), xyz.size() * 8);
  xml += arrays + "</Points>\n<Cells>\n";
  arrays.clear();
  add("<DataArray type=\"Int64\" Name=\"connectivity\"", conn.data(), conn.size() * 8);
  add("<DataArray type=\"Int64\" Name=\"offsets\"", offsets.data(), offsets.size() * 8);
  add("<DataArray type=\"UInt8\" Name=\"types\"", types, 2);
  xml += arrays + "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  const std::string file = xml + payload + "\n</AppendedData>\n</VTKFile>\n";
  ReadLimits streamed;
  streamed.stream_appended_above = 0;
  for (const ReadLimits &limits : {ReadLimits{}, streamed}) {
    const MeshInput m = read_vtu(tmp.write("z.vtu", file), "", limits);
    EXPECT_EQ(m.points, expected.points);
    EXPECT_EQ(m.values, expected.values);
    EXPECT_EQ(m.cell_nodes, expected.cell_nodes);
    EXPECT_EQ(m.cell_offsets, expected.cell_offsets);
    // The values' block claims 2^31 compressed bytes.
    std::string bad = file;
    const uint32_t claim = uint32_t{1} << 31;
    std::memcpy(&bad[xml.size() + 12], &claim, 4);
    expect_error(tmp, bad, "compressed block 0 claims", "", limits);
  }
}

} // namespace
} // namespace hoct
