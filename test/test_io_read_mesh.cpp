// Tests of include/diffuv/io/read_mesh.h and the pieces in io/internal/: the
// vertex order of real meshes; every rejection with its exact message and
// line (file names and formats, the OFF, OBJ, PLY and STL scanners, the
// checks of the polygon soup); polygons cut into triangles that know their
// polygon.
//
// Expectations come from the files themselves, parsed here by hand, not
// from CGAL's readers; except that the one-pass OBJ and PLY readers are
// compared with CGAL's read_OBJ() and read_PLY(), whose answers they must give.
#include "test_data.h"

#include <diffuv/io/read_labels.h>
#include <diffuv/io/internal/soup_to_mesh.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

namespace {

namespace fs = std::filesystem;
using diffuv_test::File_soup;
using diffuv_test::Mesh;
using diffuv_test::Point_3;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using face_descriptor = boost::graph_traits<Mesh>::face_descriptor;

using IoReadMesh = diffuv_test::Temp_dir_test;

// Reads `file` (with the repairs, or refusing what needs one) and returns the
// Input_error it must throw.
diffuv::Input_error read_error(const std::string& file, bool repair = true)
{
  return diffuv_test::input_error([&] {
    Mesh mesh;
    diffuv::Mesh_read_options options;
    options.repair = repair;
    diffuv::read_triangle_mesh(file, mesh, options);
  });
}

diffuv::Input_error strict_read_error(const std::string& file) { return read_error(file, false); }

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

// pig.stl touches itself at single points: without the repair, refused.
TEST(IoReadMeshReal, PigStlHasNonManifoldVertices)
{
  const std::string file = diffuv_test::data_path("meshes/pig.stl");
  const diffuv::Input_error e = strict_read_error(file);
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
    // Binary junk is quoted escaped, not written to the terminal.
    {"v 0 0 0\n\x01\xff\x1b[2J 1\n", 2, "not a valid OBJ file (unknown keyword \"\\x01\\xff\\x1b[2J\")"},
    {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", 2, "not a valid OBJ file (cannot read the coordinates of vertex 1)"},
    {"# comment\nv 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n", 4, "vertex 2 has a coordinate that is NaN or infinite"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", 0, "the file has no face"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2\n", 5, "face 0 has only 2 vertices"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3/1/1 2/2/2 2/3/3\n", 5, "face 1 uses vertex 1 twice"},
  };
  int k = 0;
  for(const Case& c : cases) {
    const std::string file = write("case" + std::to_string(k++) + ".obj", c.content);
    const diffuv::Input_error e = strict_read_error(file);
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
// OBJ in one pass (issue #20): scan_obj() reads a file as CGAL's read_OBJ()
// does (the same points, bit for bit, and polygons; the same files refused),
// and finds the lines and the first problem that the scanner it replaced
// found, so that no message changes.

// The OBJ scanner that ran before CGAL's reader until issue #20 (getline and
// istringstream, only to find errors): the reference for lines and messages.
diffuv::internal::Text_mesh_scan previous_obj_scan(const std::string& content)
{
  using diffuv::internal::Text_mesh_scan;
  Text_mesh_scan scan;
  std::istringstream file(content);
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid OBJ file (" + what + ")";
    return scan;
  };
  static const char* const ignored[] = {
    "vt", "vn", "vp", "bevel", "lod", "ctech", "c_interp", "usemap", "usemtl", "stech", "d_interp", "mtllib",
    "shadow_obj", "trace_obj", "o", "g", "s", "p", "cstype", "deg", "step", "bmat", "con", "curv", "curv2",
    "surf", "parm", "trim", "hole", "scrv", "sp", "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2",
    "q0_2", "q1_2", "curv2d_2", "bsp", "bzp", "cdc", "cdp", "res"};
  struct Written_face { std::size_t line, vertices_before; std::vector<int> indices; };
  std::vector<Written_face> written;
  std::string line;
  std::size_t number = 0;
  while(std::getline(file, line)) {
    ++number;
    std::istringstream in(line);
    std::string keyword;
    if(!(in >> keyword))
      continue;
    if(keyword == "v") {
      scan.vertex_line.push_back(number);
      double x, y, z;
      if(!(in >> x >> y >> z)) {
        std::string stop;
        diffuv::internal::leading_numbers(line.substr(line.find('v') + 1), stop);
        if(diffuv::internal::is_non_finite_number(stop)) {
          scan.error_line = number;
          scan.error = diffuv::internal::non_finite_message(scan.vertex_line.size() - 1);
          return scan;
        }
        return fail(number, "cannot read the coordinates of vertex " + std::to_string(scan.vertex_line.size() - 1));
      }
    } else if(keyword == "f") {
      scan.face_line.push_back(number);
      Written_face face{number, scan.vertex_line.size(), {}};
      int i;
      while(in >> i) {
        face.indices.push_back(i);
        in.ignore(256, ' ');
      }
      written.push_back(std::move(face));
    } else if(keyword.front() == '#' ||
              std::find(std::begin(ignored), std::end(ignored), keyword) != std::end(ignored)) {
      continue;
    } else {
      return fail(number, "unknown keyword \"" + diffuv::internal::printable(keyword) + "\"");
    }
  }
  const long long nv = static_cast<long long>(scan.vertex_line.size());
  for(std::size_t j = 0; j < written.size(); ++j)
    for(int i : written[j].indices) {
      const long long resolved = i < 1 ? static_cast<long long>(written[j].vertices_before) + i : i - 1LL;
      if(resolved < 0 || resolved >= nv) {
        scan.error_line = written[j].line;
        scan.error = diffuv::internal::out_of_range_message(j, std::to_string(i), scan.vertex_line.size());
        return scan;
      }
    }
  if(written.empty())
    scan.error = "the file has no face";
  return scan;
}

using Obj_polygons = std::vector<std::vector<std::size_t>>;

// Expects scan_obj() to read `content` as CGAL's reader and the previous
// scanner do; returns whether CGAL accepts it.
bool expect_obj_read_as_cgal(const std::string& content, const std::string& what)
{
  diffuv::internal::Polygon_soup soup;
  const diffuv::internal::Text_mesh_scan scan = diffuv::internal::scan_obj(content, soup);

  std::vector<Point_3> points;
  Obj_polygons polygons;
  std::istringstream in(content);
  const bool cgal = CGAL::IO::read_OBJ(in, points, polygons, CGAL::parameters::verbose(false));
  EXPECT_EQ(soup.complete, cgal) << what;
  if(cgal && soup.complete) {
    // Bit for bit: the same double, and the same sign of a zero.
    std::size_t different = points.size() == soup.points.size() ? 0 : 1;
    for(std::size_t i = 0; different == 0 && i < points.size(); ++i)
      for(int c = 0; c < 3; ++c)
        if(std::memcmp(&soup.points[i][c], &points[i][c], sizeof(double)) != 0)
          ++different;
    EXPECT_EQ(different, 0u) << what;
    EXPECT_TRUE(soup.polygons == polygons) << what;
  }

  const diffuv::internal::Text_mesh_scan previous = previous_obj_scan(content);
  EXPECT_EQ(scan.error, previous.error) << what;
  EXPECT_EQ(scan.error_line, previous.error_line) << what;
  EXPECT_TRUE(scan.vertex_line == previous.vertex_line) << what;
  EXPECT_TRUE(scan.face_line == previous.face_line) << what;
  return cgal;
}

// A soup written as OBJ in one of four styles: as CGAL writes it; with
// texture coordinates ("f v/vt", as diffuv writes it); with normals,
// relative indices, CRLF ends and tabs; with "v/vt/vn", a fourth coordinate
// and trailing spaces.
std::string obj_text(const std::vector<Point_3>& points, const Obj_polygons& polygons, int style)
{
  std::ostringstream out;
  out << std::setprecision(17);
  const char* const end = style == 2 ? "\r\n" : "\n";
  if(style == 1) out << "mtllib a.mtl" << end;
  if(style == 2) out << "# written by hand" << end << "g group" << end;
  for(const Point_3& p : points) {
    out << "v" << (style == 2 ? "  " : " ") << p.x() << (style == 2 ? "\t" : " ") << p.y() << " " << p.z()
        << (style == 3 ? " 1.0 " : "") << end;
    if(style == 1) out << "vt " << p.x() << " " << p.y() << end;
    if(style == 2) out << "vn 0 0 1" << end;
  }
  if(style == 3) out << "s off" << end;
  const long long nv = static_cast<long long>(points.size());
  for(const auto& polygon : polygons) {
    out << "f";
    for(std::size_t i : polygon) {
      const long long written = style == 2 ? static_cast<long long>(i) - nv : static_cast<long long>(i) + 1;
      out << (style == 3 ? "  " : " ") << written;
      if(style == 1) out << "/" << written;
      if(style == 2) out << "//1";
      if(style == 3) out << "/" << written << "/" << written;
    }
    out << (style == 3 ? " " : "") << end;
  }
  return out.str();
}

void read_off_soup(const std::string& name, std::vector<Point_3>& points, Obj_polygons& polygons)
{
  ASSERT_TRUE(CGAL::IO::read_polygon_soup(diffuv_test::data_path("meshes/" + name), points, polygons,
                                          CGAL::parameters::verbose(false)))
    << name;
}

TEST(IoReadMeshObj, OnePassReadsRealMeshesAsCgal)
{
  for(const char* name : {"cow.off", "nefertiti.off", "mushroom.off", "elephant.off", "man.off", "cube_quad.off",
                          "torus_quad.off", "3torus.off"}) {
    std::vector<Point_3> points;
    Obj_polygons polygons;
    read_off_soup(name, points, polygons);
    for(int style = 0; style < 4; ++style)
      EXPECT_TRUE(expect_obj_read_as_cgal(obj_text(points, polygons, style), std::string(name) + " style " +
                                                                                  std::to_string(style)));
  }
}

// The quirks of CGAL's reader (libstdc++'s streams), one by one.
TEST(IoReadMeshObj, OnePassKeepsCgalsQuirks)
{
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<std::string> contents = {
    "f\n", "f 1 2 3\n", "f -1\n", tri, tri + "f 1 2 3", "\n\n\n", "   \n\t\n", tri + "\r",
    "v 0 0 0\nf -2 1 1\nv 1 0 0\nv 0 1 0\n",        // before the first vertex, yet within CGAL's bound
    tri + "f 1 2 0\n", "v 0 0 0\nv 1 0 0\nf 1 2 0\nv 0 1 0\n", tri + "f 1 2 4\n", tri + "f 1 2 5\n",
    tri + "f -4 1 2\n", tri + "f\nf 1 2 3\n",
    // numbers: >> double
    "v 1e-310 0 0\n" + tri + "f 1 2 3\n", "v 1e-400 -1e-400 -0\n" + tri + "f 1 2 3\n",
    "v 4.9406564584124654e-324 2.4703282292062328e-324 2.4703282292062327e-324\n" + tri + "f 2 3 4\n",
    "v 1e309 0 0\n" + tri + "f 2 3 4\n", "v 1.7976931348623157e308 1.7976931348623158e308 0\n" + tri + "f 2 3 4\n",
    "v 0.1000000000000000055511151231257827021181583404541015625 0." + std::string(800, '1') + " 1" +
      std::string(400, '0') + "e-400\n" + tri + "f 2 3 4\n",
    "v +1 +0.5 +.5e+1\n" + tri + "f +2 +3 +4\n", "v 1-2-3\n" + tri + "f 2 3 4\n", "v 1.5.3e1e2\n" + tri + "f 2 3 4\n",
    "v 1e+ 2 3\n" + tri, "v 0x1p3 0 0\n" + tri, "v . 0 0\n" + tri, "v -.5 -.e 0\n" + tri, "v e5 0 0\n" + tri,
    "v 000.5 -00 0000\n" + tri + "f 002 003 004\n", "v inf 0 0\n" + tri, "v 0 0 nan\n" + tri,
    "v 0 0 0 nan\n" + tri + "f 2 3 4\n", "v 0 0 1e999#\n" + tri, "v 0 0 #0\n" + tri, "v 0 0 0#c\n" + tri + "f 2 3 4\n",
    "v 1,5 0 0\n" + tri, "v 1e5x 0 0\n" + tri,
    // indices: >> int, then ignore(256, ' ')
    tri + "f 1\t2\t3\n", tri + "f 1.9 2.9 3.9\n", tri + "f 1e2 2 3\n", tri + "f /1 2 3\n",
    tri + "f 1/" + std::string(254, '9') + " 2 3\n", tri + "f 1/" + std::string(255, '9') + " 2 3\n",
    tri + "f 1" + std::string(256, '/') + "2 3\n", tri + "f 1/" + std::string(254, '/') + "2 3\n",
    tri + "f 1" + std::string(255, 'x') + "2 3 1\n", tri + "f 1" + std::string(256, 'x') + "2 3 1\n",
    tri + "f 1" + std::string(257, 'x') + "2 3 1\n", tri + "f 1 2 3 99999999999\n", tri + "f 1 2 2147483647\n",
    tri + "f 1 2 -2147483648\n", tri + "f 1 2 -2147483649\n", tri + "f 1//2 2//2 3//2\n",
    // lines and keywords
    "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r",
    "v\v0\f0\r0\nv 1 0 0\nv 0 1 0\nf\v1 2 3\n", std::string("v 0 0 0\nv 1 0 0\0\nv 0 1 0\nf 1 2 3\n", 33),
    std::string("v 0 0 0\nv 1 0 0\n\0v 0 1 0\nf 1 2 3\n", 33), "v 0 0 0\nv 1 0 0\n#v 0 1 0\nv 0 1 0\n#\nf 1 2 3 # c\n",
    "\xef\xbb\xbfv 0 0 0\n" + tri, tri + "l 1 2\nf 1 2 3\n", tri + "vp 1 2\ncurv 0 1\nusemtl m\nf 1 2 3\n",
    "v1 0 0 0\n", "V 0 0 0\n", "F 1 2 3\n"};
  std::size_t accepted = 0;
  for(std::size_t k = 0; k < contents.size(); ++k)
    accepted += expect_obj_read_as_cgal(contents[k], "case " + std::to_string(k)) ? 1 : 0;
  EXPECT_GT(accepted, 20u);
}

// OBJ copies of small meshes in the four styles, damaged one to four times:
// words replaced (by numbers at the edges of what the streams read, keywords,
// long words), lines added, removed, repeated or swapped, characters changed,
// spaces turned into tabs, indices near the number of vertices, the file cut
// short, CRLF line ends.
TEST(IoReadMeshObj, OnePassAnswersAsCgalOnMutatedFiles)
{
  std::vector<std::string> bases;
  for(const char* name : {"tetrahedron.off", "cube_quad.off", "octahedron.off", "icosahedron.off", "star.off",
                          "hole.off", "tripod.off", "patch-23.off"}) {
    std::vector<Point_3> points;
    Obj_polygons polygons;
    read_off_soup(name, points, polygons);
    for(int style = 0; style < 4; ++style) bases.push_back(obj_text(points, polygons, style));
  }
  const std::vector<std::string> words = {
    "inf", "-inf", "nan", "1e999", "-1e999", "1e-400", "4.9e-324", "2e-310", "0x1p3", "+1", "-0", "0", "-1", "-3",
    "1-2", "1.5.3", "1e", "1e+", "e5", ".", "-", ".5", "5.", "1e5x", "99999999999", "2147483647", "2147483648",
    "-2147483649", "abc", "#", "v", "f", "vt", "vn", "o", "g", "usemtl", "xyz", "1/2/3", "1//3", "/", "\t", "\r",
    std::string(1, '\0'), "\v", std::string(300, 'x'), "1/" + std::string(300, '2'), "7" + std::string(255, '/') + " 9",
    "1e308", "1.8e308", "+-1", "1E5", "00012", "+.5", "1,5", "\xff", "1 2", "#c"};
  const std::vector<std::string> lines = {
    "f 1 2 3", "f -1 -2 -3", "f 0 1 2", "v 1 2", "v 1 2 3 4", "", "   ", "#x", "vt 0 0", "\r", "f", "f 1",
    "f 1\t2\t3", "mtllib a", "g", "v 0 0 0", "v inf 0 0", "v 1e999 0 0", "f 1/1/1 2/2/2 3/3/3", "f 1 1 2", "v",
    "vp 1 2", "l 1 2", "f -4 -5 -6"};
  std::mt19937 random(20261204);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(random() % n); };
  std::size_t accepted = 0, trials = 6000;
  for(std::size_t trial = 0; trial < trials; ++trial) {
    std::vector<std::string> text;
    {
      std::istringstream in(bases[pick(bases.size())]);
      for(std::string line; std::getline(in, line);) text.push_back(line);
    }
    bool cut = false;
    std::string content;
    for(std::size_t damage = 1 + pick(4); damage > 0 && !text.empty(); --damage) {
      std::string& line = text[pick(text.size())];
      switch(pick(11)) {
        case 0: case 1: { // a word replaced
          std::size_t start = 0;
          for(std::size_t w = pick(5); w > 0 && line.find(' ', start) != std::string::npos; --w)
            start = line.find(' ', start) + 1;
          const std::size_t stop = std::min(line.find(' ', start), line.size());
          line.replace(start, stop - start, words[pick(words.size())]);
          break;
        }
        case 2:
          text.insert(text.begin() + static_cast<std::ptrdiff_t>(pick(text.size() + 1)), lines[pick(lines.size())]);
          break;
        case 3: text.erase(text.begin() + static_cast<std::ptrdiff_t>(pick(text.size()))); break;
        case 4: text.push_back(text[pick(text.size())]); break;
        case 5: std::swap(line, text[pick(text.size())]); break;
        case 6: { // a character inserted, removed or replaced
          const std::size_t at = pick(line.size() + 1);
          const char c = static_cast<char>(pick(2) ? pick(256) : " \t\r/-+.e0123456789#"[pick(19)]);
          if(pick(2) || at == line.size()) line.insert(at, 1, c);
          else line[at] = c;
          break;
        }
        case 7: std::replace(line.begin(), line.end(), ' ', '\t'); break;
        case 8: { // an index near the number of vertices
          const long long nv =
            std::count_if(text.begin(), text.end(), [](const std::string& l) { return l.rfind("v ", 0) == 0; });
          const long long near[] = {nv, nv + 1, nv + 2, -nv, -nv - 1, 0, -1};
          if(line.rfind("f ", 0) == 0) { // its first index
            const std::size_t stop = std::min(line.find(' ', 2), line.size());
            line.replace(2, stop - 2, std::to_string(near[pick(7)]));
          }
          break;
        }
        case 9: for(std::string& l : text) l += "\r"; break;
        default: cut = true; break;
      }
    }
    for(const std::string& line : text) content += line + "\n";
    if(cut) content.resize(pick(content.size() + 1));
    accepted += expect_obj_read_as_cgal(content, "trial " + std::to_string(trial)) ? 1 : 0;
    if(::testing::Test::HasFailure()) {
      ADD_FAILURE() << "first difference on:\n" << content;
      break;
    }
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(accepted, trials / 10);
  EXPECT_LT(accepted, trials - trials / 10);
}

// ---------------------------------------------------------------------------
// PLY in one pass (issue #20): scan_ply() reads a file as CGAL's read_PLY()
// does (the same points, bit for bit, and polygons; the same files refused),
// and refuses with the messages of the scanner that ran before CGAL's reader,
// so that no message changes.

using diffuv::internal::Ply_type;

// A value read as CGAL's PLY reader reads it from a stream (`>>` into the
// type, 8-bit ones through 16-bit ones; binary bytes, swapped if big-endian).
bool previous_ply_value(std::istream& in, int format, Ply_type type, double& value)
{
  if(format != 0) {
    unsigned char b[8];
    const std::size_t n = diffuv::internal::ply_size(type);
    if(!in.read(reinterpret_cast<char*>(b), static_cast<std::streamsize>(n)))
      return false;
    if(format == 2)
      std::reverse(b, b + n);
    auto as = [&](auto t) {
      std::memcpy(&t, b, sizeof t);
      value = static_cast<double>(t);
      return true;
    };
    switch(type) {
      case Ply_type::int8: return as(std::int8_t());
      case Ply_type::uint8: return as(std::uint8_t());
      case Ply_type::int16: return as(std::int16_t());
      case Ply_type::uint16: return as(std::uint16_t());
      case Ply_type::int32: return as(std::int32_t());
      case Ply_type::uint32: return as(std::uint32_t());
      case Ply_type::float32: return as(float());
      case Ply_type::float64: return as(double());
    }
  }
  auto text = [&](auto read, auto stored) {
    if(!(in >> read))
      return false;
    value = static_cast<decltype(stored)>(read);
    return true;
  };
  switch(type) {
    case Ply_type::int8: return text(short(), static_cast<signed char>(0));
    case Ply_type::uint8: return text(static_cast<unsigned short>(0), static_cast<unsigned char>(0));
    case Ply_type::int16: return text(std::int16_t(), std::int16_t());
    case Ply_type::uint16: return text(std::uint16_t(), std::uint16_t());
    case Ply_type::int32: return text(std::int32_t(), std::int32_t());
    case Ply_type::uint32: return text(std::uint32_t(), std::uint32_t());
    case Ply_type::float32: return text(float(), float());
    case Ply_type::float64: return text(double(), double());
  }
  return false;
}

// The PLY scanner that ran before CGAL's reader until issue #20 (on a stream,
// to find what CGAL's reader would not survive): with CGAL's read_PLY(), the
// reference for answers and messages.
diffuv::internal::Text_mesh_scan previous_ply_scan(const std::string& content)
{
  using namespace diffuv::internal;
  Text_mesh_scan scan;
  const std::uintmax_t file_size = content.size();
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid PLY file (" + what + ")";
    return scan;
  };
  std::istringstream in(content);
  Ply_header header;
  std::size_t error_line = 0;
  const std::string problem = read_ply_header(in, file_size, Ply_header_rules::cgal, header, error_line);
  if(!problem.empty())
    return fail(error_line, problem);
  const std::vector<Ply_element>& elements = header.elements;
  for(const Ply_element& e : elements) {
    auto find = [&](const char* name) -> const Ply_property* {
      for(const Ply_property& p : e.properties)
        if(p.name == name) return &p;
      return nullptr;
    };
    auto is = [&](const char* name, Ply_type type) {
      const Ply_property* p = find(name);
      return p && !p->list && p->type == type;
    };
    auto require = [&](const char* name, const char* type, bool ok) {
      const Ply_property* p = find(name);
      if(p && !ok)
        fail(e.line, "property \"" + std::string(name) + "\" of element \"" + e.name + "\" is not of type " + type);
      return !p || ok;
    };
    const bool vertex = e.name == "vertex" || e.name == "vertices";
    if(vertex)
      for(const char* xyz : {"x", "y", "z"})
        if(!require(xyz, "float or double", is(xyz, Ply_type::float32) || is(xyz, Ply_type::float64)))
          return scan;
    if(vertex || e.name == "face" || e.name == "faces") {
      const bool red = is("red", Ply_type::uint8);
      if((red || is("r", Ply_type::uint8)) && (is("green", Ply_type::uint8) || is("g", Ply_type::uint8)) &&
         (is("blue", Ply_type::uint8) || is("b", Ply_type::uint8)))
        for(const char* rgb : red ? std::vector<const char*>{"red", "green", "blue"} : std::vector<const char*>{"r", "g", "b"})
          if(!require(rgb, "uchar", is(rgb, Ply_type::uint8)))
            return scan;
    }
    if(e.name == "halfedge" && !(is("source", Ply_type::uint32) && is("target", Ply_type::uint32) &&
                                 is("u", Ply_type::float32) && is("v", Ply_type::float32)))
      for(const char* end : {"source", "target"})
        if(!require(end, "uint", is(end, Ply_type::uint32)))
          return scan;
  }
  auto long_list = [](const Ply_property& p) { return p.list && ply_size(p.count_type) == 4; };
  bool long_lists = false;
  for(const Ply_element& e : elements)
    for(const Ply_property& p : e.properties)
      long_lists = long_lists || long_list(p);
  if(!long_lists)
    return scan;
  for(std::size_t k = 0; k < elements.size(); ++k) {
    const Ply_element& e = elements[k];
    const bool faces_then_lists =
        (e.name == "face" || e.name == "faces") &&
        std::any_of(elements.begin() + static_cast<std::ptrdiff_t>(k) + 1, elements.end(), [&](const Ply_element& later) {
          return std::any_of(later.properties.begin(), later.properties.end(), long_list);
        });
    auto cut_short_before_lists = [&](std::size_t j, const Ply_property& p) {
      return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" ends before its property \"" + p.name +
                         "\" can be read, and a later element has lists");
    };
    for(std::size_t j = 0; j < e.count; ++j)
      for(const Ply_property& p : e.properties) {
        double value;
        const bool ok = previous_ply_value(in, header.format, p.list ? p.count_type : p.type, value);
        if(!ok && faces_then_lists) return cut_short_before_lists(j, p);
        if(!ok && !p.list)
          return scan;
        if(!ok)
          return fail(0, "the length of list \"" + p.name + "\" of item " + std::to_string(j) + " of element \"" +
                             e.name + "\" cannot be read");
        if(!p.list)
          continue;
        if(value < 0 || value * static_cast<double>(header.format == 0 ? 2 : ply_size(p.type)) >
                            static_cast<double>(file_size + 1))
          return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" has a list \"" + p.name +
                             "\" of " + std::to_string(static_cast<long long>(value)) + " values, " +
                             (value < 0 ? "a negative length" : "more than the file can hold"));
        for(std::size_t i = 0, n = static_cast<std::size_t>(value); i < n; ++i)
          if(!previous_ply_value(in, header.format, p.type, value))
            return faces_then_lists ? cut_short_before_lists(j, p) : scan;
      }
  }
  return scan;
}

