// The uv-map both ways (paper, section 2.5): vertex -> (u,v) from the linear
// array, (u,v) -> nearest vertex from the kd-tree, and (u,v) -> a point on the
// surface (triangle + barycentric coordinates).
//
// Usage: uv_lookup [disc_mesh.off]   (default: CGAL's mushroom.off)
#include <diffuv/io/read_mesh.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <fstream>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Atlas = diffuv::Uv_atlas<Mesh>;

// The files read when none are given: CGAL's, from the data folder that
// examples/CMakeLists.txt names (DIFFUV_DEFAULT_DATA_DIR) in diffuv's build;
// a copy of this file built elsewhere looks for them in the current folder
// (CGAL's meshes: data/meshes/ in libcgal-demo's
// /usr/share/doc/libcgal-dev/data.tar.gz).
#ifdef DIFFUV_DEFAULT_DATA_DIR
static const char* const default_mesh = DIFFUV_DEFAULT_DATA_DIR "/meshes/mushroom.off";
#else
static const char* const default_mesh = "mushroom.off";
#endif

int main(int argc, char** argv)
{
  if(argc < 2 && !std::ifstream(default_mesh)) {
    std::cerr << "Usage: uv_lookup [disc_mesh.off]\n"
              << "(no mesh given, and the default " << default_mesh << " is not there)\n";
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : default_mesh;
  Mesh mesh;
  try {
    diffuv::read_triangle_mesh(file, mesh);
  } catch(const diffuv::Input_error& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  Atlas atlas(mesh);
  const diffuv::Status status = diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas); // automatic corners
  if(!status) {
    std::cerr << "Error: " << status.what() << std::endl;
    return EXIT_FAILURE;
  }

  // vertex -> (u,v): O(1)
  const Mesh::Vertex_index v(42);
  std::cout << "vertex " << v << " has (u,v) = (" << get(atlas.vertex_uv_map(), v) << ")\n";

  // (u,v) -> nearest vertex: O(log n) in chart 0's kd-tree
  const Kernel::Point_2 centre(0.5, 0.5);
  const Atlas::Local_index nearest = atlas.nearest_vertex(0, centre);
  std::cout << "nearest vertex to (0.5, 0.5): " << atlas.chart(0).vertices[nearest] << " at ("
            << atlas.uv(0, nearest) << ")\n";

  // (u,v) -> point on the surface
  const auto location = atlas.locate(0, centre);
  if(!location.inside) {
    std::cerr << "Error: (0.5, 0.5) is in no triangle of the chart" << std::endl;
    return EXIT_FAILURE;
  }
  const auto& w = location.location.second;
  std::cout << "(0.5, 0.5) lies in face " << location.location.first << " with barycentric coordinates (" << w[0]
            << ", " << w[1] << ", " << w[2] << "), at 3D point (" << atlas.point(location) << ")" << std::endl;
  return EXIT_SUCCESS;
}
