// Tests of include/diffuv/output/write_obj.h: the OBJ writer (a round trip
// of a real mesh, texture coordinates per corner on a seam, a failed write).
//
// The written file is parsed here by hand, not with CGAL's reader (which
// ignores texture coordinates).
#include "test_data.h"

#include <diffuv/output/write_obj.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using diffuv_test::Mesh;
using diffuv_test::Point_2;
using diffuv_test::Point_3;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using halfedge_descriptor = boost::graph_traits<Mesh>::halfedge_descriptor;
using face_descriptor = boost::graph_traits<Mesh>::face_descriptor;

using IoWriteObj = diffuv_test::Temp_dir_test;

struct Obj_file {
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<double, 2>> vt;
  std::vector<std::vector<std::array<std::size_t, 2>>> f; // 1-based (v, vt) per corner
  std::vector<std::string> other;                          // lines of other kinds
};

Obj_file parse_written_obj(const std::string& file)
{
  Obj_file obj;
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if(kind == "v") {
      std::array<double, 3> p;
      words >> p[0] >> p[1] >> p[2];
      obj.v.push_back(p);
    } else if(kind == "vt") {
      std::array<double, 2> t;
      words >> t[0] >> t[1];
      obj.vt.push_back(t);
    } else if(kind == "f") {
      std::vector<std::array<std::size_t, 2>> corners;
      std::string corner;
      while(words >> corner) {
        const std::size_t slash = corner.find('/');
        corners.push_back({std::stoul(corner.substr(0, slash)), std::stoul(corner.substr(slash + 1))});
      }
      obj.f.push_back(corners);
    } else {
      obj.other.push_back(line);
    }
  }
  return obj;
}

TEST_F(IoWriteObj, RoundTripOfARealMesh)
{
  const Mesh& mesh = diffuv_test::cgal_mesh("nefertiti.off");
  // One chart: the uv of a corner is a function of its vertex.
  auto uv_of = [&](vertex_descriptor v) {
    const Point_3& p = mesh.point(v);
    return Point_2(p.x() / 3 + 0.1, p.y() * p.z() + 1e-7);
  };
  Mesh copy = mesh;
  auto corner_uv = copy.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  for(halfedge_descriptor h : halfedges(copy))
    corner_uv[h] = uv_of(target(h, copy));

  const std::string file = path("nefertiti.obj");
  diffuv::write_obj(file, copy, copy.points(), corner_uv, "parameterization.mtl", "checker");
  const Obj_file obj = parse_written_obj(file);

  ASSERT_EQ(obj.v.size(), num_vertices(mesh));
  EXPECT_EQ(obj.vt.size(), num_vertices(mesh)); // no seam: one vt per vertex
  ASSERT_EQ(obj.f.size(), num_faces(mesh));
  EXPECT_EQ(obj.other, (std::vector<std::string>{"mtllib parameterization.mtl", "usemtl checker"}));

  std::size_t i = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    const Point_3& p = mesh.point(v);
    EXPECT_EQ(obj.v[i][0], p.x()); // 17 digits: exact
    EXPECT_EQ(obj.v[i][1], p.y());
    EXPECT_EQ(obj.v[i][2], p.z());
    ++i;
  }
  std::size_t j = 0, wrong_vertices = 0, wrong_uv = 0;
  for(face_descriptor f : faces(mesh)) {
    const std::vector<std::size_t> expected = diffuv_test::face_vertex_numbers(mesh, f);
    const auto& corners = obj.f[j++];
    ASSERT_EQ(corners.size(), 3u);
    for(std::size_t c = 0; c < 3; ++c) {
      if(corners[c][0] != expected[c] + 1)
        ++wrong_vertices;
      const Point_2 uv = uv_of(vertex_descriptor(static_cast<Mesh::size_type>(expected[c])));
      const auto& t = obj.vt.at(corners[c][1] - 1);
      if(std::abs(t[0] - uv.x()) > 1e-8 * std::max(1.0, std::abs(uv.x())) ||
         std::abs(t[1] - uv.y()) > 1e-8 * std::max(1.0, std::abs(uv.y())))
        ++wrong_uv;
    }
  }
  EXPECT_EQ(wrong_vertices, 0u);
  EXPECT_EQ(wrong_uv, 0u);
}

TEST_F(IoWriteObj, SeamVertexGetsTwoTextureCoordinates)
{
  // Two triangles 0-1-2 and 0-2-3 cut along their common edge 0-2 in uv.
  Mesh mesh;
  const vertex_descriptor a = mesh.add_vertex(Point_3(0, 0, 0)), b = mesh.add_vertex(Point_3(1, 0, 0)),
                          c = mesh.add_vertex(Point_3(1, 1, 0)), d = mesh.add_vertex(Point_3(0, 1, 0));
  const face_descriptor f1 = mesh.add_face(a, b, c), f2 = mesh.add_face(a, c, d);
  auto corner_uv = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f1, mesh), mesh)) {
    const Point_3& p = mesh.point(target(h, mesh));
    corner_uv[h] = Point_2(p.x(), p.y());
  }
  // In the second face, a moves in u only and c in v only: both must count.
  for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f2, mesh), mesh)) {
    const vertex_descriptor v = target(h, mesh);
    const Point_3& p = mesh.point(v);
    corner_uv[h] = Point_2(p.x() + (v == a ? 2 : 0), p.y() + (v == c ? 2 : 0));
  }
  const std::string file = path("seam.obj");
  diffuv::write_obj(file, mesh, mesh.points(), corner_uv);
  const Obj_file obj = parse_written_obj(file);
  EXPECT_EQ(obj.v.size(), 4u);
  EXPECT_EQ(obj.vt.size(), 6u); // a and c twice, b and d once
  ASSERT_EQ(obj.f.size(), 2u);
  EXPECT_TRUE(obj.other.empty());

  // Each corner refers to its own vertex and to a vt holding that corner's uv.
  std::size_t j = 0;
  std::map<std::size_t, std::vector<std::size_t>> vts_of_vertex;
  for(face_descriptor f : {f1, f2}) {
    std::size_t c = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const auto& corner = obj.f[j][c++];
      EXPECT_EQ(corner[0], std::size_t(target(h, mesh)) + 1);
      EXPECT_EQ(obj.vt.at(corner[1] - 1)[0], corner_uv[h].x());
      EXPECT_EQ(obj.vt.at(corner[1] - 1)[1], corner_uv[h].y());
      vts_of_vertex[corner[0]].push_back(corner[1]);
    }
    ++j;
  }
  EXPECT_NE(vts_of_vertex[1][0], vts_of_vertex[1][1]); // vertex a on the seam
  EXPECT_NE(vts_of_vertex[3][0], vts_of_vertex[3][1]); // vertex c on the seam
}

TEST_F(IoWriteObj, MissingFolderThrows)
{
  const Mesh& mesh = diffuv_test::cgal_mesh("nefertiti.off");
  Mesh copy = mesh;
  auto corner_uv = copy.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
  const std::string file = path("missing/out.obj");
  try {
    diffuv::write_obj(file, copy, copy.points(), corner_uv);
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Output_error& e) {
    EXPECT_EQ(e.path(), file);
    EXPECT_EQ(std::string(e.what()), file + ": cannot create the temporary file " + path("missing/.out.obj.tmp.") +
                                         std::to_string(::getpid()) + " (No such file or directory)");
  }
  EXPECT_FALSE(fs::exists(path("missing")));
}

} // namespace