// What reading a PLY file answers: the soup, or the message and line of the refusal.
struct Ply_answer {
  bool accepted = false;
  std::string message;
  std::size_t line = 0;
  std::vector<std::array<double, 3>> points;
  Obj_polygons polygons;
};

// The answer of read_triangle_mesh() before issue #20: the previous scanner,
// then CGAL's read_PLY().
Ply_answer previous_ply_answer(const std::string& content)
{
  Ply_answer answer;
  const diffuv::internal::Text_mesh_scan scan = previous_ply_scan(content);
  if(!scan.error.empty()) {
    answer.message = scan.error;
    answer.line = scan.error_line;
    return answer;
  }
  std::istringstream in(content);
  std::vector<Point_3> points;
  try {
    answer.accepted = CGAL::IO::read_PLY(in, points, answer.polygons, CGAL::parameters::verbose(false));
  } catch(const std::exception& e) {
    answer.message = std::string("not a valid PLY file (") + e.what() + ")";
    return answer;
  }
  if(!answer.accepted)
    answer.message = "not a valid PLY file";
  for(const Point_3& p : points)
    answer.points.push_back({p.x(), p.y(), p.z()});
  return answer;
}

// The answer of scan_ply().
Ply_answer ply_answer(const std::string& content)
{
  Ply_answer answer;
  diffuv::internal::Polygon_soup soup;
  const diffuv::internal::Text_mesh_scan scan = diffuv::internal::scan_ply(content, content.size(), soup);
  answer.accepted = scan.error.empty() && soup.complete;
  answer.message = !scan.error.empty() ? scan.error : soup.complete ? "" : "not a valid PLY file";
  answer.line = scan.error_line;
  answer.points = std::move(soup.points);
  answer.polygons = std::move(soup.polygons);
  return answer;
}

