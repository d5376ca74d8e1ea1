// Two tessellations of one surface put in correspondence through
// (region, u, v): CGAL's cow and an isotropically remeshed copy of it, moved
// away and rotated so that 3D proximity could not help. A's regions are
// automatic disc patches; B gets them by nearest face before it is moved (as
// a person would transfer or paint them: with ragged borders that the
// correspondence cleans). Then B's per-vertex data (here its height) is pulled
// onto A, and the error is measured against the truth (the closest point).
//
// Usage: correspondence [mesh.off]   (default: CGAL's cow.off)
#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/correspondence/transfer.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/layout/disc_patches.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// The files read when none are given: CGAL's, from the data folder that
// examples/CMakeLists.txt names (DIFFUV_DEFAULT_DATA_DIR) in diffuv's build;
// a copy of this file built elsewhere looks for them in the current folder
// (CGAL's meshes: data/meshes/ in libcgal-demo's
// /usr/share/doc/libcgal-dev/data.tar.gz).
#ifdef DIFFUV_DEFAULT_DATA_DIR
static const char* const default_mesh = DIFFUV_DEFAULT_DATA_DIR "/meshes/cow.off";
#else
static const char* const default_mesh = "cow.off";
#endif

int main(int argc, char** argv)
{
  if(argc < 2 && !std::ifstream(default_mesh)) {
    std::cerr << "Usage: correspondence [mesh.off]\n"
              << "(no mesh given, and the default " << default_mesh << " is not there)\n";
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : default_mesh;
  Mesh a;
  try {
    diffuv::read_triangle_mesh(file, a);
  } catch(const diffuv::Error& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  // A's regions: automatic disc patches, as `diffuv segment` writes them.
  diffuv::Segmentation<Mesh> seg;
  const diffuv::Status segmented = diffuv::disc_patches(a, a.points(), std::vector<int>(), seg);
  if(!segmented) {
    std::cerr << "Error: " << segmented.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<int> labels_a(num_faces(a));
  for(auto f : faces(a)) labels_a[f.idx()] = static_cast<int>(seg.face_patch[f.idx()]);

  // B: a remeshed copy (edges 1.3x longer on average), labelled by nearest face, then moved.
  Mesh b = a;
  double mean_edge = 0;
  for(auto e : edges(a)) mean_edge += PMP::edge_length(e, a);
  mean_edge /= num_edges(a);
  PMP::isotropic_remeshing(faces(b), 1.3 * mean_edge, b, CGAL::parameters::number_of_iterations(3));
  b.collect_garbage();
  const std::vector<int> labels_b = diffuv::nearest_face_labels(a, labels_a, b);
  const CGAL::Aff_transformation_3<Kernel> move(0.0, -2.0, 0.0, 5.0, 2.0, 0.0, 0.0, -1.0, 0.0, 0.0, 2.0, 3.0);
  PMP::transform(move, b); // rotated a quarter turn, scaled by 2, translated

  // Both atlases; B takes its corners where A has them (by the regions around them).
  diffuv::Labelled_atlas<Mesh> atlas_a(a), atlas_b(b);
  diffuv::Status status = diffuv::build_labelled_atlas(a, a.points(), labels_a, atlas_a);
  if(!status) {
    std::cerr << "Error: mesh A: " << status.what() << std::endl;
    return EXIT_FAILURE;
  }
  const auto follow_a = diffuv::atlas_to_follow(atlas_a);
  status = diffuv::build_labelled_atlas(b, b.points(), labels_b, follow_a, atlas_b);
  if(!status) {
    std::cerr << "Error: mesh B: " << status.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "A: " << num_vertices(a) << " vertices, " << atlas_a.segmentation.number_of_patches() << " patches\n"
            << "B: " << num_vertices(b) << " vertices, " << atlas_b.segmentation.number_of_patches()
            << " patches; labels cleaned: " << atlas_b.cleaning.changed_faces() << " faces\n";

  const diffuv::Atlas_correspondence<Mesh, Mesh> correspondence(atlas_a, atlas_b);
  const auto& match = correspondence.report();
  std::cout << "matched " << match.matched_patches << " patches; labels only in A: " << match.labels_only_in_a.size()
            << ", only in B: " << match.labels_only_in_b.size() << '\n';
  if(match.matched_patches == 0) {
    std::cerr << "Error: no region matches" << std::endl;
    return EXIT_FAILURE;
  }
  const auto images = correspondence.map_vertices();

  // B's height (its z after the move) carried onto A's vertices.
  std::vector<double> height(num_vertices(b));
  for(auto v : vertices(b)) height[v.idx()] = b.point(v).z();
  const std::vector<double> height_on_a = diffuv::transfer_vertex_values(
      b, images, boost::make_iterator_property_map(height.begin(), get(boost::vertex_index, b)),
      std::numeric_limits<double>::quiet_NaN());

  // Error: distance from each image to the truth (A's vertex moved like B,
  // then its closest point on B), over sqrt(area of B). Euclidean here; the
  // benchmark measures geodesic distances.
  CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>> tree(
      faces(b).first, faces(b).second, b);
  tree.accelerate_distance_queries();
  const double scale = std::sqrt(PMP::area(b));
  std::vector<double> errors;
  std::size_t unmapped = 0;
  double height_error = 0;
  for(auto v : vertices(a)) {
    const auto& image = images[v.idx()];
    if(!image.mapped()) { ++unmapped; continue; }
    const auto truth = tree.closest_point(move.transform(a.point(v)));
    errors.push_back(std::sqrt(CGAL::squared_distance(image.point, truth)) / scale);
    height_error = (std::max)(height_error, std::abs(height_on_a[v.idx()] - image.point.z()));
  }
  if(errors.empty()) {
    std::cerr << "Error: no vertex was mapped" << std::endl;
    return EXIT_FAILURE;
  }
  std::sort(errors.begin(), errors.end());
  double mean = 0;
  for(double e : errors) mean += e;
  mean /= errors.size();
  const double within = 100. * double(std::upper_bound(errors.begin(), errors.end(), 0.05) - errors.begin()) /
                        double(num_vertices(a));
  std::cout << "mapped " << errors.size() << " of " << num_vertices(a) << " vertices (" << unmapped
            << " unmapped)\nerror / sqrt(area): mean " << mean << ", median " << errors[errors.size() / 2]
            << ", p95 " << errors[errors.size() * 95 / 100] << ", max " << errors.back() << "; " << within
            << "% within 0.05\nheight carried to A: largest difference from the image's own height " << height_error
            << '\n';
  return EXIT_SUCCESS;
}
