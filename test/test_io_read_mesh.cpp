// Tests of include/diffuv/io/read_mesh.h and the pieces in io/internal/: the
// vertex order of real meshes; every rejection with its exact message and
// line (file names and formats, the OFF, OBJ, PLY and STL scanners, the
// checks of the polygon soup); polygons cut into triangles that know their
// polygon.
//
// Expectations come from the files themselves, parsed here by hand, not
// from CGAL's readers.
#include "test_data.h"

#include <diffuv/io/read_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using diffuv_test::File_soup;
using diffuv_test::Mesh;
using diffuv_test::Point_3;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using face_descriptor = boost::graph_traits<Mesh>::face_descriptor;

using IoReadMesh = diffuv_test::Temp_dir_test;

// Reads `file` and returns the Input_error it must throw.
diffuv::Input_error read_error(const std::string& file)
{
  return diffuv_test::input_error([&] {
    Mesh mesh;
    diffuv::read_triangle_mesh(file, mesh);
  });
}

// ---------------------------------------------------------------------------
// Hand-written parsers of the real files: the expected points and faces
// (OFF: diffuv_test::parse_off()).

// ASCII PLY whose first element is "vertex" starting with x y z, and whose
// second is "face" starting with the index list.
File_soup parse_ascii_ply(const std::string& file)
{
  std::ifstream in(file);
  std::string line;
  std::vector<std::size_t> counts;
  while(std::getline(in, line) && line != "end_header") {
    std::istringstream words(line);
    std::string w, name;
    std::size_t n = 0;
    if(words >> w && w == "element" && words >> name >> n)
      counts.push_back(n);
  }
  File_soup soup;
  for(std::size_t i = 0; i < counts.at(0); ++i) {
    std::getline(in, line);
    std::istringstream words(line);
    std::array<double, 3> p;
    words >> p[0] >> p[1] >> p[2];
    soup.points.push_back(p);
  }
  for(std::size_t j = 0; j < counts.at(1); ++j) {
    std::getline(in, line);
    std::istringstream words(line);
    soup.faces.push_back(diffuv_test::read_face_indices(words));
  }
  return soup;
}

// Binary STL; points numbered by first appearance, identical ones merged.
File_soup parse_binary_stl(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  char header[80];
  in.read(header, 80);
  std::uint32_t n = 0;
  in.read(reinterpret_cast<char*>(&n), 4);
  File_soup soup;
  std::map<std::array<float, 3>, std::size_t> number;
  for(std::uint32_t t = 0; t < n; ++t) {
    float data[12];
    in.read(reinterpret_cast<char*>(data), sizeof data);
    char attribute[2];
    in.read(attribute, 2);
    std::vector<std::size_t> f;
    for(int c = 0; c < 3; ++c) {
      const std::array<float, 3> p{data[3 + 3 * c], data[4 + 3 * c], data[5 + 3 * c]};
      const auto it = number.emplace(p, soup.points.size()).first;
      if(it->second == soup.points.size())
        soup.points.push_back({double(p[0]), double(p[1]), double(p[2])});
      f.push_back(it->second);
    }
    soup.faces.push_back(f);
  }
  EXPECT_TRUE(in) << file;
  return soup;
}

// Checks that the mesh read from `file` has the file's points in the file's
// order and the file's faces in the file's order.
void expect_same_as_file(const std::string& file, const File_soup& soup)
{
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(file, mesh);
  EXPECT_EQ(report.vertices, soup.points.size()) << file;
  EXPECT_EQ(report.faces_in_file, soup.faces.size()) << file;
  EXPECT_EQ(report.polygons_triangulated, 0u) << file;
  EXPECT_EQ(report.faces, soup.faces.size()) << file;
  EXPECT_EQ(num_vertices(mesh), soup.points.size()) << file;
  EXPECT_EQ(num_faces(mesh), soup.faces.size()) << file;

  std::size_t i = 0, wrong_points = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    const Point_3& p = mesh.point(v);
    const auto& q = soup.points[i++];
    if(p.x() != q[0] || p.y() != q[1] || p.z() != q[2])
      ++wrong_points;
  }
  EXPECT_EQ(wrong_points, 0u) << file;

  std::size_t j = 0, wrong_faces = 0;
  for(face_descriptor f : faces(mesh))
    if(!diffuv_test::same_cycle(diffuv_test::face_vertex_numbers(mesh, f), soup.faces[j++]))
      ++wrong_faces;
  EXPECT_EQ(wrong_faces, 0u) << file;

  // Nothing triangulated: face j comes from polygon j.
  std::vector<std::size_t> identity(soup.faces.size());
  for(std::size_t k = 0; k < identity.size(); ++k)
    identity[k] = k;
  EXPECT_EQ(report.file_face, identity) << file;
}