// Expects scan_ply() to answer `content` as the previous reader did;
// returns whether it is accepted.
bool expect_ply_read_as_cgal(const std::string& content, const std::string& what)
{
  const Ply_answer now = ply_answer(content);
  const Ply_answer before = previous_ply_answer(content);
  EXPECT_EQ(now.accepted, before.accepted) << what;
  // A list whose length CGAL's reader could not read has the length of
  // uninitialised memory: the previous path then said "not a valid PLY
  // file", or passed on the exception of a vector sized to that garbage
  // (whichever the stack held). Both refuse; scan_ply() says the former.
  const bool garbage_length = now.message == "not a valid PLY file" &&
                              (before.message == "not a valid PLY file (vector::_M_default_append)" ||
                               before.message == "not a valid PLY file (std::bad_alloc)");
  if(!garbage_length)
    EXPECT_EQ(now.message, before.message) << what;
  EXPECT_EQ(now.line, before.line) << what;
  if(now.accepted && before.accepted) {
    // Bit for bit: the same double, and the same sign of a zero.
    EXPECT_EQ(now.points.size(), before.points.size()) << what;
    EXPECT_TRUE(now.points.size() == before.points.size() &&
                (now.points.empty() ||
                 std::memcmp(now.points.data(), before.points.data(), now.points.size() * sizeof(now.points[0])) == 0))
      << what;
    EXPECT_TRUE(now.polygons == before.polygons) << what;
  }
  return before.accepted;
}

// A soup written as PLY by hand, in a style: the format, the types of the
// coordinates and of the index lists, and what else the file holds.
struct Ply_style {
  int format = 0; // 0 ascii, 1 binary little-endian, 2 binary big-endian
  Ply_type coordinate = Ply_type::float64;
  Ply_type count = Ply_type::uint8;
  Ply_type index = Ply_type::int32;
  const char* indices = "vertex_indices";
  bool extras = false; // normals, colours, labels, texture lists, an edge element, comments
  bool crlf = false;   // text: CRLF line ends
};

const char* ply_type_name(Ply_type type)
{
  static const char* const names[8] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
  return names[static_cast<int>(type)];
}

// Appends `value` as a value of `type`: text with 17 digits, or binary.
void put_ply_value(std::string& out, int format, Ply_type type, double value)
{
  if(format == 0) {
    std::ostringstream s;
    s << std::setprecision(17) << value << ' ';
    out += s.str();
    return;
  }
  auto put = [&](auto t) {
    unsigned char b[sizeof t];
    std::memcpy(b, &t, sizeof t);
    if(format == 2)
      std::reverse(b, b + sizeof t);
    out.append(reinterpret_cast<const char*>(b), sizeof t);
  };
  // Integers wrap to their type (200 as a char is -56), through a 64-bit
  // integer: a double out of the target's range would be undefined behaviour.
  auto whole = [&] { return static_cast<std::int64_t>(value); };
  switch(type) {
    case Ply_type::int8: put(static_cast<std::int8_t>(whole())); break;
    case Ply_type::uint8: put(static_cast<std::uint8_t>(whole())); break;
    case Ply_type::int16: put(static_cast<std::int16_t>(whole())); break;
    case Ply_type::uint16: put(static_cast<std::uint16_t>(whole())); break;
    case Ply_type::int32: put(static_cast<std::int32_t>(whole())); break;
    case Ply_type::uint32: put(static_cast<std::uint32_t>(whole())); break;
    case Ply_type::float32: put(static_cast<float>(value)); break;
    case Ply_type::float64: put(value); break;
  }
}

std::string ply_text(const std::vector<Point_3>& points, const Obj_polygons& polygons, const Ply_style& style)
{
  static const char* const formats[3] = {"ascii", "binary_little_endian", "binary_big_endian"};
  const char* const end = style.crlf ? "\r\n" : "\n";
  const bool text = style.format == 0;
  std::ostringstream h;
  h << "ply" << end << "format " << formats[style.format] << " 1.0" << end;
  if(style.extras) h << "comment written by hand" << end << "obj_info a test" << end;
  h << "element vertex " << points.size() << end;
  for(const char* c : {"x", "y", "z"})
    h << "property " << ply_type_name(style.coordinate) << " " << c << end;
  if(style.extras)
    h << "property float nx" << end << "property float ny" << end << "property float nz" << end
      << "property uchar red" << end << "property uchar green" << end << "property uchar blue" << end
      << "property int label" << end << "comment between properties" << end;
  h << "element face " << polygons.size() << end;
  if(style.extras) h << "property uchar red" << end << "property list uchar float texcoord" << end;
  h << "property list " << ply_type_name(style.count) << " " << ply_type_name(style.index) << " " << style.indices
    << end;
  if(style.extras) h << "property ushort segment" << end << "element edge 1" << end << "property int vertex1" << end
                     << "property int vertex2" << end;
  h << "end_header" << end;
  std::string out = h.str();
  for(std::size_t i = 0; i < points.size(); ++i) {
    for(int c = 0; c < 3; ++c) put_ply_value(out, style.format, style.coordinate, points[i][c]);
    if(style.extras) {
      for(int c = 0; c < 3; ++c) put_ply_value(out, style.format, Ply_type::float32, 0.25 * c);
      for(int c = 0; c < 3; ++c) put_ply_value(out, style.format, Ply_type::uint8, (i * 7 + c) % 256);
      put_ply_value(out, style.format, Ply_type::int32, -static_cast<double>(i));
    }
    if(text) out += end;
  }
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    if(style.extras) {
      put_ply_value(out, style.format, Ply_type::uint8, j % 256);
      put_ply_value(out, style.format, Ply_type::uint8, 2);
      put_ply_value(out, style.format, Ply_type::float32, 0.5);
      put_ply_value(out, style.format, Ply_type::float32, 0.75);
    }
    put_ply_value(out, style.format, style.count, static_cast<double>(polygons[j].size()));
    for(std::size_t i : polygons[j]) put_ply_value(out, style.format, style.index, static_cast<double>(i));
    if(style.extras) put_ply_value(out, style.format, Ply_type::uint16, j % 7);
    if(text) out += end;
  }
  if(style.extras) {
    put_ply_value(out, style.format, Ply_type::int32, 0);
    put_ply_value(out, style.format, Ply_type::int32, 1);
    if(text) out += end;
  }
  return out;
}

