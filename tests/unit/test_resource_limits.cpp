// Resource safety of the readers (issue 8): counts and sizes in a file are checked against the
// bytes it has before anything is allocated for them, and against the memory budget
// (ReadLimits, the CLI's --max-memory) with a "needs ~X, limit Y" message. Each hostile header
// here used to reach an allocation or a read past the data (under ASan: a report).
#include "io/base64.hpp"
#include "io/msh_reader.hpp"
#include "io/read_limits.hpp"
#include "io/vtu_reader.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/mesh.hpp"
#include "test_meshes.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace hoct {
namespace {

std::string slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

MeshInput small_mesh(int degree) {
  std::mt19937_64 rng(3);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(2, rng, v, t);
  return testing::lagrange_mesh(
      v, t, [=](int64_t) { return degree; }, nullptr, nullptr, rng);
}

// The .vtu text of small_mesh(degree) in `encoding`.
std::string vtu_text(VtkEncoding encoding, int degree = 2) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("hoct_limits_" + std::to_string(::getpid()) + ".vtu");
  write_vtu(path.string(), small_mesh(degree), encoding);
  std::string s = slurp(path.string());
  std::filesystem::remove(path);
  return s;
}

std::string error_of(const std::string &bytes, const ReadLimits &limits = {}) {
  try {
    read_vtu_buffer(bytes, "hostile.vtu", "", limits);
  } catch (const InputError &e) {
    return e.what();
  }
  return "(no error)";
}

std::string b64(const std::vector<uint64_t> &words) {
  return base64_encode(words.data(), words.size() * sizeof(uint64_t));
}

// Inline binary array whose UInt64 header claims 2^64 - 5 bytes: header + size wraps around to
// 3, which passed a "header + size <= available" check.
TEST(ResourceLimits, VtuSizeHeaderThatWrapsAround) {
  std::string s = vtu_text(VtkEncoding::Base64);
  const std::size_t at = s.find("format=\"binary\">\n") + std::strlen("format=\"binary\">\n");
  s.replace(at, 12, b64({~uint64_t{0} - 4}));
  EXPECT_NE(error_of(s).find("truncated binary data (the header claims 18446744073709551611"),
            std::string::npos)
      << error_of(s);
}

// zlib header claiming a 2 GiB block for a few compressed bytes: refused before allocating.
TEST(ResourceLimits, VtuZlibBlockThatCannotExpandThatFar) {
  std::string s = vtu_text(VtkEncoding::Base64Zlib);
  const std::size_t at = s.find("format=\"binary\">\n") + std::strlen("format=\"binary\">\n");
  // One block: header {1 block, block size, last size, compressed size} = 32 bytes, 44 chars.
  const std::vector<uint8_t> h = base64_decode(std::string_view(s).substr(at, 44));
  ASSERT_EQ(h.size(), 32u);
  uint64_t csize;
  std::memcpy(&csize, h.data() + 24, 8);
  s.replace(at, 44, b64({1, uint64_t{1} << 31, uint64_t{1} << 31, csize}));
  EXPECT_NE(error_of(s).find("cannot expand to the 2147483648 bytes"), std::string::npos)
      << error_of(s);
  // A block count beyond what the data can hold.
  s.replace(at, 44, b64({uint64_t{1} << 40, 32768, 100, csize}));
  EXPECT_NE(error_of(s).find("compression header claims 1099511627776 blocks"), std::string::npos)
      << error_of(s);
  // The last block larger than the block size.
  s.replace(at, 44, b64({1, 16, 32, csize}));
  EXPECT_NE(error_of(s).find("implausible compression header"), std::string::npos) << error_of(s);
}

// A zlib bomb: one triangle whose Points blocks (4096 copies of 1 MiB of zeros, ~1 KB each
// compressed) declare 4 GiB for the 9 values its header counts. Refused from the compression
// header before anything inflates, read whole and streamed from the file. Before: 4 GiB
// allocated and inflated, then "has 536870912 values, expected 9".
std::string zlib_bomb_vtu() {
  std::vector<uint8_t> zero(std::size_t{1} << 20, 0);
  std::vector<uint8_t> packed(compressBound(static_cast<uLong>(zero.size())));
  uLongf packed_size = static_cast<uLongf>(packed.size());
  EXPECT_EQ(compress2(packed.data(), &packed_size, zero.data(), static_cast<uLong>(zero.size()), 9),
            Z_OK);
  constexpr uint64_t kBlocks = 4096;
  std::vector<uint64_t> header = {kBlocks, zero.size(), zero.size()};
  header.resize(3 + kBlocks, packed_size);
  std::string payload(reinterpret_cast<const char *>(header.data()), header.size() * 8);
  for (uint64_t b = 0; b < kBlocks; ++b)
    payload.append(reinterpret_cast<const char *>(packed.data()), packed_size);
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\" "
         "compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid><Piece NumberOfPoints=\"3\" "
         "NumberOfCells=\"1\"><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"appended\" offset=\"0\"/></Points></Piece></UnstructuredGrid>\n"
         "<AppendedData encoding=\"raw\">_" +
         payload + "\n</AppendedData>\n</VTKFile>\n";
}