// ---------------------------------------------------------------------------
// Reading real meshes

TEST(IoReadMeshReal, OffKeepsTheFileOrder)
{
  for(const char* name : {"cow.off", "nefertiti.off"}) {
    const std::string file = diffuv_test::data_path(std::string("meshes/") + name);
    const File_soup soup = diffuv_test::parse_off(file);
    expect_same_as_file(file, soup);
  }
  // The counts of the headers, written in the files.
  EXPECT_EQ(diffuv_test::parse_off(diffuv_test::data_path("meshes/cow.off")).points.size(), 2904u);
  EXPECT_EQ(diffuv_test::parse_off(diffuv_test::data_path("meshes/cow.off")).faces.size(), 5804u);
  EXPECT_EQ(diffuv_test::parse_off(diffuv_test::data_path("meshes/nefertiti.off")).points.size(), 299u);
  EXPECT_EQ(diffuv_test::parse_off(diffuv_test::data_path("meshes/nefertiti.off")).faces.size(), 562u);
}

TEST(IoReadMeshReal, PlyKeepsTheFileOrder)
{
  const std::string file = diffuv_test::data_path("meshes/colored_tetra.ply");
  const File_soup soup = parse_ascii_ply(file);
  ASSERT_EQ(soup.points.size(), 4u);
  ASSERT_EQ(soup.faces.size(), 4u);
  expect_same_as_file(file, soup);
}

TEST(IoReadMeshReal, BinaryStlNumbersPointsByFirstAppearance)
{
  const std::string file = diffuv_test::data_path("meshes/sphere.stl");
  const File_soup soup = parse_binary_stl(file);
  ASSERT_EQ(soup.faces.size(), 320u);
  ASSERT_EQ(soup.points.size(), 162u);
  expect_same_as_file(file, soup);
}

// pig.stl touches itself at single points: CGAL's read_polygon_mesh would
// silently duplicate those vertices (changing the numbering); we refuse.
TEST(IoReadMeshReal, PigStlHasNonManifoldVertices)
{
  const std::string file = diffuv_test::data_path("meshes/pig.stl");
  const diffuv::Input_error e = read_error(file);
  EXPECT_EQ(e.line(), 0u);
  EXPECT_EQ(e.reason(), "non-manifold edge or vertex, or inconsistent orientation "
                        "(the faces around vertex 90 form 2 separate fans)");
  EXPECT_EQ(std::string(e.what()), file + ": " + e.reason());
}

// ---------------------------------------------------------------------------
// Files, names and formats

const std::string triangle_off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST_F(IoReadMesh, ExtensionIsCaseInsensitive)
{
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(write("t.OfF", triangle_off), mesh);
  EXPECT_EQ(report.vertices, 3u);
  EXPECT_EQ(num_faces(mesh), 1u);
}

TEST_F(IoReadMesh, UnknownOrMissingExtension)
{
  const std::string xyz = write("t.xyz", triangle_off);
  diffuv::Input_error e = read_error(xyz);
  EXPECT_EQ(std::string(e.what()), xyz + ": unknown mesh file extension \".xyz\" (expected .off, .obj, .ply or .stl)");
  EXPECT_EQ(e.line(), 0u);
  EXPECT_EQ(e.file(), xyz);

  const std::string none = write("t", triangle_off);
  e = read_error(none);
  EXPECT_EQ(e.reason(), "the file name has no extension (expected .off, .obj, .ply or .stl)");
}