// The styles the tests write: CGAL's writer's two (text with 17 digits, and
// little-endian binary), and six by hand.
std::vector<std::string> ply_texts(const std::vector<Point_3>& points, const Obj_polygons& polygons)
{
  std::vector<std::string> texts;
  for(bool binary : {false, true}) {
    std::ostringstream out;
    CGAL::IO::set_mode(out, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
    CGAL::IO::write_PLY(out, points, polygons, CGAL::parameters::stream_precision(17));
    texts.push_back(out.str());
  }
  Ply_style style;
  style.format = 2; // big-endian, doubles, uchar and int
  texts.push_back(ply_text(points, polygons, style));
  style.coordinate = Ply_type::float32; // big-endian floats, 32-bit lengths, uint indices
  style.count = Ply_type::int32;
  style.index = Ply_type::uint32;
  style.indices = "vertex_index";
  texts.push_back(ply_text(points, polygons, style));
  style = Ply_style();
  style.format = 1; // little-endian floats with extras, ushort lengths
  style.coordinate = Ply_type::float32;
  style.count = Ply_type::uint16;
  style.extras = true;
  texts.push_back(ply_text(points, polygons, style));
  style.format = 2;
  texts.push_back(ply_text(points, polygons, style));
  style.format = 0; // text, 17 digits read as floats, extras, CRLF, uint lengths
  style.count = Ply_type::uint32;
  style.crlf = true;
  texts.push_back(ply_text(points, polygons, style));
  style = Ply_style(); // text with char lengths and vertex_index
  style.count = Ply_type::int8;
  style.indices = "vertex_index";
  texts.push_back(ply_text(points, polygons, style));
  return texts;
}

TEST(IoReadMeshPly, OnePassReadsRealMeshesAsCgal)
{
  for(const char* name : {"cow.off", "nefertiti.off", "mushroom.off", "elephant.off", "man.off", "cube_quad.off",
                          "torus_quad.off", "3torus.off"}) {
    std::vector<Point_3> points;
    Obj_polygons polygons;
    read_off_soup(name, points, polygons);
    const std::vector<std::string> texts = ply_texts(points, polygons);
    for(std::size_t style = 0; style < texts.size(); ++style) {
      const std::string what = std::string(name) + " style " + std::to_string(style);
      EXPECT_TRUE(expect_ply_read_as_cgal(texts[style], what));
      // And what was written: the points (as floats where written so) and polygons of the mesh.
      const Ply_answer read = ply_answer(texts[style]);
      ASSERT_EQ(read.points.size(), points.size()) << what;
      EXPECT_TRUE(read.polygons == polygons) << what;
    }
  }
  // CGAL's own PLY files.
  for(const char* name : {"colored_tetra.ply", "sphere.ply", "b9.ply"})
    EXPECT_TRUE(expect_ply_read_as_cgal(diffuv_test::file_content(diffuv_test::data_path(std::string("meshes/") + name)),
                                        name));
}

// The quirks of CGAL's reader (libstdc++'s streams, its choice of
// properties), one by one.
TEST(IoReadMeshPly, OnePassKeepsCgalsQuirks)
{
  auto head = [](const std::string& format, const std::string& vertex, const std::string& face) {
    return "ply\nformat " + format + " 1.0\nelement vertex 3\n" + vertex + "element face 1\n" + face + "end_header\n";
  };
  const std::string xyz = "property double x\nproperty double y\nproperty double z\n";
  const std::string fxyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string list = "property list uchar int vertex_indices\n";
  const std::string text = head("ascii", xyz, list);
  const std::string ftext = head("ascii", fxyz, list);
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n";
  const std::string tri = points + "3 0 1 2\n";
  auto with = [&](const std::string& list_line, const std::string& face) {
    return head("ascii", xyz, list_line) + points + face;
  };
  std::vector<std::string> contents = {
    text + tri, ftext + tri, text + points, text, text + tri + "trailing words\n", text + tri.substr(0, tri.size() - 1),
    // numbers: >> double, >> float
    text + "1e-310 0 0\n1e-400 -1e-400 -0\n0 1 0\n3 0 1 2\n", text + "1e999 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    text + "+1 +.5 +5.e+1\n1 0 0\n0 1 0\n3 0 1 2\n", text + "1-2-3\n1 0 0\n0 1 0\n3 0 1 2\n",
    text + "0x10 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", text + "nan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    text + "inf 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", text + "1e 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    text + "1.5.3 0\n1 0 0\n0 1 0\n3 0 1 2\n", text + ". 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    text + "1,5 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", text + "1e5x 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    text + "0.1000000000000000055511151231257827021181583404541015625 0." + std::string(800, '1') + " 1" +
      std::string(400, '0') + "e-400\n1 0 0\n0 1 0\n3 0 1 2\n",
    ftext + "0.1 0.2 0.30000001192092896\n1 0 0\n0 1 0\n3 0 1 2\n",
    ftext + "3.4028235e38 -3.4028235e38 1e-46\n1 0 0\n0 1 0\n3 0 1 2\n", ftext + "3.40282357e38 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    ftext + "1e39 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ftext + "1e-40 1.00000001 16777217\n1 0 0\n0 1 0\n3 0 1 2\n",
    ftext + "0.1000000000000000055511151231257827021181583404541015625 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    // indices and lengths: >> into their types
    text + points + "3 +0 +1 +2\n", text + points + "+3 0 1 2\n", text + points + "3 0 1 -1\n",
    text + points + "3 0 1 2147483648\n", text + points + "3 0 1 0x1\n", text + points + "3 0 1 1.5\n",
    text + points + "3\t0\v1\f2\r\n", text + points + "4 0 1 2\n", text + points + "2 0 1 2\n", text + points + "0\n",
    text + points + "300 0 1 2\n", text + points + "259 0 1 2\n", text + points + "-253 0 1 2\n",
    text + points + "-1 0 1 2\n", text + points + "3 0 1 2 3 4 5\n",
    with("property list uint int vertex_indices\n", "3 0 1 2\n"),
    with("property list uint uint vertex_indices\n", "3 0 1 4294967295\n"),
    with("property list uint uint vertex_indices\n", "3 0 1 -1\n"),
    with("property list uint uint vertex_indices\n", "3 0 1 -4294967295\n"),
    with("property list uint uint vertex_indices\n", "3 0 1 4294967296\n"),
    with("property list int int vertex_indices\n", "-3 0 1 2\n"),
    with("property list int int vertex_indices\n", "99999 0 1 2\n"),
    with("property list int int vertex_indices\n", "3 0 1\n"), with("property list int int vertex_indices\n", "x\n"),
    with("property list int int vertex_indices\n", ""), with("property list uint int vertex_indices\n", "-1 0 1 2\n"),
    with("property list char int vertex_indices\n", "200 0 1 2\n"),
    with("property list char int vertex_indices\n", "-1 0 1 2\n"),
    with("property list char int vertex_indices\n", "259 0 1 2\n"),
    with("property list short int vertex_indices\n", "-1 0 1 2\n"),
    with("property list short int vertex_indices\n", "65539 0 1 2\n"),
    with("property list ushort int vertex_indices\n", "-65533 0 1 2\n"),
    with("property list ushort int vertex_indices\n", "-1 0 1 2\n"),
    with("property list float int vertex_indices\n", "3 0 1 2\n"),
    with("property list int8 int32 vertex_indices\n", "3 0 1 2\n"),
    // which property holds the indices
    with("property list uchar int vertex_index\n", "3 0 1 2\n"),
    with("property list uchar uint vertex_indices\n", "3 0 1 2\n"),
    with("property list uchar short vertex_indices\n", "3 0 1 2\n"),
    with("property list uchar short vertex_indices\nproperty list uchar int vertex_index\n", "3 0 1 2 3 2 1 0\n"),
    with("property list uchar int vertex_index\nproperty list uchar int vertex_indices\n", "3 0 1 2 3 2 1 0\n"),
    with("property list uchar int vertex_indices\nproperty list uchar int vertex_indices\n", "3 0 1 2 3 2 1 0\n"),
    with("property int vertex_indices\nproperty list uchar int vertex_index\n", "7 3 0 1 2\n"),
    with("property list uchar double vertex_indices\n", "3 0 1 2\n"), with("property list uchar int indices\n", "3 0 1 2\n"),
    with("property int label\n" + list + "property uchar red\nproperty uchar green\nproperty uchar blue\n",
         "5 3 0 1 2 255 0 0\n"),
    with("property uchar r\nproperty uchar g\nproperty uchar b\n" + list, "1 2 3 3 0 1 2\n"),
    with("property float red\nproperty uchar green\nproperty uchar blue\n" + list, "1 2 3 3 0 1 2\n"),
    with("property uchar red\nproperty uchar green\nproperty float blue\n" + list, "1 2 3 3 0 1 2\n"),
    with(list + "property xyz unknown\n", "3 0 1 2 5\n"), with(list + "property list uchar xyz unknown\n", "3 0 1 2 5\n"),
    with("property list uchar int vertex_indices extra words\n", "3 0 1 2\n"),
    // vertices: which properties hold the coordinates
    head("ascii", "property double x\nproperty double y\n", list) + "0 0\n1 0\n0 1\n3 0 1 2\n",
    head("ascii", "property double z\nproperty double y\nproperty double x\n", list) + tri,
    head("ascii", "property double x\nproperty double x\nproperty double y\nproperty double z\n", list) +
      "0 9 0 0\n1 9 0 0\n0 9 1 0\n3 0 1 2\n",
    head("ascii", "property double x\nproperty float y\nproperty double z\n", list) + "0.1 0.1 0.1\n1 0 0\n0 1 0\n3 0 1 2\n",
    head("ascii", "property int x\nproperty double y\nproperty double z\n", list) + tri,
    head("ascii", "property list uchar float x\nproperty double y\nproperty double z\n", list) + tri,
    head("ascii", xyz + "property uchar red\nproperty uchar green\nproperty uchar blue\n", list) +
      "0 0 0 1 2 3\n1 0 0 300 2 3\n0 1 0 1 2 3\n3 0 1 2\n",
    head("ascii", xyz + "property uchar red\nproperty uchar green\nproperty short blue\n", list) + tri,
    head("ascii", xyz + "property char c\nproperty uchar u\nproperty short s\nproperty ushort us\nproperty int i\n"
                  "property uint ui\n", list) + "0 0 0 -1 1 -1 1 -1 1\n1 0 0 200 300 40000 70000 1 1\n0 1 0 1 1 1 1 1 1\n3 0 1 2\n",
    head("ascii", xyz + "property list uint float normals\n", list) + "0 0 0 2 1 1\n1 0 0 0\n0 1 0 1 1\n3 0 1 2\n",
    head("ascii", xyz + "property list uint float normals\n", list) + "0 0 0 9999999 1 1\n1 0 0 0\n0 1 0 1 1\n3 0 1 2\n",
    // elements and the header
    "ply\nformat ascii 1.0\nelement vertices 3\n" + xyz + "element faces 1\n" + list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement face 1\n" + list + "element vertex 3\n" + xyz + "end_header\n3 0 1 2\n" + points,
    "ply\nformat ascii 1.0\nelement vertex 2\n" + xyz + "element vertex 1\n" + xyz + "element face 1\n" + list +
      "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list + "element face 1\n" + list +
      "end_header\n" + tri + "3 2 1 0\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list + "element face 1\n" +
      "property list uchar short vertex_indices\nend_header\n" + tri + "3 2 1 0\n",
    "ply\nformat ascii 1.0\nelement vertex 3\nelement face 1\n" + list + "end_header\n3 0 1 2\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\nend_header\n" + points,
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list +
      "element halfedge 1\nproperty uint source\nproperty uint target\nproperty float u\nproperty float v\nend_header\n" +
      tri + "0 1 0.5 0.5\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list +
      "element halfedge 1\nproperty int source\nproperty uint target\nend_header\n" + tri + "0 1\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list +
      "element halfedge 1\nproperty uint source\nproperty uint target\nend_header\n" + tri + "0 1\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list +
      "element thing 2\nproperty list uint int values\nend_header\n" + tri + "1 5 2 6 7\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list +
      "element thing 2\nproperty list uint int values\nend_header\n" + tri + "1 5 2 6\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list +
      "element thing 1\nproperty list uint int values\nend_header\n" + points + "3 0 1\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" +
      "property list uchar float vertex_indices\nelement thing 1\nproperty list uint int values\nend_header\n" + tri +
      "1 5\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" +
      "property list uchar float vertex_indices\nelement thing 1\nproperty list uint int values\nend_header\n" + tri +
      "99999 5\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list + "element empty 5\nend_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list + "element big 99999\nend_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nelement face 1\n" + list + "end_header\n0\n1\n2\n3 0 1 2\n",
    "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\n" + std::string("property double x\r\nproperty double y\r\n") +
      "property double z\r\nelement face 1\r\n" + "property list uchar int vertex_indices\r\nend_header\r\n" +
      "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n",
    "ply\nformat ascii 1.0\ncomment a\nobj_info b\n\nelement vertex 3\n" + xyz + "element face 1\n" + list +
      "end_header\n" + tri,
    "ply\nformat ascii 1.0\ncomment a\nobj_info b\nunknown line\nelement vertex 3\n" + xyz + "comment c\nelement face 1\n" +
      list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list + "end_header", "ply\nformat ascii 1.0\n",
    "ply\nformat ascii 1.0\nelement vertex 0\nelement face 0\nend_header", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n",
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list + "end_head\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\n" + list, "ply\n", "ply",
    "ply\nformat ascii\n" + text.substr(17) + tri, "ply\nform ascii 1.0\n" + text.substr(17) + tri,
    "ply\nformat binary 1.0\n" + text.substr(17) + tri, "plyx\n" + text.substr(4) + tri, " ply\n" + text.substr(4) + tri,
    "ply\nformat ascii 1.0\nproperty double x\nelement vertex 3\n" + xyz + "element face 1\n" + list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3 4\n" + xyz + "element face 1\n" + list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex -3\n" + xyz + "element face 1\n" + list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex +3\n" + xyz + "element face 1\n" + list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex\n" + xyz + "element face 1\n" + list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double\n" + xyz + "element face 1\n" + list + "end_header\n" + tri,
    "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "element face 1\nproperty list uchar int\nend_header\n" + tri,
  };
  // Binary: little- and big-endian, floats and doubles, lengths of each size.
  for(int format : {1, 2})
    for(Ply_type coordinate : {Ply_type::float32, Ply_type::float64})
      for(Ply_type count : {Ply_type::int8, Ply_type::uint8, Ply_type::int16, Ply_type::uint16, Ply_type::int32,
                            Ply_type::uint32})
        for(Ply_type index : {Ply_type::int32, Ply_type::uint32}) {
          const std::string header = head(format == 1 ? "binary_little_endian" : "binary_big_endian",
                                          "property " + std::string(ply_type_name(coordinate)) + " x\nproperty " +
                                            ply_type_name(coordinate) + " y\nproperty " + ply_type_name(coordinate) +
                                            " z\n",
                                          "property list " + std::string(ply_type_name(count)) + " " +
                                            ply_type_name(index) + " vertex_indices\n");
          std::string data;
          for(double v : {0.1, 0., 0., 1., -0., 0., 0., 1e-40, 3.5}) put_ply_value(data, format, coordinate, v);
          std::string face;
          put_ply_value(face, format, count, 3);
          for(double i : {0., 1., 2.}) put_ply_value(face, format, index, i);
          contents.push_back(header + data + face);
          contents.push_back(header + data + face.substr(0, face.size() - 1)); // cut short
          contents.push_back(header + data);
          contents.push_back(header + data + face + "more");
          std::string negative;
          put_ply_value(negative, format, count, -1);
          contents.push_back(header + data + negative + face.substr(face.size() - 12));
          std::string large;
          put_ply_value(large, format, count, 200);
          contents.push_back(header + data + large + face.substr(face.size() - 12));
        }
  // A binary header ending in CRLF, and a NaN.
  std::string binary_tri = head("binary_little_endian", fxyz, list);
  for(float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, std::numeric_limits<float>::quiet_NaN()})
    put_ply_value(binary_tri, 1, Ply_type::float32, static_cast<double>(v));
  put_ply_value(binary_tri, 1, Ply_type::uint8, 3);
  for(double i : {0., 1., 2.}) put_ply_value(binary_tri, 1, Ply_type::int32, i);
  contents.push_back(binary_tri);
  std::string crlf = binary_tri;
  crlf.replace(crlf.find("end_header\n"), 11, "end_header\r\n");
  contents.push_back(crlf);

  std::size_t accepted = 0;
  for(std::size_t k = 0; k < contents.size(); ++k)
    accepted += expect_ply_read_as_cgal(contents[k], "case " + std::to_string(k) + ":\n" + contents[k]) ? 1 : 0;
  EXPECT_GT(accepted, 40u);
}

