// Measures how much a diffuv map distorts a disc mesh: flipped and
// overlapping triangles, angle and area distortion, Sander's stretch.
//
// Usage: distortion [disc_mesh.off]   (default: CGAL's three_peaks.off)
#include <diffuv/io/read_mesh.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <fstream>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// The files read when none are given: CGAL's, from the data folder that
// examples/CMakeLists.txt names (DIFFUV_DEFAULT_DATA_DIR) in diffuv's build;
// a copy of this file built elsewhere looks for them in the current folder
// (CGAL's meshes: data/meshes/ in libcgal-demo's
// /usr/share/doc/libcgal-dev/data.tar.gz).
#ifdef DIFFUV_DEFAULT_DATA_DIR
static const char* const default_mesh = DIFFUV_DEFAULT_DATA_DIR "/meshes/three_peaks.off";
#else
static const char* const default_mesh = "three_peaks.off";
#endif

int main(int argc, char** argv)
{
  if(argc < 2 && !std::ifstream(default_mesh)) {
    std::cerr << "Usage: distortion [disc_mesh.off]\n"
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
  diffuv::Uv_atlas<Mesh> atlas(mesh);
  const diffuv::Status status = diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas);
  if(!status) {
    std::cerr << "Error: " << status.what() << std::endl;
    return EXIT_FAILURE;
  }

  std::vector<diffuv::Triangle_distortion> per_face;
  const diffuv::Distortion_summary d =
      diffuv::measure_distortion(mesh, mesh.points(), faces(mesh), atlas.chart_uv_map(0), &per_face);

  std::cout << file << ": " << d.faces << " faces\n"
            << "  flipped " << d.flipped << ", degenerate " << d.degenerate << ", overlapping pairs "
            << d.overlapping_pairs << (d.injective() ? " (injective)" : " (not injective)") << "\n"
            << "  angle distortion mean " << d.angle_mean << ", max " << d.angle_max << "\n"
            << "  area distortion mean " << d.area_mean << ", max " << d.area_max << "\n"
            << "  stretch L2 " << d.stretch_l2 << ", Linf " << d.stretch_linf << std::endl;
  return EXIT_SUCCESS;
}