TEST_F(IoReadMesh, MissingDirectoryOrEmptyFile)
{
  diffuv::Input_error e = read_error(path("missing.off"));
  EXPECT_EQ(std::string(e.what()), path("missing.off") + ": cannot open file");
  EXPECT_EQ(e.line(), 0u);

  fs::create_directory(path("folder.off"));
  EXPECT_EQ(read_error(path("folder.off")).reason(), "is a directory, not a mesh file");
  fs::create_directory(path("folder"));
  EXPECT_EQ(read_error(path("folder")).reason(), "is a directory, not a mesh file");

  e = read_error(write("empty.obj", ""));
  EXPECT_EQ(e.reason(), "the file is empty");
  EXPECT_EQ(e.line(), 0u);
}

TEST_F(IoReadMesh, ReadingReplacesTheMeshContent)
{
  Mesh mesh;
  diffuv::read_triangle_mesh(diffuv_test::data_path("meshes/nefertiti.off"), mesh);
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(write("t.off", triangle_off), mesh);
  EXPECT_EQ(report.vertices, 3u);
  EXPECT_EQ(num_vertices(mesh), 3u);
  EXPECT_EQ(num_faces(mesh), 1u);
  EXPECT_EQ(mesh.point(*std::next(vertices(mesh).begin())), Point_3(1, 0, 0));
}

// ---------------------------------------------------------------------------
// OFF syntax: CGAL says "false"; the message says where and why.