// PLY copies of small meshes in the styles of ply_texts(), damaged one to
// four times: header words replaced (by types, names, keywords, counts),
// header lines added, removed or swapped, words of the data replaced (by
// numbers at the edges of what the streams read), bytes changed, added or
// removed, CRLF line ends, the file cut short.
TEST(IoReadMeshPly, OnePassAnswersAsCgalOnMutatedFiles)
{
  std::vector<std::string> bases;
  for(const char* name : {"tetrahedron.off", "cube_quad.off", "octahedron.off", "star.off", "hole.off"}) {
    std::vector<Point_3> points;
    Obj_polygons polygons;
    read_off_soup(name, points, polygons);
    for(const std::string& text : ply_texts(points, polygons)) bases.push_back(text);
  }
  const std::vector<std::string> header_words = {
    "char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8", "int16", "uint16", "int32",
    "uint32", "float32", "float64", "list", "property", "element", "comment", "obj_info", "end_header", "vertex",
    "vertices", "face", "faces", "halfedge", "edge", "vertex_indices", "vertex_index", "x", "y", "z", "red", "green",
    "blue", "r", "g", "b", "source", "target", "u", "v", "ascii", "binary_little_endian", "binary_big_endian", "format",
    "0", "1", "2", "3", "7", "-1", "+2", "99999", "1e3", "", "xyz"};
  const std::vector<std::string> header_lines = {
    "property list uint int vertex_indices", "property list uchar uint vertex_index", "property float x",
    "property double y", "property uchar red", "property list int int values", "element thing 2", "element face 1",
    "element vertex 2", "comment c", "obj_info", "", "end_header", "property list ushort float texcoord",
    "property int source", "element halfedge 1"};
  const std::vector<std::string> data_words = {
    "inf", "-inf", "nan", "1e999", "-1e999", "1e-400", "4.9e-324", "1e-46", "3.5e38", "0x1p3", "+1", "-0", "0", "-1",
    "-3", "1-2", "1.5.3", "1e", "e5", ".", "-", ".5", "5.", "1e5x", "99999999999", "2147483647", "2147483648",
    "4294967295", "4294967296", "-4294967295", "300", "-253", "65536", "-65535", "200", "abc", "#", "\t", "\r",
    std::string(1, '\0'), "\v", std::string(300, '7'), "1e308", "1.8e308", "+-1", "1E5", "00012", "+.5", "1,5",
    "\xff", "1 2", "3 0 1 2"};
  std::mt19937 random(20261205);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(random() % n); };
  std::size_t accepted = 0;
  const std::size_t trials = 5000;
  for(std::size_t trial = 0; trial < trials; ++trial) {
    std::string content = bases[pick(bases.size())];
    const std::size_t header_end = content.find("end_header") + 10;
    std::vector<std::string> header;
    {
      std::istringstream in(content.substr(0, header_end));
      for(std::string line; std::getline(in, line);) header.push_back(line);
    }
    std::string data = content.substr(header_end);
    const bool text = content.find("format ascii") != std::string::npos;
    bool cut = false;
    for(std::size_t damage = 1 + pick(4); damage > 0; --damage) {
      std::string& line = header[pick(header.size())];
      switch(pick(10)) {
        case 0: case 1: { // a header word replaced
          std::size_t start = 0;
          for(std::size_t w = pick(5); w > 0 && line.find(' ', start) != std::string::npos; --w)
            start = line.find(' ', start) + 1;
          const std::size_t stop = std::min(line.find(' ', start), line.size());
          line.replace(start, stop - start, header_words[pick(header_words.size())]);
          break;
        }
        case 2: // a header line added
          header.insert(header.begin() + static_cast<std::ptrdiff_t>(1 + pick(header.size())),
                        header_lines[pick(header_lines.size())]);
          break;
        case 3: // a header line removed or swapped
          if(header.size() > 3) {
            const std::size_t at = 2 + pick(header.size() - 2);
            if(pick(2)) header.erase(header.begin() + static_cast<std::ptrdiff_t>(at));
            else std::swap(header[at], header[2 + pick(header.size() - 2)]);
          }
          break;
        case 4: case 5: { // a word of the data replaced (text), or bytes (binary)
          if(data.size() < 2) break;
          std::size_t start = pick(data.size());
          if(text) {
            while(start > 0 && !diffuv::internal::is_blank(data[start - 1])) --start;
            std::size_t stop = start;
            while(stop < data.size() && !diffuv::internal::is_blank(data[stop])) ++stop;
            data.replace(start, stop - start, data_words[pick(data_words.size())]);
          } else {
            const char bytes[] = {'\0', '\x01', '\x03', '\x7f', '\x80', '\xff'};
            for(std::size_t n = 1 + pick(4); n > 0 && start < data.size(); --n, ++start)
              data[start] = pick(2) ? bytes[pick(sizeof bytes)] : static_cast<char>(pick(256));
          }
          break;
        }
        case 6: { // a byte of the data inserted or removed
          const std::size_t at = pick(data.size() + 1);
          if(pick(2) || at == data.size()) data.insert(at, 1, static_cast<char>(pick(2) ? pick(256) : ' '));
          else data.erase(at, 1);
          break;
        }
        case 7: // a character of the header changed
          if(!line.empty()) line[pick(line.size())] = " \t\r0123456789-+.xe"[pick(18)];
          break;
        case 8: // CRLF
          for(std::string& l : header) l += "\r";
          if(text) {
            std::string crlf;
            for(char c : data) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
            data = crlf;
          }
          break;
        default: cut = true; break;
      }
    }
    content.clear();
    for(const std::string& line : header) content += line + "\n";
    content += data.substr(data.empty() || data[0] != '\n' ? 0 : 1);
    if(cut) content.resize(pick(content.size() + 1));
    accepted += expect_ply_read_as_cgal(content, "trial " + std::to_string(trial)) ? 1 : 0;
    if(::testing::Test::HasFailure()) {
      ADD_FAILURE() << "first difference on:\n" << content;
      break;
    }
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(accepted, trials / 10);
  EXPECT_LT(accepted, trials - trials / 10);
}

