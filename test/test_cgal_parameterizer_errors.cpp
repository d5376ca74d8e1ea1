// Tests of Diffusion_parameterizer_3's errors (cgal/Diffusion_parameterizer_3.h):
// meshes that are not discs, bad or missing corners, corner lists of another
// length than four, error codes and messages through CGAL's parameterize().
#include "test_data.h"

#include <diffuv/cgal/Diffusion_parameterizer_3.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_map>

namespace {

using namespace diffuv_test;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

using vertex_descriptor = Mesh::Vertex_index;
using halfedge_descriptor = Mesh::Halfedge_index;
using Parameterizer = diffuv::Diffusion_parameterizer_3<Mesh>;
using Seam_edge_pmap = Mesh::Property_map<Mesh::Edge_index, bool>;
using Seam_vertex_pmap = Mesh::Property_map<vertex_descriptor, bool>;
using Tube_seam_mesh = CGAL::Seam_mesh<Mesh, Seam_edge_pmap, Seam_vertex_pmap>;
using Seam_vertex = boost::graph_traits<Tube_seam_mesh>::vertex_descriptor;

TEST(CgalParameterizer, ClosedMeshIsNotADisc)
{
  Mesh cow = cgal_mesh("cow.off");
  auto uv = cow.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(-7, -7)).first;
  auto parameterized = cow.add_property_map<vertex_descriptor, bool>("v:parameterized", false).first;
  auto index = cow.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  ASSERT_EQ(PMP::longest_border(cow).first, Mesh::null_halfedge()); // no border halfedge to give CGAL's parameterize()

  Parameterizer parameterizer;
  EXPECT_EQ(parameterizer.parameterize(cow, Mesh::null_halfedge(), uv, index, parameterized), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_EQ(parameterizer.status().code, diffuv::Status_code::no_border);
  // Any halfedge of it: its component is closed.
  EXPECT_EQ(parameterizer.parameterize(cow, *halfedges(cow).begin(), uv, index, parameterized),
            SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_EQ(parameterizer.status().code, diffuv::Status_code::no_border);
  EXPECT_TRUE(parameterizer.corners().empty());
  for(vertex_descriptor v : vertices(cow)) {
    EXPECT_FALSE(parameterized[v]);
    EXPECT_EQ(uv[v], Point_2(-7, -7));
  }

  // A closed Seam_mesh without seams: the same.
  Seam_edge_pmap seam_edges = cow.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_pmap seam_vertices = cow.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  Tube_seam_mesh seam_mesh(cow, seam_edges, seam_vertices);
  std::unordered_map<Seam_vertex, Point_2> uv_of;
  std::unordered_map<Seam_vertex, bool> parameterized_of;
  std::unordered_map<Seam_vertex, int> index_of;
  diffuv::Diffusion_parameterizer_3<Tube_seam_mesh> seam_parameterizer;
  EXPECT_EQ(seam_parameterizer.parameterize(seam_mesh, PMP::longest_border(seam_mesh).first,
                                            boost::make_assoc_property_map(uv_of), boost::make_assoc_property_map(index_of),
                                            boost::make_assoc_property_map(parameterized_of)),
            SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_TRUE(uv_of.empty());
  EXPECT_TRUE(parameterized_of.empty());
}

TEST(CgalParameterizer, AnnulusIsNotADisc)
{
  // A grid with a hole in its middle: two border loops.
  Mesh annulus = make_grid(4, 4);
  for(auto f : faces(annulus)) {
    auto c = CGAL::centroid(annulus.point(annulus.source(annulus.halfedge(f))), annulus.point(annulus.target(annulus.halfedge(f))),
                            annulus.point(annulus.target(annulus.next(annulus.halfedge(f)))));
    if(std::abs(c.x() - 0.5) < 0.25 && std::abs(c.y() - 0.5) < 0.25) CGAL::Euler::remove_face(annulus.halfedge(f), annulus);
  }
  annulus.collect_garbage();
  auto uv = annulus.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(-7, -7)).first;
  for(halfedge_descriptor bhd : {PMP::longest_border(annulus).first, halfedge_descriptor()}) {
    if(bhd == halfedge_descriptor()) // the inner loop
      for(halfedge_descriptor h : halfedges(annulus))
        if(is_border(h, annulus) && std::abs(annulus.point(target(h, annulus)).x() - 0.5) < 0.3) bhd = h;
    ASSERT_TRUE(is_border(bhd, annulus));
    Parameterizer parameterizer;
    EXPECT_EQ(SMP::parameterize(annulus, parameterizer, bhd, uv), SMP::ERROR_NO_TOPOLOGICAL_DISC);
    EXPECT_EQ(parameterizer.status().code, diffuv::Status_code::several_borders) << parameterizer.status().what();
  }
  for(vertex_descriptor v : vertices(annulus)) EXPECT_EQ(uv[v], Point_2(-7, -7));
}

TEST(CgalParameterizer, BadCornersAndShortOrNonTriangleBorders)
{
  Mesh mesh = cgal_mesh("nefertiti.off");
  auto uv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(-7, -7)).first;
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  const std::vector<vertex_descriptor> c = selection_corners("square_corners.selection.txt");
  vertex_descriptor inner = Mesh::null_vertex();
  for(vertex_descriptor v : vertices(mesh))
    if(!is_border(v, mesh)) inner = v;

  Parameterizer inner_corner(c[0], c[1], inner, c[3]);
  EXPECT_EQ(SMP::parameterize(mesh, inner_corner, bhd, uv), SMP::ERROR_NON_CONVEX_BORDER);
  EXPECT_EQ(inner_corner.status().code, diffuv::Status_code::corner_not_on_border);
  Parameterizer twice(c[0], c[1], c[1], c[3]);
  EXPECT_EQ(SMP::parameterize(mesh, twice, bhd, uv), SMP::ERROR_NON_CONVEX_BORDER);
  EXPECT_EQ(twice.status().code, diffuv::Status_code::corner_duplicated);
  Parameterizer not_a_vertex(c[0], c[1], c[2], vertex_descriptor(Mesh::size_type(num_vertices(mesh) + 10)));
  EXPECT_EQ(SMP::parameterize(mesh, not_a_vertex, bhd, uv), SMP::ERROR_NON_CONVEX_BORDER);
  EXPECT_EQ(not_a_vertex.status().code, diffuv::Status_code::corner_not_on_border);
  for(vertex_descriptor v : vertices(mesh)) EXPECT_EQ(uv[v], Point_2(-7, -7));

  // One triangle: three border vertices.
  Mesh triangle;
  triangle.add_face(triangle.add_vertex(Point_3(0, 0, 0)), triangle.add_vertex(Point_3(1, 0, 0)),
                    triangle.add_vertex(Point_3(0, 1, 0)));
  auto tuv = triangle.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  Parameterizer automatic;
  EXPECT_EQ(SMP::parameterize(triangle, automatic, PMP::longest_border(triangle).first, tuv), SMP::ERROR_BORDER_TOO_SHORT);

  // Quads.
  Mesh quads;
  std::vector<vertex_descriptor> q;
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i) q.push_back(quads.add_vertex(Point_3(i, j, 0)));
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 2; ++i) quads.add_face(q[3 * j + i], q[3 * j + i + 1], q[3 * j + i + 4], q[3 * j + i + 3]);
  auto quv = quads.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  EXPECT_EQ(SMP::parameterize(quads, automatic, PMP::longest_border(quads).first, quv), SMP::ERROR_NON_TRIANGULAR_MESH);
  EXPECT_EQ(automatic.status().code, diffuv::Status_code::not_triangle_mesh);
}

