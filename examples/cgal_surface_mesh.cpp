// diffuv's parameterizer through CGAL's own entry point on a Surface_mesh:
// CGAL::Surface_mesh_parameterization::parameterize() with a
// diffuv::Diffusion_parameterizer_3 and automatic corners, the uv in a
// Surface_mesh property map, then the distortion measured.
//
// Usage: cgal_surface_mesh [disc-mesh.off]     Default: CGAL's mushroom.off.
//
// README.md shows the parts between the "// [includes]" and "// [parameterize]" marks
// (scripts/check_snippets.py, CTest 'snippets', keeps them equal).
#include <diffuv/metrics/distortion.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

// [includes]
#include <diffuv/cgal/Diffusion_parameterizer_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMP = CGAL::Surface_mesh_parameterization;
// [includes]

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
    std::cerr << "Usage: cgal_surface_mesh [disc-mesh.off]\n"
              << "(no mesh given, and the default " << default_mesh << " is not there)\n";
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : default_mesh;
  // [parameterize]
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || is_empty(mesh)) {
    std::cerr << "Error: cannot read " << file << std::endl;
    return EXIT_FAILURE;
  }
  // CGAL's convention: the longest border cycle gives the border halfedge (null on a closed mesh).
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  if(bhd == boost::graph_traits<Mesh>::null_halfedge()) {
    std::cerr << "Error: " << file << " has no border; cut it open first (see seam_mesh.cpp)" << std::endl;
    return EXIT_FAILURE;
  }

  auto uv = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  diffuv::Diffusion_parameterizer_3<Mesh> parameterizer; // automatic corners; (c0, c1, c2, c3) to give them
  const SMP::Error_code err = SMP::parameterize(mesh, parameterizer, bhd, uv);
  if(err != SMP::OK) { // diffuv's sentences: CGAL 5.5's get_error_message() is off by one
    std::cerr << "Error: " << diffuv::cgal_error_message(err) << " (" << parameterizer.status().what() << ")\n";
    return EXIT_FAILURE;
  }
  // [parameterize]

  const diffuv::Distortion_summary d = diffuv::measure_distortion(mesh, mesh.points(), faces(mesh), uv);
  std::cout << file << ": " << num_vertices(mesh) << " vertices mapped onto the unit square\n"
            << "flipped " << d.flipped << ", overlapping pairs " << d.overlapping_pairs << ", angle distortion mean "
            << d.angle_mean << " (1 = conformal), area distortion mean " << d.area_mean << std::endl;
  return d.injective() ? EXIT_SUCCESS : EXIT_FAILURE;
}