// The numbers of text PLY as libstdc++'s `>>` reads them into each type:
// the same success, value and stop, on words from an alphabet of what
// numbers are made of.
TEST(IoReadMeshPly, NumbersAsTheStreamsReadThem)
{
  std::mt19937 random(20261206);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(random() % n); };
  const std::string alphabet = "0123456789012345678901234567890123456789+-.eE x\t\n";
  auto check = [&](const std::string& word, auto read) {
    using T = decltype(read);
    T stream_value{}, value{};
    std::istringstream in(word);
    const bool stream_ok = static_cast<bool>(in >> stream_value);
    in.clear();
    const auto stream_stop = static_cast<std::size_t>(in.tellg());
    const char* at = word.data();
    bool ok;
    if constexpr(std::is_floating_point_v<T>)
      ok = diffuv::internal::extract_floating(at, word.data() + word.size(), value);
    else
      ok = diffuv::internal::extract_integer(at, word.data() + word.size(), value);
    EXPECT_EQ(ok, stream_ok) << "\"" << word << "\" as " << typeid(T).name();
    if(ok && stream_ok) {
      EXPECT_EQ(std::memcmp(&value, &stream_value, sizeof(T)), 0) << "\"" << word << "\" as " << typeid(T).name();
      EXPECT_EQ(static_cast<std::size_t>(at - word.data()), stream_stop) << "\"" << word << "\"";
    }
  };
  std::vector<std::string> words = {"-65535", "-65536", "65535", "65536", "-4294967295", "-4294967296", "4294967295",
                                    "-32768", "-32769", "32767", "32768", "-2147483648", "-2147483649", "2147483647",
                                    "3.4028235e38", "3.40282357e38", "1e-46", "1e-45", "1e-400", "1e309", "0x10",
                                    "+", "-", "", " ", "+-1", "00000000000000000000001", "99999999999999999999"};
  for(int k = 0; k < 20000; ++k) {
    std::string word;
    for(std::size_t n = 1 + pick(12); n > 0; --n) word += alphabet[pick(alphabet.size())];
    words.push_back(word);
  }
  for(const std::string& word : words) {
    check(word, short());
    check(word, static_cast<unsigned short>(0));
    check(word, int());
    check(word, 0u);
    check(word, float());
    check(word, double());
    if(::testing::Test::HasFailure())
      break;
  }
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
  e = strict_read_error(write("b.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n4 1 3 2 3\n"));
  EXPECT_EQ(e.reason(), "face 1 uses vertex 3 twice");
  EXPECT_EQ(e.line(), 8u);
}

TEST_F(IoReadMesh, NonManifoldOrInconsistentSoups)
{
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n";
  // Three faces on the edge 0-1.
  diffuv::Input_error e = strict_read_error(write("edge.off", "OFF\n5 3 0\n" + points + "3 0 1 2\n3 1 0 3\n3 0 1 4\n"));
  EXPECT_EQ(e.reason(), "non-manifold edge or vertex, or inconsistent orientation "
                        "(faces 0 and 2 both go from vertex 0 to vertex 1)");
  EXPECT_EQ(e.line(), 10u);
  // Two faces that disagree on the orientation of their common edge.
  e = strict_read_error(write("orientation.off", "OFF\n5 2 0\n" + points + "3 0 1 2\n3 0 1 3\n"));
  EXPECT_EQ(e.reason(), "non-manifold edge or vertex, or inconsistent orientation "
                        "(faces 0 and 1 both go from vertex 0 to vertex 1)");
  EXPECT_EQ(e.line(), 9u);
  // Two triangles touching at vertex 0 only (a bow tie).
  e = strict_read_error(write("bowtie.off", "OFF\n5 2 0\n" + points + "3 0 1 2\n3 0 3 4\n"));
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

// ---------------------------------------------------------------------------
// Repair (the default): no point moves, the file's points keep their numbers

Mesh read_repaired(const std::string& file, diffuv::Mesh_read_report& report)
{
  Mesh mesh;
  report = diffuv::read_triangle_mesh(file, mesh);
  return mesh;
}

// Every vertex sits where the file's point it stands for sits; points merged
// into another stay where they were, used by no face.
void expect_no_point_moved(const Mesh& mesh, const diffuv::Mesh_read_report& report, const File_soup& soup)
{
  ASSERT_EQ(report.vertices, soup.points.size());
  std::size_t moved = 0, bad_copies = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    const std::size_t i = report.point_of(v.idx());
    ASSERT_LT(i, soup.points.size());
    if(v.idx() >= soup.points.size() && i == v.idx()) ++bad_copies; // a copy must name its point
    const auto& q = soup.points[i];
    if(mesh.point(v) != Point_3(q[0], q[1], q[2])) ++moved;
  }
  EXPECT_EQ(moved, 0u);
  EXPECT_EQ(bad_copies, 0u);
  for(std::size_t i = 0; i < soup.points.size(); ++i) {
    const std::size_t v = report.vertex_of(i);
    EXPECT_LE(v, i);
    const auto& q = soup.points[i];
    EXPECT_EQ(mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(v))), Point_3(q[0], q[1], q[2]));
  }
}

// Every face of the mesh is its file polygon (a triangle), the points
// renamed as the repair renamed them: as in the file or turned over.
// Returns how many are turned over.
std::size_t faces_turned_over(const Mesh& mesh, const diffuv::Mesh_read_report& report, const File_soup& soup)
{
  std::size_t turned = 0, other = 0;
  EXPECT_EQ(report.file_face.size(), num_faces(mesh));
  for(face_descriptor f : faces(mesh)) {
    std::vector<std::size_t> corners;
    for(std::size_t v : diffuv_test::face_vertex_numbers(mesh, f)) corners.push_back(report.point_of(v));
    std::vector<std::size_t> polygon;
    for(std::size_t i : soup.faces[report.file_face[f.idx()]]) polygon.push_back(report.vertex_of(i));
    std::vector<std::size_t> reversed(polygon.rbegin(), polygon.rend());
    for(std::size_t& i : corners) i = report.vertex_of(i);
    if(diffuv_test::same_cycle(corners, reversed)) ++turned;
    else if(!diffuv_test::same_cycle(corners, polygon)) ++other;
  }
  EXPECT_EQ(other, 0u);
  return turned;
}

std::size_t non_manifold_vertex_count(const Mesh& mesh)
{
  std::vector<Mesh::Halfedge_index> found;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(found));
  return found.size();
}

// The soup as CGAL's OFF reader reads it (comments and all), in file order.
File_soup cgal_off_soup(const std::string& file)
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  EXPECT_TRUE(CGAL::IO::read_OFF(file, points, polygons)) << file;
  File_soup soup;
  for(const Point_3& p : points) soup.points.push_back({p.x(), p.y(), p.z()});
  soup.faces = polygons;
  return soup;
}

TEST(IoReadMeshRepair, ShuffledMeshesAreOrientedAsTheirOriginals)
{
  // CGAL's *-shuffled.off have faces turned over at random; blobby, cube and
  // oblong also come as they should be.
  for(const std::string name : {"blobby", "cube", "oblong", "cube4", "tet"}) {
    SCOPED_TRACE(name);
    const std::string file = diffuv_test::data_path("meshes/" + name + "-shuffled.off");
    EXPECT_EQ(strict_read_error(file).reason().rfind("non-manifold edge or vertex, or inconsistent orientation", 0), 0u);
    diffuv::Mesh_read_report report;
    const Mesh mesh = read_repaired(file, report);
    const File_soup soup = cgal_off_soup(file);
    EXPECT_GT(report.repair.faces_reoriented, 0u);
    EXPECT_EQ(report.repair.vertex_copies, 0u);
    EXPECT_TRUE(CGAL::is_closed(mesh));
    EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
    expect_no_point_moved(mesh, report, soup);
    if(report.polygons_triangulated == 0) EXPECT_EQ(faces_turned_over(mesh, report, soup), report.repair.faces_reoriented);
    const double volume = CGAL::to_double(CGAL::Polygon_mesh_processing::volume(mesh));
    const std::string original = diffuv_test::data_path("meshes/" + name + ".off");
    if(std::filesystem::exists(original)) {
      Mesh good;
      diffuv::read_triangle_mesh(original, good);
      const double expected = CGAL::to_double(CGAL::Polygon_mesh_processing::volume(good));
      EXPECT_NEAR(volume, expected, 1e-6 * std::abs(expected));
    } else {
      EXPECT_GT(volume, 0.); // outward, as most of its faces are
    }
  }
}

TEST(IoReadMeshRepair, PigStlNonManifoldVerticesAreSplit)
{
  const std::string file = diffuv_test::data_path("meshes/pig.stl");
  diffuv::Mesh_read_report report;
  const Mesh mesh = read_repaired(file, report);
  const File_soup soup = parse_binary_stl(file);
  EXPECT_GT(report.repair.vertices_split, 0u);
  EXPECT_GE(report.repair.vertex_copies, report.repair.vertices_split);
  EXPECT_EQ(num_vertices(mesh), soup.points.size() + report.repair.vertex_copies);
  EXPECT_EQ(num_faces(mesh), soup.faces.size());
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
  expect_no_point_moved(mesh, report, soup);
  EXPECT_EQ(faces_turned_over(mesh, report, soup), report.repair.faces_reoriented);
}

// Every face written with its own three points (an unwelded export): with
// the repair, one closed cow; without it, a valid but useless soup of
// separate triangles.
TEST_F(IoReadMesh, UnweldedFacesAreStitched)
{
  const File_soup cow = diffuv_test::parse_off(diffuv_test::data_path("meshes/cow.off"));
  std::ostringstream off;
  off << std::setprecision(17) << "OFF\n" << 3 * cow.faces.size() << ' ' << cow.faces.size() << " 0\n";
  for(const auto& f : cow.faces)
    for(std::size_t i : f) off << cow.points[i][0] << ' ' << cow.points[i][1] << ' ' << cow.points[i][2] << '\n';
  for(std::size_t j = 0; j < cow.faces.size(); ++j) off << "3 " << 3 * j << ' ' << 3 * j + 1 << ' ' << 3 * j + 2 << '\n';
  const std::string file = write("unwelded.off", off.str());
  const File_soup soup = diffuv_test::parse_off(file);

  diffuv::Mesh_read_report report;
  const Mesh mesh = read_repaired(file, report);
  EXPECT_EQ(report.repair.points_merged, 3 * cow.faces.size() - cow.points.size());
  EXPECT_EQ(report.isolated_vertices, report.repair.points_merged);
  EXPECT_EQ(report.repair.faces_reoriented, 0u);
  EXPECT_EQ(num_faces(mesh), cow.faces.size());
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
  expect_no_point_moved(mesh, report, soup);
  EXPECT_EQ(faces_turned_over(mesh, report, soup), 0u);
  std::vector<std::size_t> component(num_faces(mesh));
  EXPECT_EQ(CGAL::Polygon_mesh_processing::connected_components(
                mesh, CGAL::make_property_map(component)), 1u);

  Mesh apart;
  diffuv::Mesh_read_options strict;
  strict.repair = false;
  diffuv::read_triangle_mesh(file, apart, strict);
  std::vector<std::size_t> apart_component(num_faces(apart));
  EXPECT_EQ(CGAL::Polygon_mesh_processing::connected_components(
                apart, CGAL::make_property_map(apart_component)), cow.faces.size());
}