TEST(CgalParameterizer, CornerListsOfAnotherLengthThanFourAreReported)
{
  // A selection of three corners (or five, or none) given as a list: the
  // count is reported, nothing is read past the list, nothing is written.
  Mesh mesh = cgal_mesh("nefertiti.off");
  auto uv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(-7, -7)).first;
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  const std::vector<vertex_descriptor> c = selection_corners("square_corners.selection.txt");
  ASSERT_EQ(c.size(), 4u);
  vertex_descriptor fifth = Mesh::null_vertex();
  for(vertex_descriptor v : vertices(mesh))
    if(is_border(v, mesh) && std::find(c.begin(), c.end(), v) == c.end()) fifth = v;
  ASSERT_NE(fifth, Mesh::null_vertex());

  for(const std::vector<vertex_descriptor>& corners :
      {std::vector<vertex_descriptor>{c[0], c[1], c[2]}, std::vector<vertex_descriptor>{},
       std::vector<vertex_descriptor>{c[0], c[1], c[2], c[3], fifth}}) {
    Parameterizer listed(corners);
    EXPECT_TRUE(listed.corners_given());
    EXPECT_EQ(SMP::parameterize(mesh, listed, bhd, uv), SMP::ERROR_NON_CONVEX_BORDER);
    EXPECT_EQ(listed.status().code, diffuv::Status_code::corner_count);
    EXPECT_EQ(listed.status().what(),
              "exactly four corner vertices are needed (" + std::to_string(corners.size()) + " given)");
    EXPECT_TRUE(listed.corners().empty());
  }
  for(vertex_descriptor v : vertices(mesh)) EXPECT_EQ(uv[v], Point_2(-7, -7));

  // Four listed: the same map as the four corners given one by one.
  Parameterizer listed(c), one_by_one(c[0], c[1], c[2], c[3]);
  ASSERT_EQ(SMP::parameterize(mesh, listed, bhd, uv), SMP::OK) << listed.status().what();
  std::vector<Point_2> first;
  for(vertex_descriptor v : vertices(mesh)) first.push_back(uv[v]);
  ASSERT_EQ(SMP::parameterize(mesh, one_by_one, bhd, uv), SMP::OK);
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(mesh)) EXPECT_EQ(uv[v], first[i++]);
  EXPECT_EQ(listed.corners(), one_by_one.corners());
}

TEST(CgalParameterizer, ErrorCodesAndMessages)
{
  EXPECT_EQ(diffuv::to_cgal_error_code(diffuv::Status_code::ok), SMP::OK);
  EXPECT_EQ(diffuv::to_cgal_error_code(diffuv::Status_code::not_a_disc), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_EQ(diffuv::to_cgal_error_code(diffuv::Status_code::unreachable_vertices), SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM);
  // Our sentences, one per code (CGAL 5.5's get_error_message() is off by one from code 4 on).
  std::set<std::string> sentences;
  for(int code = SMP::OK; code <= SMP::ERROR_WRONG_PARAMETER; ++code)
    sentences.insert(diffuv::cgal_error_message(SMP::Error_code(code)));
  EXPECT_EQ(sentences.size(), std::size_t(SMP::ERROR_WRONG_PARAMETER) + 1);
  EXPECT_STREQ(diffuv::cgal_error_message(SMP::ERROR_BORDER_TOO_SHORT),
               "This border parameterization requires a longer border");
}


} // namespace