TEST_F(IoReadMesh, OffSyntaxErrorsHaveALine)
{
  struct Case { const char* content; std::size_t line; const char* reason; };
  const Case cases[] = {
    {"OOF\n3 1 0\n", 1, "not a valid OFF file (the file does not start with an OFF header)"},
    {"# only a comment\n\n", 0, "not a valid OFF file (the file has no OFF header)"},
    {"OFF\n3 x 0\n", 2, "not a valid OFF file (cannot read the numbers of vertices, faces and edges)"},
    {"OFF\n-1 1 0\n0 0 0\n", 2, "not a valid OFF file (negative number of vertices or faces)"},
    {"OFF\n200000000 1 0\n0 0 0\n3 0 0 0\n", 2,
     "not a valid OFF file (the header announces 200000000 vertices and 1 face, "
     "more than the 32 bytes of the file can hold)"},
    {"# a comment\nOFF\n# another\n3 1 0\n0 0 0\n\n1 0\n0 1 0\n3 0 1 2\n", 7,
     "not a valid OFF file (vertex 1 does not have 3 coordinates)"},
    {"OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", 5,
     "not a valid OFF file (face 0 lists fewer than its 3 vertex indices)"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\nx 0 1 2\n", 6,
     "not a valid OFF file (face 0 does not start with its number of vertices)"},
    {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 0, "not a valid OFF file (the file ends before face 1 of 2)"},
    {"OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n", 0, "not a valid OFF file (the file ends before vertex 3 of 4)"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 6, "face 0 has vertex index 3, out of range (the file has 3 vertices)"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 6, "face 0 has vertex index -1, out of range (the file has 3 vertices)"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n", 5, "vertex 2 has a coordinate that is NaN or infinite"},
    {"OFF\n3 1 0\n0 0 0\n1 0 1e999\n0 1 0\n3 0 1 2\n", 4, "vertex 1 has a coordinate that is NaN or infinite"},
  };
  int k = 0;
  for(const Case& c : cases) {
    const std::string file = write("case" + std::to_string(k++) + ".off", c.content);
    const diffuv::Input_error e = read_error(file);
    EXPECT_EQ(e.reason(), c.reason) << c.content;
    EXPECT_EQ(e.line(), c.line) << c.content;
    EXPECT_EQ(e.file(), file);
    const std::string where = c.line > 0 ? ":" + std::to_string(c.line) : std::string();
    EXPECT_EQ(std::string(e.what()), file + where + ": " + c.reason);
  }
}

TEST_F(IoReadMesh, OffWithoutFace)
{
  const diffuv::Input_error e = read_error(write("noface.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"));
  EXPECT_EQ(e.reason(), "the file has no face");
  EXPECT_EQ(e.line(), 0u);
}

// ---------------------------------------------------------------------------
// OBJ

TEST_F(IoReadMesh, ObjErrorsHaveALine)
{
  struct Case { const char* content; std::size_t line; const char* reason; };
  const Case cases[] = {
    // One past the last vertex: CGAL's reader accepts it (then its mesh
    // builder asserts); we must not.
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "face 0 has vertex index 4, out of range (the file has 3 vertices)"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 9\n", 5, "face 1 has vertex index 9, out of range (the file has 3 vertices)"},
    {"v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 0 1 0\n", 3, "face 0 has vertex index -3, out of range (the file has 3 vertices)"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nxyz 1\nf 1 2 3\n", 4, "not a valid OBJ file (unknown keyword \"xyz\")"},
    {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", 2, "not a valid OBJ file (cannot read the coordinates of vertex 1)"},
    {"# comment\nv 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n", 4, "vertex 2 has a coordinate that is NaN or infinite"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", 0, "the file has no face"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2\n", 5, "face 0 has only 2 vertices"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3/1/1 2/2/2 2/3/3\n", 5, "face 1 uses vertex 1 twice"},
  };
  int k = 0;
  for(const Case& c : cases) {
    const std::string file = write("case" + std::to_string(k++) + ".obj", c.content);
    const diffuv::Input_error e = read_error(file);
    EXPECT_EQ(e.reason(), c.reason) << c.content;
    EXPECT_EQ(e.line(), c.line) << c.content;
  }
}

TEST_F(IoReadMesh, ObjWithTexturesAndNegativeIndices)
{
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(
    write("t.obj", "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nv 1 1 0\nf -3/2 -1 -2\n"),
    mesh);
  EXPECT_EQ(report.vertices, 4u);
  EXPECT_EQ(report.faces, 2u);
  const face_descriptor second = *std::next(faces(mesh).begin());
  EXPECT_TRUE(diffuv_test::same_cycle(diffuv_test::face_vertex_numbers(mesh, second), {1, 3, 2}));
}

// ---------------------------------------------------------------------------
// PLY and STL (binary: no line numbers)

std::string binary_ply_triangle(float bad_x)
{
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                  "property float y\nproperty float z\nelement face 1\n"
                  "property list uchar int vertex_indices\nend_header\n";
  const float xyz[9] = {0, 0, 0, bad_x, 0, 0, 0, 1, 0};
  s.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const unsigned char three = 3;
  s.append(reinterpret_cast<const char*>(&three), 1);
  const std::int32_t indices[3] = {0, 1, 2};
  s.append(reinterpret_cast<const char*>(indices), sizeof indices);
  return s;
}

TEST_F(IoReadMesh, PlyNonFiniteCoordinates)
{
  Mesh mesh;
  EXPECT_EQ(diffuv::read_triangle_mesh(write("ok.ply", binary_ply_triangle(1.f)), mesh).vertices, 3u);

  for(float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()}) {
    const diffuv::Input_error e = read_error(write("bad.ply", binary_ply_triangle(bad)));
    EXPECT_EQ(e.reason(), "vertex 1 has a coordinate that is NaN or infinite") << bad;
    EXPECT_EQ(e.line(), 0u);
  }
}

TEST_F(IoReadMesh, PlyIndexErrors)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                             "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(read_error(write("a.ply", header + "3 0 1 5\n")).reason(),
            "face 0 has vertex index 5, out of range (the file has 3 vertices)");
  EXPECT_EQ(read_error(write("b.ply", header + "3 0 -1 2\n")).reason(),
            "face 0 has vertex index -1, out of range (the file has 3 vertices)");
  EXPECT_EQ(read_error(write("c.ply", header + "3 0 1\n")).reason(), "not a valid PLY file");
  EXPECT_EQ(read_error(write("d.ply", "ply\nformat ascii 1.0\nelement vertex 3\nend_head\n")).reason(),
            "not a valid PLY file");
}

TEST_F(IoReadMesh, StlWithoutFace)
{
  // Not "solid ...": binary. (A header of spaces would be skipped by CGAL's
  // reader as leading white space.)
  std::string s(80, 'x');
  s.append(4, '\0'); // zero triangles
  EXPECT_EQ(read_error(write("empty.stl", s)).reason(), "the file has no face");
  EXPECT_EQ(read_error(write("truncated.stl", s.substr(0, 80) + std::string("\x05\0\0\0", 4))).reason(),
            "not a valid STL file");
}

// ---------------------------------------------------------------------------
// Topology

TEST_F(IoReadMesh, FaceWithFewerThanThreeOrRepeatedVertices)
{
  diffuv::Input_error e = read_error(write("a.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1\n"));
  EXPECT_EQ(e.reason(), "face 1 has only 2 vertices");
  EXPECT_EQ(e.line(), 7u);
  e = read_error(write("b.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n4 1 3 2 3\n"));
  EXPECT_EQ(e.reason(), "face 1 uses vertex 3 twice");
  EXPECT_EQ(e.line(), 8u);
}

TEST_F(IoReadMesh, NonManifoldOrInconsistentSoups)
{
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n";
  // Three faces on the edge 0-1.
  diffuv::Input_error e = read_error(write("edge.off", "OFF\n5 3 0\n" + points + "3 0 1 2\n3 1 0 3\n3 0 1 4\n"));
  EXPECT_EQ(e.reason(), "non-manifold edge or vertex, or inconsistent orientation "
                        "(faces 0 and 2 both go from vertex 0 to vertex 1)");
  EXPECT_EQ(e.line(), 10u);
  // Two faces that disagree on the orientation of their common edge.
  e = read_error(write("orientation.off", "OFF\n5 2 0\n" + points + "3 0 1 2\n3 0 1 3\n"));
  EXPECT_EQ(e.reason(), "non-manifold edge or vertex, or inconsistent orientation "
                        "(faces 0 and 1 both go from vertex 0 to vertex 1)");
  EXPECT_EQ(e.line(), 9u);
  // Two triangles touching at vertex 0 only (a bow tie).
  e = read_error(write("bowtie.off", "OFF\n5 2 0\n" + points + "3 0 1 2\n3 0 3 4\n"));
  EXPECT_EQ(e.reason(), "non-manifold edge or vertex, or inconsistent orientation "
                        "(the faces around vertex 0 form 2 separate fans)");
  EXPECT_EQ(e.line(), 0u);
}

TEST_F(IoReadMesh, PolygonsAreTriangulated)
{
  // Two quads side by side, and a pentagon above them.
  const std::string content = "OFF\n8 3 0\n"
                              "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n2 2 0.1\n"
                              "4 0 1 4 3\n4 1 2 5 4\n5 3 4 5 7 6\n";
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(write("quads.off", content), mesh);
  EXPECT_EQ(report.faces_in_file, 3u);
  EXPECT_EQ(report.polygons_triangulated, 3u);
  EXPECT_EQ(report.faces, 2u + 2u + 3u);
  EXPECT_EQ(num_faces(mesh), 7u);
  EXPECT_EQ(report.degenerate_faces, 0u);
  EXPECT_EQ(report.isolated_vertices, 0u);
  std::size_t triangles = 0;
  for(face_descriptor f : faces(mesh))
    if(diffuv_test::face_vertex_numbers(mesh, f).size() == 3)
      ++triangles;
  EXPECT_EQ(triangles, 7u);
  EXPECT_EQ(num_vertices(mesh), 8u);
  EXPECT_EQ(mesh.point(vertex_descriptor(7)), Point_3(2, 2, 0.1));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

// Checks report.file_face against the polygons of the file: every face's
// corners are corners of its polygon, and a polygon of k vertices gives k - 2
// triangles.
void expect_faces_come_from(const Mesh& mesh, const diffuv::Mesh_read_report& report,
                            const std::vector<std::vector<std::size_t>>& polygons)
{
  ASSERT_EQ(report.file_face.size(), num_faces(mesh));
  std::vector<std::size_t> triangles(polygons.size(), 0);
  std::size_t f = 0;
  for(face_descriptor face : faces(mesh)) {
    const std::size_t j = report.file_face[f++];
    ASSERT_LT(j, polygons.size());
    ++triangles[j];
    for(std::size_t v : diffuv_test::face_vertex_numbers(mesh, face))
      EXPECT_NE(std::find(polygons[j].begin(), polygons[j].end(), v), polygons[j].end())
        << "face " << f - 1 << " has vertex " << v << ", not a corner of polygon " << j;
  }
  for(std::size_t j = 0; j < polygons.size(); ++j)
    EXPECT_EQ(triangles[j], polygons[j].size() - 2) << "polygon " << j;
}

TEST_F(IoReadMesh, TrianglesKnowTheirPolygon)
{
  // A quad (split by one diagonal), a pentagon (CGAL's CDT: the face is
  // removed and the hole filled), a triangle, a hexagon, from left to right.
  const std::string content = "OFF\n14 4 0\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"            // 0-3
                              "2 0 0\n2 1 0\n1.5 1.5 0\n"               // 4-6
                              "3 0 0\n"                                 // 7
                              "4 0 0\n5 0 0\n5.5 0.5 0\n5 1 0\n4 1 0\n3.5 0.5 0\n" // 8-13
                              "4 0 1 2 3\n5 1 4 5 6 2\n3 4 7 5\n6 8 9 10 11 12 13\n";
  const std::vector<std::vector<std::size_t>> polygons = {
    {0, 1, 2, 3}, {1, 4, 5, 6, 2}, {4, 7, 5}, {8, 9, 10, 11, 12, 13}};
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(write("mixed.off", content), mesh);
  EXPECT_EQ(report.faces, 2u + 3u + 1u + 4u);
  expect_faces_come_from(mesh, report, polygons);
  // The appended triangles come after the file's faces.
  EXPECT_EQ(report.file_face[2], 2u);

  // A quad on a line: CGAL refuses it, the fan cut by Euler::split_face().
  const std::string flat = "OFF\n8 3 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n0 5 0\n1 5 0\n2 5 0\n0 6 0\n"
                           "3 4 5 6\n4 0 1 2 3\n3 4 6 7\n";
  const diffuv::Mesh_read_report flat_report = diffuv::read_triangle_mesh(write("flat.off", flat), mesh);
  expect_faces_come_from(mesh, flat_report, {{4, 5, 6}, {0, 1, 2, 3}, {4, 6, 7}});
  EXPECT_EQ(flat_report.file_face, (std::vector<std::size_t>{0, 1, 2, 1}));
}

TEST_F(IoReadMesh, DegeneratePolygonsAreKeptAndCounted)
{
  // A quad on a line (CGAL's triangulation refuses it: cut as a fan) and a
  // flat triangle, beside a good triangle.
  const std::string content = "OFF\n8 3 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n0 5 0\n1 5 0\n2 5 0\n0 6 0\n"
                              "4 0 1 2 3\n3 4 5 6\n3 4 6 7\n";
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(write("flat.off", content), mesh);
  EXPECT_EQ(report.polygons_triangulated, 1u);
  EXPECT_EQ(report.faces, 4u);
  EXPECT_EQ(report.degenerate_faces, 3u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST_F(IoReadMesh, IsolatedPointsKeepTheirIndex)
{
  Mesh mesh;
  const diffuv::Mesh_read_report report =
    diffuv::read_triangle_mesh(write("iso.off", "OFF\n4 1 0\n5 5 5\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n"), mesh);
  EXPECT_EQ(report.vertices, 4u);
  EXPECT_EQ(report.isolated_vertices, 1u);
  EXPECT_EQ(num_vertices(mesh), 4u);
  EXPECT_EQ(mesh.point(*vertices(mesh).begin()), Point_3(5, 5, 5));
  EXPECT_EQ(halfedge(*vertices(mesh).begin(), mesh), Mesh::null_halfedge()); // isolated
  // A pitfall for the callers: CGAL calls a mesh with an isolated vertex invalid.
  EXPECT_FALSE(CGAL::is_valid_polygon_mesh(mesh));
}

// A quad whose only good diagonal (0-2) is already an edge of the mesh.
TEST_F(IoReadMesh, TriangulationMustNotDuplicateAnEdge)
{
  const std::string content = "OFF\n4 3 0\n0 0 0\n2 0 0\n0.5 0.5 0\n0 2 0\n4 0 1 2 3\n3 0 2 1\n3 0 3 2\n";
  const diffuv::Input_error e = read_error(write("pillow.off", content));
  EXPECT_EQ(e.reason(), "face 0 cannot be triangulated without a second edge between vertices 0 and 2");
  EXPECT_EQ(e.line(), 7u);
}

} // namespace
