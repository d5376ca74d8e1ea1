// Parameterizes a disc mesh onto the unit square with four given corners,
// as CGAL's square_border_parameterizer example does, and writes an OBJ.
//
// Usage: parameterize_disc [mesh.off] [corners.selection.txt]
// Default: CGAL's nefertiti.off with square_corners.selection.txt.
#include <diffuv/io/read_mesh.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/output/write_obj.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <fstream>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

// The files read when none are given: CGAL's, from the data folder that
// examples/CMakeLists.txt names (DIFFUV_DEFAULT_DATA_DIR) in diffuv's build;
// a copy of this file built elsewhere looks for them in the current folder
// (CGAL's meshes: data/meshes/ in libcgal-demo's
// /usr/share/doc/libcgal-dev/data.tar.gz).
#ifdef DIFFUV_DEFAULT_DATA_DIR
static const char* const default_mesh = DIFFUV_DEFAULT_DATA_DIR "/meshes/nefertiti.off";
static const char* const default_selection = DIFFUV_DEFAULT_DATA_DIR "/selections/square_corners.selection.txt";
#else
static const char* const default_mesh = "nefertiti.off";
static const char* const default_selection = "square_corners.selection.txt";
#endif

int main(int argc, char** argv)
{
  const std::string mesh_file = argc > 1 ? argv[1] : default_mesh;
  const std::string corner_file = argc > 2 ? argv[2] : default_selection;
  const char* const missing = argc < 2 && !std::ifstream(default_mesh)        ? default_mesh
                              : argc < 3 && !std::ifstream(default_selection) ? default_selection
                                                                              : nullptr;
  if(missing) {
    std::cerr << "Usage: parameterize_disc [mesh.off [corners.selection.txt]]\n"
              << "(the default " << missing << " is not there)\n";
    return EXIT_FAILURE;
  }

  Mesh mesh;
  std::vector<vertex_descriptor> corners;
  try {
    diffuv::read_triangle_mesh(mesh_file, mesh);
    corners = diffuv::selection_vertices(mesh, diffuv::read_selection_file(corner_file), corner_file);
  } catch(const diffuv::Input_error& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  // corners[0] goes to (0,0); the others follow counter-clockwise along the border.
  diffuv::Uv_atlas<Mesh> atlas(mesh);
  diffuv::Four_sides<vertex_descriptor> sides;
  diffuv::Disc_parameterization_report<Mesh> disc_report;
  const diffuv::Status status = diffuv::parameterize_disc(mesh, mesh.points(), corners, atlas, {}, &disc_report);
  sides = disc_report.sides;
  if(!status) {
    std::cerr << "Error: " << status.what() << std::endl;
    return EXIT_FAILURE;
  }

  auto uv = atlas.vertex_uv_map();
  for(vertex_descriptor c : sides.corners)
    std::cout << "corner " << c << " -> (" << get(uv, c) << ")\n";

  try {
    diffuv::write_obj("parameterize_disc.obj", mesh, mesh.points(), atlas.corner_uv_map());
  } catch(const diffuv::Output_error& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote parameterize_disc.obj (" << num_vertices(mesh) << " vertices)" << std::endl;
  return EXIT_SUCCESS;
}