// A disc written without shared points is stitched back into a disc whose
// merged points are vertices on no face: parameterize_disc() maps it with
// the corners read through the merges, as it maps the same grid welded
// (every vertex at the same (u,v) as the welded grid's vertex at its place).
TEST_F(IoReadMesh, AStitchedDiscTakesCorners)
{
  const int n = 7; // n x n points, a gently curved grid
  const auto point = [&](int i, int j) {
    return std::array<double, 3>{double(i), double(j), 0.05 * (i - 3) * (j - 2)};
  };
  std::ostringstream welded, unwelded;
  welded << std::setprecision(17) << "OFF\n" << n * n << ' ' << 2 * (n - 1) * (n - 1) << " 0\n";
  unwelded << std::setprecision(17) << "OFF\n" << 6 * (n - 1) * (n - 1) << ' ' << 2 * (n - 1) * (n - 1) << " 0\n";
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const auto p = point(i, j);
      welded << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
  std::vector<std::array<int, 3>> triangles;
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  std::map<int, std::size_t> unwelded_point_of; // a grid point -> its first copy in the unwelded file
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int k = 0; k < 3; ++k) {
      const int g = triangles[t][k];
      unwelded_point_of.emplace(g, 3 * t + k);
      const auto p = point(g % n, g / n);
      unwelded << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
  for(const auto& t : triangles) welded << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for(std::size_t t = 0; t < triangles.size(); ++t)
    unwelded << "3 " << 3 * t << ' ' << 3 * t + 1 << ' ' << 3 * t + 2 << '\n';

  diffuv::Mesh_read_report welded_report, report;
  const Mesh grid = read_repaired(write("welded.off", welded.str()), welded_report);
  const Mesh stitched = read_repaired(write("unwelded.off", unwelded.str()), report);
  ASSERT_FALSE(welded_report.repair.any());
  ASSERT_EQ(report.repair.points_merged, 6 * (n - 1) * (n - 1) - n * n);
  EXPECT_FALSE(diffuv::check_disc(stitched));                 // vertices on no face: not a disc as such
  EXPECT_TRUE(diffuv::check_disc(stitched, true)) << diffuv::check_disc(stitched, true).what();

  const std::array<int, 4> grid_corners = {0, n - 1, n * n - 1, n * (n - 1)};
  std::vector<vertex_descriptor> welded_corners, stitched_corners;
  for(int g : grid_corners) {
    welded_corners.emplace_back(static_cast<Mesh::size_type>(g));
    stitched_corners.emplace_back(static_cast<Mesh::size_type>(report.vertex_of(unwelded_point_of.at(g))));
  }
  diffuv::Uv_atlas<Mesh> welded_atlas(grid), atlas(stitched);
  diffuv::Disc_parameterization_report<Mesh> welded_sides, sides;
  ASSERT_TRUE(diffuv::parameterize_disc(grid, grid.points(), welded_corners, welded_atlas, {}, &welded_sides));
  const diffuv::Status status = diffuv::parameterize_disc(stitched, stitched.points(), stitched_corners, atlas, {}, &sides);
  ASSERT_TRUE(status) << status.what();
  ASSERT_EQ(atlas.number_of_charts(), 1u);
  EXPECT_EQ(atlas.chart(0).vertices.size(), std::size_t(n * n));
  EXPECT_EQ(atlas.chart(0).faces.size(), triangles.size());
  EXPECT_EQ(sides.sides.corners[0], stitched_corners[0]);
  EXPECT_EQ(sides.sides.u1.size(), welded_sides.sides.u1.size());
  EXPECT_EQ(sides.sides.v2.size(), welded_sides.sides.v2.size());
  for(int g = 0; g < n * n; ++g) {
    const vertex_descriptor w(static_cast<Mesh::size_type>(g));
    const vertex_descriptor s(static_cast<Mesh::size_type>(report.vertex_of(unwelded_point_of.at(g))));
    ASSERT_EQ(stitched.point(s), grid.point(w));
    const auto expected = get(welded_atlas.chart_uv_map(0), w), got = get(atlas.chart_uv_map(0), s);
    EXPECT_NEAR(got.x(), expected.x(), 1e-12) << "grid point " << g;
    EXPECT_NEAR(got.y(), expected.y(), 1e-12) << "grid point " << g;
  }
  // A corner on no face (a merged point) is refused, naming it.
  std::vector<vertex_descriptor> merged_corner = stitched_corners;
  merged_corner[1] = vertex_descriptor(static_cast<Mesh::size_type>(3 * (n - 1) * (n - 1) * 2 - 1));
  ASSERT_EQ(stitched.halfedge(merged_corner[1]), Mesh::null_halfedge());
  diffuv::Uv_atlas<Mesh> refused(stitched);
  const diffuv::Status no_face = diffuv::parameterize_disc(stitched, stitched.points(), merged_corner, refused);
  EXPECT_EQ(no_face.code, diffuv::Status_code::corner_not_on_border) << no_face.what();
  EXPECT_EQ(refused.number_of_charts(), 0u);
}

// STL has no shared points: CGAL's reader merges identical ones, so a closed
// mesh written as STL is read closed. STL is single precision: two of cow's
// points become one float point, whose faces then meet in two fans; the
// repair splits it again (and nothing else is repaired).
TEST_F(IoReadMesh, StlOfAClosedMeshIsReadClosed)
{
  const File_soup cow = diffuv_test::parse_off(diffuv_test::data_path("meshes/cow.off"));
  std::ostringstream stl;
  stl << std::setprecision(9) << "solid cow\n";
  for(const auto& f : cow.faces) {
    stl << "facet normal 0 0 0\nouter loop\n";
    for(std::size_t i : f)
      stl << "vertex " << float(cow.points[i][0]) << ' ' << float(cow.points[i][1]) << ' ' << float(cow.points[i][2]) << '\n';
    stl << "endloop\nendfacet\n";
  }
  stl << "endsolid cow\n";
  std::vector<std::array<float, 3>> single;
  for(const auto& p : cow.points) single.push_back({{float(p[0]), float(p[1]), float(p[2])}});
  std::sort(single.begin(), single.end());
  const std::size_t distinct = static_cast<std::size_t>(std::unique(single.begin(), single.end()) - single.begin());
  ASSERT_LT(distinct, cow.points.size()); // what this test is about

  diffuv::Mesh_read_report report;
  const Mesh mesh = read_repaired(write("cow.stl", stl.str()), report);
  EXPECT_EQ(report.vertices, distinct);
  EXPECT_EQ(report.repair.vertices_split, cow.points.size() - distinct);
  EXPECT_EQ(report.repair.points_merged + report.repair.degenerate_faces + report.repair.duplicate_faces +
                report.repair.faces_reoriented + report.repair.non_manifold_edges,
            0u);
  EXPECT_EQ(num_vertices(mesh), cow.points.size());
  EXPECT_EQ(num_faces(mesh), cow.faces.size());
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
}

// Labels are numbered by the file's faces: a face dropped or turned over by
// the repair must not shift them.
TEST_F(IoReadMesh, LabelsFollowTheFileFacesThroughTheRepair)
{
  const std::string points = "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n";
  // The 2x2 grid's 8 triangles, with a face using point 4 twice (file face
  // 2), a copy of face 0 turned over (file face 5), and face 8 turned over.
  const std::string face_lines = "3 0 1 4\n3 0 4 3\n3 4 4 1\n3 1 2 5\n3 1 5 4\n3 4 1 0\n3 3 4 7\n3 3 7 6\n3 4 8 5\n3 4 8 7\n";
  const std::string file = write("grid.off", "OFF\n9 10 0\n" + points + face_lines);
  std::string labels;
  for(int j = 0; j < 10; ++j) labels += std::to_string(100 + j) + "\n";
  const std::string label_file = write("grid.labels.txt", labels);

  diffuv::Mesh_read_report report;
  const Mesh mesh = read_repaired(file, report);
  EXPECT_EQ(report.repair.degenerate_faces, 1u);
  EXPECT_EQ(report.repair.duplicate_faces, 1u);
  EXPECT_EQ(report.repair.faces_reoriented, 1u);
  ASSERT_EQ(num_faces(mesh), 8u);
  const std::vector<int> face_labels =
      diffuv::face_labels_of_mesh(diffuv::read_face_labels(label_file, report.faces_in_file), report);
  const File_soup soup = diffuv_test::parse_off(file);
  EXPECT_EQ(faces_turned_over(mesh, report, soup), 1u);
  for(face_descriptor f : faces(mesh)) {
    const std::size_t j = report.file_face[f.idx()];
    EXPECT_NE(j, 2u);
    EXPECT_NE(j, 5u);
    EXPECT_EQ(face_labels[f.idx()], 100 + static_cast<int>(j));
  }
  // Without the repair: refused, naming the first problem.
  EXPECT_EQ(strict_read_error(file).reason(), "face 2 uses vertex 4 twice");
}

// CGAL keeps the orientation of each component's first face; diffuv the
// orientation of most faces.
TEST_F(IoReadMesh, MostFacesKeepTheirOrientation)
{
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::vector<std::string> outward = {"3 0 2 1\n", "3 0 1 3\n", "3 0 3 2\n", "3 1 2 3\n"};
  for(std::size_t flipped = 0; flipped < 4; ++flipped) {
    std::string face_lines;
    for(std::size_t j = 0; j < 4; ++j) {
      std::istringstream in(outward[j]);
      std::size_t k, a, b, c;
      in >> k >> a >> b >> c;
      face_lines += j == flipped ? "3 " + std::to_string(a) + ' ' + std::to_string(c) + ' ' + std::to_string(b) + '\n'
                            : outward[j];
    }
    diffuv::Mesh_read_report report;
    const Mesh mesh = read_repaired(write("tet" + std::to_string(flipped) + ".off", "OFF\n4 4 0\n" + points + face_lines), report);
    EXPECT_EQ(report.repair.faces_reoriented, 1u) << "face " << flipped << " turned over";
    EXPECT_NEAR(CGAL::to_double(CGAL::Polygon_mesh_processing::volume(mesh)), 1. / 6., 1e-12);
  }
}

// A closed mesh whose faces were turned more often than not is read facing
// outwards (its signed volume positive), and an open one keeps the
// orientation most of its faces had: cow with three faces in four turned
// over, and the same with one face removed (then open).
TEST_F(IoReadMesh, AClosedMeshFacesOutwards)
{
  const File_soup cow = diffuv_test::parse_off(diffuv_test::data_path("meshes/cow.off"));
  const auto write_turned = [&](const std::string& name, std::size_t skip) {
    std::ostringstream off;
    const std::size_t faces = cow.faces.size() - (skip < cow.faces.size() ? 1 : 0);
    off << std::setprecision(17) << "OFF\n" << cow.points.size() << ' ' << faces << " 0\n";
    for(const auto& p : cow.points) off << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for(std::size_t j = 0; j < cow.faces.size(); ++j) {
      if(j == skip) continue;
      std::vector<std::size_t> f = cow.faces[j];
      if(j % 4 != 0) std::reverse(f.begin(), f.end());
      off << f.size();
      for(std::size_t i : f) off << ' ' << i;
      off << '\n';
    }
    return write(name, off.str());
  };
  diffuv::Mesh_read_report report;
  const Mesh closed = read_repaired(write_turned("closed.off", std::size_t(-1)), report);
  ASSERT_TRUE(CGAL::is_closed(closed));
  EXPECT_GT(CGAL::to_double(CGAL::Polygon_mesh_processing::volume(closed)), 0.);
  EXPECT_EQ(report.repair.faces_reoriented, cow.faces.size() - (cow.faces.size() + 3) / 4); // the turned ones back
  const Mesh open = read_repaired(write_turned("open.off", 1), report);
  ASSERT_FALSE(CGAL::is_closed(open));
  EXPECT_EQ(report.repair.faces_reoriented, (cow.faces.size() + 3) / 4); // the few, against most of the faces
}

TEST_F(IoReadMesh, NonManifoldPlacesAreSplit)
{
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n";
  // Two triangles touching at point 0 only (a bow tie): point 0 gets a copy.
  diffuv::Mesh_read_report report;
  Mesh mesh = read_repaired(write("bowtie.off", "OFF\n5 2 0\n" + points + "3 0 1 2\n3 0 3 4\n"), report);
  EXPECT_EQ(report.repair.vertices_split, 1u);
  EXPECT_EQ(report.repair.vertex_copies, 1u);
  EXPECT_EQ(num_vertices(mesh), 6u);
  EXPECT_EQ(report.point_of(5), 0u);
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
  // Three faces on the edge 0-1: cut apart, its two ends split.
  mesh = read_repaired(write("edge.off", "OFF\n5 3 0\n" + points + "3 0 1 2\n3 1 0 3\n3 0 1 4\n"), report);
  EXPECT_EQ(report.repair.non_manifold_edges, 1u);
  EXPECT_EQ(report.repair.vertices_split, 2u);
  EXPECT_EQ(num_vertices(mesh), 5u + report.repair.vertex_copies);
  EXPECT_EQ(num_faces(mesh), 3u);
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
  for(vertex_descriptor v : vertices(mesh)) EXPECT_EQ(mesh.point(v), mesh.point(Mesh::Vertex_index(report.point_of(v.idx()))));
}

