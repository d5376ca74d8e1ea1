// Regression tests of the fuzzing (test/fuzz, scripts/fuzz.sh).
//
// 1. Every input a fuzzer found to crash, hang or break an invariant is kept
//    in test/fuzz/regressions/<target>/ and replayed here through the same
//    target code (test/fuzz/<target>.h): it must end in a documented error or
//    a correct result.
// 2. Each bug, minimised by hand, with the exact answer of the reader. The
//    mesh reader's bugs were in CGAL 5.5's OFF and PLY readers, which trust
//    what they read; read_triangle_mesh() now checks the file first.
#include "test_data.h"

#include "fuzz/label_file.h"
#include "fuzz/mesh_param.h"
#include "fuzz/painted_colors.h"
#include "fuzz/selection_file.h"

#include <diffuv/core/error.h>
#include <diffuv/io/read_mesh.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using diffuv_test::Mesh;

// ---------------------------------------------------------------------------
// 1. Replays

// test/fuzz/regressions, next to this file (CMake compiles it by its absolute path).
fs::path regressions_dir()
{
  return fs::path(__FILE__).parent_path() / "fuzz" / "regressions";
}

// Runs every file of regressions/<target> through `run`; returns how many.
std::size_t replay(const std::string& target, void (*run)(const std::uint8_t*, std::size_t))
{
  const fs::path dir = regressions_dir() / target;
  std::size_t count = 0;
  if(!fs::is_directory(dir)) return count;
  for(const auto& entry : fs::directory_iterator(dir)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch(const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
    ++count;
  }
  return count;
}

TEST(FuzzRegressions, ReplayEveryReproducer)
{
  if(!fs::is_directory(regressions_dir()))
    GTEST_SKIP() << regressions_dir() << " not found (this file was not compiled from the source tree)";
  EXPECT_GT(replay("mesh_param", diffuv_fuzz::mesh_param), 0u);
  replay("painted_colors", diffuv_fuzz::painted_colors);
  replay("label_file", diffuv_fuzz::label_file);
  replay("selection_file", diffuv_fuzz::selection_file);
}

// ---------------------------------------------------------------------------
// 2. The bugs, minimised

struct Case {
  const char* name;
  std::string content;
  std::size_t line;
  std::string reason;
};

// Each case must throw Input_error(file, line, reason).
class FuzzFoundMesh : public diffuv_test::Temp_dir_test {
protected:
  void expect(const std::vector<Case>& cases)
  {
    for(const Case& c : cases) {
      const std::string file = write(c.name, c.content);
      Mesh mesh;
      try {
        diffuv::read_triangle_mesh(file, mesh);
        ADD_FAILURE() << c.name << " was read without error";
      } catch(const diffuv::Input_error& e) {
        EXPECT_EQ(e.reason(), c.reason) << c.name;
        EXPECT_EQ(e.line(), c.line) << c.name;
      }
    }
  }
};

std::string big_endian32(std::int32_t v)
{
  const auto u = static_cast<std::uint32_t>(v);
  return {static_cast<char>(u >> 24), static_cast<char>((u >> 16) & 0xff), static_cast<char>((u >> 8) & 0xff),
          static_cast<char>(u & 0xff)};
}

const std::string triangle_vertices = "0 0 0\n1 0 0\n0 1 0\n";

// CGAL's PLY header reader adds a property to the last element, even when
// there is none yet (found by fuzz_mesh_param: UBSan, then a null pointer).
TEST_F(FuzzFoundMesh, PlyPropertyBeforeAnyElement)
{
  expect({{"a.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\nend_header\n" + triangle_vertices, 3,
           "not a valid PLY file (a property line comes before any element line)"}});
}

// Counts and types that CGAL's PLY reader trusts: an element without
// properties is "read" count times (4e9 points), a coordinate or colour of
// another type than CGAL asks for fails an assertion then dereferences null,
// a list length is allocated before it is read.
TEST_F(FuzzFoundMesh, PlyCountsAndTypesCheckedBeforeCgalReads)
{
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  expect({
    {"count.ply", "ply\nformat ascii 1.0\nelement vertex 4000000000\nend_header\n", 3,
     "not a valid PLY file (the header announces 4000000000 vertex items, more than the 58 bytes of the file can hold)"},
    {"int_x.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty float y\nproperty float z\n" + face +
                      "end_header\n" + triangle_vertices + "3 0 1 2\n",
     3, "not a valid PLY file (property \"x\" of element \"vertex\" is not of type float or double)"},
    {"list_x.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty list uchar float x\nproperty float y\n"
                   "property float z\n" + face + "end_header\n1 0 0 0\n1 1 0 0\n1 0 1 0\n3 0 1 2\n",
     3, "not a valid PLY file (property \"x\" of element \"vertex\" is not of type float or double)"},
    {"green.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                      "property uchar red\nproperty float green\nproperty uchar g\nproperty uchar blue\n" + face +
                      "end_header\n0 0 0 1 0.5 1 1\n1 0 0 1 0.5 1 1\n0 1 0 1 0.5 1 1\n3 0 1 2\n",
     3, "not a valid PLY file (property \"green\" of element \"vertex\" is not of type uchar)"},
    {"halfedge.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + face +
                         "element halfedge 1\nproperty int source\nproperty uint target\nend_header\n" +
                         triangle_vertices + "3 0 1 2\n0 1\n",
     9, "not a valid PLY file (property \"source\" of element \"halfedge\" is not of type uint)"},
    {"long_list.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                          "element face 1\nproperty list int int vertex_indices\nend_header\n" + triangle_vertices +
                          "2147483647 0 1 2\n",
     0, "not a valid PLY file (item 0 of element \"face\" has a list \"vertex_indices\" of 2147483647 values, more "
        "than the file can hold)"},
    // The length read fails at the end of the file: CGAL allocates an uninitialised length
    // (found by fuzz_mesh_param: a 4.7 GB allocation).
    {"unread_list.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                            "element face 1\nproperty list int int vertex_indices\nend_header\n" + triangle_vertices,
     0, "not a valid PLY file (the length of list \"vertex_indices\" of item 0 of element \"face\" cannot be read)"},
    // CGAL ignores a failed read of the faces and reads the next element's
    // list lengths from the failed stream, uninitialised (found by
    // fuzz_mesh_param in CI: a 3.4 GB, then a 7 GB allocation).
    {"faces_then_lists.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                                 "element face 1\nproperty list uchar int vertex_indices\nproperty double q\n"
                                 "element other 1\nproperty list int int stuff\nend_header\n" + triangle_vertices +
                                 "3 0 1 2\n",
     0, "not a valid PLY file (item 0 of element \"face\" ends before its property \"q\" can be read, and a later "
        "element has lists)"},
    {"negative_list.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                              "element face 1\nproperty list int int vertex_indices\nend_header\n" +
                              triangle_vertices + "-3 0 1 2\n",
     0, "not a valid PLY file (item 0 of element \"face\" has a list \"vertex_indices\" of -3 values, a negative "
        "length)"},
  });

  // The same long list in binary (big-endian uint length).
  std::string binary = "ply\nformat binary_big_endian 1.0\nelement vertex 3\n" + xyz +
                       "element face 1\nproperty list uint int vertex_indices\nend_header\n";
  for(float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    binary += big_endian32(static_cast<std::int32_t>(u));
  }
  binary += big_endian32(-1) + big_endian32(0) + big_endian32(1) + big_endian32(2); // length 4294967295
  expect({{"long_list_binary.ply", binary, 0,
           "not a valid PLY file (item 0 of element \"face\" has a list \"vertex_indices\" of 4294967295 values, "
           "more than the file can hold)"}});

  // What stays valid: 32-bit list lengths that fit.
  Mesh mesh;
  EXPECT_EQ(diffuv::read_triangle_mesh(write("ok.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                                                           "element face 1\nproperty list uint int vertex_indices\n"
                                                           "end_header\n" + triangle_vertices + "3 0 1 2\n"),
                                       mesh)
                .faces,
            1u);
}

// CGAL's OFF reader converts a face size and indices to std::size_t as read
// (a negative one is undefined behaviour: found by fuzz_mesh_param, UBSan) and
// allocates the face before reading its indices.
TEST_F(FuzzFoundMesh, OffFaceSizesCheckedBeforeCgalReads)
{
  const std::string head = "OFF\n3 1 0\n" + triangle_vertices;
  expect({
    {"negative.off", head + "-1 0 1 2\n", 6, "not a valid OFF file (face 0 does not start with its number of vertices)"},
    {"huge.off", head + "300000000 0 1 2\n", 6,
     "not a valid OFF file (face 0 lists fewer than its 300000000 vertex indices)"},
    // CGAL doubles the number of edges, an int (found by fuzz_mesh_param: UBSan, signed overflow).
    {"edges.off", "OFF\n3 1 2000000000\n" + triangle_vertices + "3 0 1 2\n", 2,
     "not a valid OFF file (the number of edges 2000000000 is out of range)"},
    // "1-2" is one number for CGAL, two for operator>>: both readings are checked.
    {"cgal_syntax.off", head + "3 0 1-2 2\n", 6, "face 0 has vertex index -2, out of range (the file has 3 vertices)"},
  });

  // Binary OFF: three big-endian counts, then big-endian floats and integers.
  std::string binary = "OFF BINARY\n" + big_endian32(3) + big_endian32(1) + big_endian32(0);
  for(float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    binary += big_endian32(static_cast<std::int32_t>(u));
  }
  expect({
    {"huge_binary.off", binary + big_endian32(2147483647) + big_endian32(0) + big_endian32(1) + big_endian32(2), 0,
     "not a valid OFF file (face 0 has 2147483647 vertices, more than the file can hold)"},
    {"unread_binary.off", binary, 0, "not a valid OFF file (the file ends before face 0 of 1)"},
    {"edges_binary.off", "OFF BINARY\n" + big_endian32(3) + big_endian32(1) + big_endian32(1330005514) + binary.substr(23) +
                             big_endian32(3) + big_endian32(0) + big_endian32(1) + big_endian32(2),
     1, "not a valid OFF file (the number of edges 1330005514 is out of range)"},
    {"negative_binary.off", binary + big_endian32(-5) + big_endian32(0) + big_endian32(1) + big_endian32(2), 0,
     "not a valid OFF file (face 0 has -5 vertices, a negative number)"},
  });
  Mesh mesh;
  EXPECT_EQ(diffuv::read_triangle_mesh(
                write("ok_binary.off", binary + big_endian32(3) + big_endian32(0) + big_endian32(1) + big_endian32(2)),
                mesh)
                .faces,
            1u);
}

// CGAL's OFF reader reads texture coordinates, normals and colours at
// positions it does not check: STOFF (texture without colour) at an
// uninitialised position (found by fuzz_mesh_param: ASan SEGV), a short
// coloured line past the end of its vector, colour values and colour-map
// indices converted or looked up unchecked.
TEST_F(FuzzFoundMesh, OffColorsNormalsAndTexturesCheckedBeforeCgalReads)
{
  const std::string face = "3 0 1 2\n";
  expect({
    {"stoff.off", "STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n" + face, 1,
     "not a valid OFF file (texture coordinates without colours (STOFF) cannot be read)"},
    {"short.off", "CNOFF\n3 1 0\n0 0 0\n1 0 0 0 0 1\n0 1 0 0 0 1\n" + face, 3,
     "not a valid OFF file (vertex 0 has 3 numbers; CNOFF needs 6)"},
    {"component.off", "COFF\n3 1 0\n0 0 0 300 0 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n" + face, 3,
     "not a valid OFF file (vertex 0 has colour component 300, outside [0, 255] (integers))"},
    {"float.off", "COFF\n3 1 0\n0 0 0 0.5 2.5 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n" + face, 3,
     "not a valid OFF file (vertex 0 has colour component 2.5, outside [0, 1])"},
    {"map.off", "COFF\n3 1 0\n0 0 0 1000\n1 0 0 1\n0 1 0 1\n" + face, 3,
     "not a valid OFF file (vertex 0 has colour-map index 1000, outside [0, 148])"},
    {"missing.off", "COFF\n3 1 0\n0 0 0 1 1 1\n1 0 0\n0 1 0 1 1 1\n" + face, 4,
     "not a valid OFF file (vertex 1 has no colour, but an earlier one has)"},
    {"two.off", "COFF\n3 1 0\n" + triangle_vertices + "3 0 1 2 1 1\n", 6,
     "not a valid OFF file (face 0 has 2 colour components; expected 3 or 4)"},
    {"w.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n" + face, 4, "vertex 1 has a coordinate that is NaN or infinite"},
    // n-dimensional OFF (a dimension before the counts) is checked the same way.
    {"stnoff.off", "STnOFF\n3\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n" + face, 1,
     "not a valid OFF file (texture coordinates without colours (STOFF) cannot be read)"},
    {"noff.off", "nOFF\n3\n3 1 0\n" + triangle_vertices + "-1 0 1 2\n", 7,
     "not a valid OFF file (face 0 does not start with its number of vertices)"},
    {"noff_counts.off", "nOFF\n3\n3 1 2.7\n" + triangle_vertices + face, 3,
     "not a valid OFF file (cannot read the numbers of vertices, faces and edges)"},
  });

  // What stays valid: colours of every kind, texture coordinates with colours.
  Mesh mesh;
  for(const std::string& content :
      {"COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0.5 0.5 0.5\n0 1 0 7\n3 0 1 2 0 0 255\n",
       "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0 0 0\n1 0 0 0 0 1 0 1 0 1 0\n0 1 0 0 0 1 0 0 1 0 1\n3 0 1 2\n",
       "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0.5 0.5 0.5\n", "nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"})
    EXPECT_EQ(diffuv::read_triangle_mesh(write("ok.off", content), mesh).faces, 1u) << content;
}

// A polygon whose first and last corners coincide once projected along its
// normal: CGAL's triangulate_face() inserts the closing constraint from a
// point to itself, a precondition of Constrained_triangulation_2 (found by
// fuzz_mesh_param; undefined in release builds). Such a polygon is cut as a
// fan, like the polygons that triangulate_face() refuses.
TEST_F(FuzzFoundMesh, PolygonWhoseCornersCoincideInProjectionIsCutAsAFan)
{
  for(const std::string& face : {"5 0 1 2 3 4\n", "5 4 0 1 2 3\n", "5 0 4 1 2 3\n"}) {
    const std::string off = "OFF\n5 1 0\n0 0 0\n1 0 0\n1.5 1 0\n0.5 1.5 0\n0 0 0\n" + face;
    Mesh mesh;
    const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(write("pentagon.off", off), mesh);
    EXPECT_EQ(report.polygons_triangulated, 1u) << face;
    EXPECT_EQ(num_faces(mesh), 3u) << face;
    EXPECT_TRUE(CGAL::is_triangle_mesh(mesh)) << face;
    EXPECT_TRUE(mesh.is_valid(false)) << face;
    EXPECT_EQ(report.file_face, (std::vector<std::size_t>{0, 0, 0})) << face;
  }
}

// CGAL 5.5's constrained triangulation of a strongly non-planar pentagon
// left a corrupt mesh (a vertex whose halfedge does not point to it), and
// the walk around that vertex never ended (found by fuzz_mesh_param: a
// timeout). The polygons are then cut as fans.
TEST_F(FuzzFoundMesh, CorruptTriangulationFallsBackToFans)
{
  const std::string points = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 14\n";
  // The fan of the pentagon needs edge 1-4 (a diagonal of face 1) a second time: a clear error.
  expect({{"pentagon.obj", points + "f 1 4 3 2\nf 1 2 6 5\nf 2 3 1 5 8\n", 11,
           "face 2 cannot be triangulated without a second edge between vertices 1 and 4"}});
  // Alone, the same pentagon is cut as a fan: a valid mesh.
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(write("alone.obj", points + "f 2 3 1 5 8\n"), mesh);
  EXPECT_TRUE(mesh.is_valid(false));
  EXPECT_TRUE(CGAL::is_triangle_mesh(mesh));
  EXPECT_EQ(report.polygons_triangulated, 1u);
  EXPECT_EQ(report.file_face, (std::vector<std::size_t>{0, 0, 0}));
}

} // namespace
