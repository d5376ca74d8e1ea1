// Helpers of the correspondence tests: automatic labels, shuffled and moved
// copies with the labels carried over, atlases (test_correspondence.cpp,
// test_layout_sub_patches.cpp).
#ifndef DIFFUV_TEST_CORRESPONDENCE_DATA_H
#define DIFFUV_TEST_CORRESPONDENCE_DATA_H


#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/labelled_atlas_pair.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/correspondence/transfer.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/parameterization/diffusion_patches.h>
#include <diffuv/layout/sub_patches.h>
#include <diffuv/patches/patches_from_labels.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <limits>
#include <map>
#include <set>
#include <vector>


namespace {

using diffuv_test::Mesh;
using diffuv_test::Point_3;
using Atlas = diffuv::Labelled_atlas<Mesh>;
using Correspondence = diffuv::Atlas_correspondence<Mesh, Mesh>;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;

// Labels of automatic disc patches (what `diffuv segment --layout voronoi`
// writes): region-sized, as a user paints them.
std::vector<int> segment_labels(const Mesh& m, std::size_t patches = 12)
{
  diffuv::Segmentation<Mesh> seg;
  diffuv::Patching_options options;
  options.layout = diffuv::Patch_layout::voronoi;
  options.automatic.patches = patches;
  EXPECT_TRUE(diffuv::disc_patches(m, m.points(), std::vector<int>(), seg, options).ok());
  std::vector<int> labels(num_faces(m));
  for(auto f : faces(m)) labels[f.idx()] = static_cast<int>(seg.face_patch[f.idx()]);
  return labels;
}

// A copy of `m` with vertices and faces in a random order, moved by a
// rotation, a scale and a translation: vertex_of[v] is the copy of vertex v,
// face_of[f] the copy of face f.
struct Moved_copy {
  Mesh mesh;
  std::vector<vertex_descriptor> vertex_of;
  std::vector<face_descriptor> face_of;
  double scale = 1.;
};

Moved_copy shuffled_moved_copy(const Mesh& m, unsigned seed, bool move)
{
  Moved_copy c;
  std::mt19937 rng(seed);
  std::vector<std::size_t> vperm(num_vertices(m)), fperm(num_faces(m));
  std::iota(vperm.begin(), vperm.end(), 0);
  std::iota(fperm.begin(), fperm.end(), 0);
  std::shuffle(vperm.begin(), vperm.end(), rng); // new vertex k is old vertex vperm[k]
  std::shuffle(fperm.begin(), fperm.end(), rng);
  c.scale = move ? 2.5 : 1.;
  const double a = 0.7, b = -1.1;  // rotation angles about z then x
  c.vertex_of.resize(num_vertices(m));
  for(std::size_t k = 0; k < vperm.size(); ++k) {
    const Point_3& p = m.point(vertex_descriptor(static_cast<Mesh::size_type>(vperm[k])));
    Point_3 q = p;
    if(move) {
      const double x1 = std::cos(a) * p.x() - std::sin(a) * p.y(), y1 = std::sin(a) * p.x() + std::cos(a) * p.y();
      const double y2 = std::cos(b) * y1 - std::sin(b) * p.z(), z2 = std::sin(b) * y1 + std::cos(b) * p.z();
      q = Point_3(c.scale * x1 + 3., c.scale * y2 - 7., c.scale * z2 + 1.);
    }
    c.vertex_of[vperm[k]] = c.mesh.add_vertex(q);
  }
  c.face_of.resize(num_faces(m));
  for(std::size_t k = 0; k < fperm.size(); ++k) {
    const face_descriptor f(static_cast<Mesh::size_type>(fperm[k]));
    std::vector<vertex_descriptor> fv;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) fv.push_back(c.vertex_of[v.idx()]);
    c.face_of[f.idx()] = c.mesh.add_face(fv);
  }
  return c;
}

std::vector<int> carry_labels(const std::vector<int>& labels, const Moved_copy& c)
{
  std::vector<int> out(labels.size());
  for(std::size_t f = 0; f < labels.size(); ++f) out[c.face_of[f].idx()] = labels[f];
  return out;
}

double sqrt_area(const Mesh& m) { return std::sqrt(CGAL::Polygon_mesh_processing::area(m)); }

// Build both atlases; the caller keeps them alive for the correspondence.
void build(const Mesh& m, const std::vector<int>& labels, Atlas& atlas,
           const diffuv::Labelled_atlas_options& options = diffuv::Labelled_atlas_options())
{
  ASSERT_TRUE(diffuv::build_labelled_atlas(m, m.points(), labels, atlas, options).ok());
}

// Vertex (label, part) set-up shared by several tests: cow, its automatic patches.
const Mesh& cow() { return diffuv_test::cgal_mesh("cow.off"); }

} // namespace

#endif // DIFFUV_TEST_CORRESPONDENCE_DATA_H