// A Moebius strip of six quads cut in triangles: no orientation agrees
// everywhere; refused, naming two faces and their edge.
TEST_F(IoReadMesh, MoebiusStripIsRefused)
{
  const int n = 6;
  std::ostringstream off;
  off << "OFF\n" << 2 * n << ' ' << 2 * n << " 0\n" << std::setprecision(17);
  const double pi = 3.14159265358979323846;
  for(int i = 0; i < n; ++i) {
    const double t = 2 * pi * i / n;
    for(double w : {-0.5, 0.5})
      off << (2 + w * std::cos(t / 2)) * std::cos(t) << ' ' << (2 + w * std::cos(t / 2)) * std::sin(t) << ' '
          << w * std::sin(t / 2) << '\n';
  }
  for(int i = 0; i < n; ++i) {
    // Quad (2i, 2i+1) -> next; the last one joins the first with a half twist.
    const int a = 2 * i, b = 2 * i + 1;
    const int c = i + 1 < n ? 2 * i + 3 : 0, d = i + 1 < n ? 2 * i + 2 : 1;
    off << "3 " << a << ' ' << b << ' ' << c << "\n3 " << a << ' ' << c << ' ' << d << '\n';
  }
  const diffuv::Input_error e = read_error(write("moebius.off", off.str()));
  EXPECT_EQ(e.reason().rfind("the surface is not orientable (like a Moebius strip): faces ", 0), 0u) << e.reason();
  EXPECT_NE(e.reason().find(" disagree on the direction of the edge between vertices "), std::string::npos) << e.reason();
  // The faces named are where the strip's twist is: in the file, both go
  // the same way along the edge named.
  std::size_t f = 0, g = 0, a = 0, b = 0;
  ASSERT_EQ(std::sscanf(e.reason().c_str(),
                        "the surface is not orientable (like a Moebius strip): faces %zu and %zu disagree on the "
                        "direction of the edge between vertices %zu and %zu",
                        &f, &g, &a, &b),
            4)
      << e.reason();
  const File_soup soup = diffuv_test::parse_off(write("moebius.off", off.str()));
  const auto direction = [&](std::size_t face) {
    const auto& p = soup.faces.at(face);
    for(std::size_t k = 0; k < p.size(); ++k) {
      if(p[k] == a && p[(k + 1) % p.size()] == b) return 1;
      if(p[k] == b && p[(k + 1) % p.size()] == a) return -1;
    }
    return 0;
  };
  EXPECT_NE(direction(f), 0);
  EXPECT_EQ(direction(f), direction(g)) << e.reason();
  EXPECT_GT(e.line(), 2u + 2 * n);
}

// ---------------------------------------------------------------------------
// The soup built into a mesh in one pass (io/internal/soup_to_mesh.h): the
// same arrays as CGAL's polygon_soup_to_polygon_mesh(), halfedge for halfedge.

// Where two meshes differ ("" if nowhere): counts, points, and every
// connectivity array of Surface_mesh.
std::string first_difference(const Mesh& a, const Mesh& b)
{
  if(a.number_of_vertices() != b.number_of_vertices() || a.number_of_halfedges() != b.number_of_halfedges() ||
     a.number_of_faces() != b.number_of_faces())
    return "counts";
  for(auto v : a.vertices()) {
    if(a.point(v) != b.point(v)) return "point of vertex " + std::to_string(v.idx());
    if(a.halfedge(v) != b.halfedge(v)) return "halfedge of vertex " + std::to_string(v.idx());
  }
  for(auto h : a.halfedges()) {
    const std::string at = " of halfedge " + std::to_string(h.idx());
    if(a.target(h) != b.target(h)) return "target" + at;
    if(a.next(h) != b.next(h)) return "next" + at;
    if(a.prev(h) != b.prev(h)) return "prev" + at;
    if(a.face(h) != b.face(h)) return "face" + at;
  }
  for(auto f : a.faces())
    if(a.halfedge(f) != b.halfedge(f)) return "halfedge of face " + std::to_string(f.idx());
  return "";
}

// Builds the soup both ways; false if the one-pass builder refused it.
bool expect_built_as_cgal_builds(const std::vector<Point_3>& points, const std::vector<std::vector<std::size_t>>& polygons,
                                 const std::string& what)
{
  Mesh by_cgal, by_us;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, by_cgal);
  if(!diffuv::internal::soup_to_surface_mesh(points, polygons, by_us)) return false;
  EXPECT_TRUE(by_us.is_valid(false)) << what;
  EXPECT_EQ(first_difference(by_cgal, by_us), "") << what;
  return true;
}

TEST(IoSoupToMesh, SameMeshAsCgalsBuilderOnRealMeshes)
{
  // Closed (cow), with a border (mushroom), three components (blobby_3cc),
  // polygons of 3 to 12 corners (3torus, P, torus_quad, cube_quad).
  for(const char* name : {"cow.off", "mushroom.off", "blobby_3cc.off", "3torus.off", "P.off", "torus_quad.off", "cube_quad.off"}) {
    std::vector<Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(diffuv_test::data_path(std::string("meshes/") + name), points, polygons)) << name;
    ASSERT_TRUE(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons)) << name;
    EXPECT_TRUE(expect_built_as_cgal_builds(points, polygons, name)) << name << " refused";
  }
}

TEST(IoSoupToMesh, SameMeshAsCgalsBuilderOnShuffledSoupsWithHoles)
{
  // Soups made from real ones: polygons shuffled and their corners rotated,
  // then some removed (holes), a renumbered copy of part of it added (a second
  // component, isolated points), the points renumbered. The builders must
  // agree wherever CGAL calls the soup a polygon mesh; the order in which
  // polygons arrive is what decides CGAL's halfedge of each vertex.
  std::mt19937 random(7);
  std::size_t compared = 0, with_holes = 0, with_polygons = 0;
  for(const char* name : {"cow.off", "mushroom.off", "3torus.off", "P.off", "cube_quad.off", "nefertiti.off"}) {
    std::vector<Point_3> points0;
    std::vector<std::vector<std::size_t>> polygons0;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(diffuv_test::data_path(std::string("meshes/") + name), points0, polygons0)) << name;
    for(int trial = 0; trial < 24; ++trial) {
      std::vector<Point_3> points = points0;
      std::vector<std::vector<std::size_t>> polygons = polygons0;
      std::shuffle(polygons.begin(), polygons.end(), random);
      for(auto& polygon : polygons) std::rotate(polygon.begin(), polygon.begin() + random() % polygon.size(), polygon.end());
      const int kind = trial % 4;
      if(kind >= 1)
        for(std::size_t k = random() % (1 + polygons.size() / 10); k > 0 && polygons.size() > 1; --k)
          polygons.erase(polygons.begin() + static_cast<std::ptrdiff_t>(random() % polygons.size()));
      if(kind >= 2) {
        points.emplace_back(9, 9, 9);  // isolated
        const std::size_t offset = points.size();
        points.insert(points.end(), points0.begin(), points0.end());
        std::vector<std::vector<std::size_t>> copy;
        for(const auto& polygon : polygons)
          if(random() % 2) {
            copy.push_back(polygon);
            for(auto& v : copy.back()) v += offset;
          }
        polygons.insert(polygons.end(), copy.begin(), copy.end());
        std::shuffle(polygons.begin(), polygons.end(), random);
      }
      if(kind == 3) {
        std::vector<std::size_t> renumber(points.size());
        std::iota(renumber.begin(), renumber.end(), std::size_t(0));
        std::shuffle(renumber.begin(), renumber.end(), random);
        std::vector<Point_3> moved(points.size());
        for(std::size_t i = 0; i < points.size(); ++i) moved[renumber[i]] = points[i];
        points = moved;
        for(auto& polygon : polygons)
          for(auto& v : polygon) v = renumber[v];
      }
      if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons)) continue;
      const std::string what = std::string(name) + ", trial " + std::to_string(trial);
      ASSERT_TRUE(expect_built_as_cgal_builds(points, polygons, what)) << what << " refused";
      ++compared;
      Mesh mesh;
      diffuv::internal::soup_to_surface_mesh(points, polygons, mesh);
      if(!CGAL::is_closed(mesh)) ++with_holes;
      if(!CGAL::is_triangle_mesh(mesh)) ++with_polygons;
    }
  }
  // Enough of each kind to mean something (about half the trials cut a
  // vertex's fan in two and are not meshes).
  EXPECT_GE(compared, 40u);
  EXPECT_GE(with_holes, 15u);
  EXPECT_GE(with_polygons, 10u);
}

TEST(IoSoupToMesh, RefusesWhatIsNotAMeshAndLeavesItToCgal)
{
  // A square of two triangles, then broken in each way the builder checks.
  const std::vector<Point_3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}};
  using Soup = std::vector<std::vector<std::size_t>>;
  EXPECT_TRUE(expect_built_as_cgal_builds(points, Soup{{0, 1, 2}, {0, 2, 3}}, "square"));
  const std::vector<std::pair<const char*, Soup>> broken = {
      {"an edge run the same way twice", Soup{{0, 1, 2}, {0, 1, 3}}},
      {"an edge of three faces", Soup{{0, 1, 2}, {1, 0, 3}, {1, 0, 4}}},
      {"a point used twice", Soup{{0, 1, 2, 1}}},
      {"two corners", Soup{{0, 1}}},
      {"two gaps at a vertex", Soup{{0, 1, 2}, {0, 3, 4}}},
      {"a point out of range", Soup{{0, 1, 7}}}};
  for(const auto& [what, polygons] : broken) {
    Mesh mesh;
    EXPECT_FALSE(diffuv::internal::soup_to_surface_mesh(points, polygons, mesh)) << what;
    EXPECT_TRUE(mesh.is_empty()) << what;
  }
  // Two closed fans on one vertex (two tetrahedra sharing an apex), and a
  // closed fan with an open one: no border gap is doubled, but the walk
  // around the apex misses polygons.
  const std::vector<Point_3> cones = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  const Soup tetrahedron = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  Soup two_tetrahedra = tetrahedron;
  for(const auto& t : tetrahedron) two_tetrahedra.push_back({t[0] == 0 ? 0 : t[0] + 3, t[1] == 0 ? 0 : t[1] + 3, t[2] == 0 ? 0 : t[2] + 3});
  Soup tetrahedron_and_fan = tetrahedron;
  tetrahedron_and_fan.push_back({0, 4, 5});
  tetrahedron_and_fan.push_back({0, 5, 6});
  for(const Soup& polygons : {two_tetrahedra, tetrahedron_and_fan}) {
    Mesh mesh;
    EXPECT_FALSE(diffuv::internal::soup_to_surface_mesh(cones, polygons, mesh)) << polygons.size() << " polygons";
    EXPECT_TRUE(mesh.is_empty());
  }
  // soup_to_mesh() then gives CGAL's answer: two triangles that share vertex 0
  // only become two fans there.
  Mesh by_cgal, by_us;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, broken[4].second, by_cgal);
  diffuv::internal::soup_to_mesh(points, broken[4].second, by_us);
  EXPECT_EQ(first_difference(by_cgal, by_us), "");
  EXPECT_EQ(by_us.number_of_faces(), 2u);
}

} // namespace