TEST(ResourceLimits, VtuZlibBombRefusedBeforeInflating) {
  const std::string s = zlib_bomb_vtu();
  ASSERT_LT(s.size(), std::size_t{5} << 20);
  const std::string expected = "DataArray in <Points> has 536870912 values (as its compression "
                               "header declares, before inflating), expected 9 Float64 values";
  EXPECT_NE(error_of(s).find(expected), std::string::npos) << error_of(s);
  // Streamed from the file (as files above ReadLimits::stream_appended_above are).
  const auto path =
      std::filesystem::temp_directory_path() / ("hoct_bomb_" + std::to_string(::getpid()) + ".vtu");
  {
    std::ofstream out(path, std::ios::binary);
    out << s;
  }
  std::string streamed = "(no error)";
  try {
    read_vtu(path.string(), "", {.stream_appended_above = 0});
  } catch (const InputError &e) {
    streamed = e.what();
  }
  std::filesystem::remove(path);
  EXPECT_NE(streamed.find(expected), std::string::npos) << streamed;
}

// Appended base64 whose first group is padded ("AA=="): the decoded header is shorter than the
// 8 bytes it must hold (was a heap read past the end).
TEST(ResourceLimits, VtuAppendedBase64ShortHeader) {
  std::string s = vtu_text(VtkEncoding::AppendedBase64);
  const std::size_t us = s.find('_', s.find("<AppendedData"));
  s.replace(us + 1, 4, "AA==");
  EXPECT_NE(error_of(s).find("truncated appended base64 header"), std::string::npos) << error_of(s);
}

// Degree 21 (the VTU reader's limit is 20, the core's kMaxDegree): a clear error.
TEST(ResourceLimits, VtuDegreeAboveTheLimit) {
  const std::string s = vtu_text(VtkEncoding::Ascii, 21);
  EXPECT_NE(error_of(s).find("has degree 21 (at most 20 supported)"), std::string::npos)
      << error_of(s);
}

// The memory budget: an estimate from the header counts, checked before reading the arrays.
TEST(ResourceLimits, VtuMemoryBudget) {
  const MeshInput m = small_mesh(3);
  const std::string s = vtu_text(VtkEncoding::Base64Zlib, 3);
  const uint64_t need = estimate_memory_bytes(m.num_points(), m.num_cells(), m.cell_nodes.size());
  EXPECT_NO_THROW(read_vtu_buffer(s, "ok.vtu", "", {.max_memory_bytes = need}));
  const std::string e = error_of(s, {.max_memory_bytes = need - 1});
  EXPECT_NE(e.find("hostile.vtu: piece 0: 49 points and 8 cells need ~"), std::string::npos) << e;
  EXPECT_NE(e.find(", limit "), std::string::npos) << e;
}

TEST(ResourceLimits, MshMemoryBudget) {
  const std::string path = std::string(HOCT_TEST_DATA) + "/msh/gmsh_square_p3_binary.msh";
  const std::string bytes = slurp(path);
  EXPECT_NO_THROW(read_msh_buffer(bytes, "ok.msh", "", {.max_memory_bytes = 64ull << 20}));
  try {
    read_msh_buffer(bytes, "big.msh", "", {.max_memory_bytes = 1 << 20});
    ADD_FAILURE() << "no error";
  } catch (const InputError &e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("big.msh: byte "), std::string::npos) << what;
    EXPECT_NE(what.find("need ~"), std::string::npos) << what;
    EXPECT_NE(what.find("limit 1 MiB"), std::string::npos) << what;
  }
}

// Finite but huge values (fuzz_vtu found 8.3e307, which gave NaN tree nodes) and coordinates:
// refused by the mesh checks beyond 1e100 in magnitude, accepted below.
TEST(ResourceLimits, ValuesAndCoordinatesBeyond1e100) {
  auto error = [](const MeshInput &m) -> std::string {
    try {
      build_mesh(m);
    } catch (const Error &e) {
      return e.what();
    }
    return "(no error)";
  };
  MeshInput m = small_mesh(2);
  m.values[3] = 1e99;
  EXPECT_EQ(error(m), "(no error)");
  m.values[3] = 8.3e307;
  EXPECT_NE(error(m).find("value out of range"), std::string::npos) << error(m);
  m.values[3] = 0;
  m.points[4][2] = -1e150;
  EXPECT_NE(error(m).find("point 4 has a coordinate beyond 1e100"), std::string::npos) << error(m);
}

TEST(ResourceLimits, EstimateGrowsWithEveryCountAndSaturates) {
  const uint64_t base = estimate_memory_bytes(0, 0, 0);
  EXPECT_GT(estimate_memory_bytes(1000, 0, 0), base);
  EXPECT_GT(estimate_memory_bytes(0, 1000, 0), base);
  EXPECT_GT(estimate_memory_bytes(0, 0, 1000), base);
  EXPECT_EQ(estimate_memory_bytes(~uint64_t{0}, ~uint64_t{0}, ~uint64_t{0}), ~uint64_t{0});
}

TEST(ResourceLimits, ParseMemorySize) {
  EXPECT_EQ(parse_memory_size("512M", 0), 512ull << 20);
  EXPECT_EQ(parse_memory_size("8G", 0), 8ull << 30);
  EXPECT_EQ(parse_memory_size("2.5GiB", 0), 5ull << 29);
  EXPECT_EQ(parse_memory_size("1024", 0), 1024u);
  EXPECT_EQ(parse_memory_size("50%", 1000), 500u);
  for (const char *bad : {"", "abc", "0", "-1G", "12Q", "150%", "1e30T"})
    EXPECT_THROW(parse_memory_size(bad, 1000), Error) << bad;
  EXPECT_THROW(parse_memory_size("50%", 0), Error);
}

} // namespace
} // namespace hoct
