// CGAL's square_border_parameterizer example with diffuv's parameterizer:
// a Polyhedron_3, four corners from a selection file (or chosen
// automatically), CGAL::Surface_mesh_parameterization::parameterize(), and the
// result written as CGAL does (the flattened mesh in OFF) and as a mesh with
// texture coordinates (OBJ).
//
// Usage: cgal_parameterize [mesh.off] [corners.selection.txt | auto]
// Default: CGAL's nefertiti.off with square_corners.selection.txt.
// Writes cgal_parameterize.off (x = u, y = v) and cgal_parameterize.obj.
#include <diffuv/cgal/Diffusion_parameterizer_3.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/output/write_obj.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Unique_hash_map.h>

#include <boost/property_map/function_property_map.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>                     Kernel;
typedef Kernel::Point_2                                    Point_2;
typedef CGAL::Polyhedron_3<Kernel>                         PolyMesh;

typedef boost::graph_traits<PolyMesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<PolyMesh>::vertex_descriptor   vertex_descriptor;

typedef CGAL::Unique_hash_map<vertex_descriptor, Point_2>  UV_uhm;
typedef boost::associative_property_map<UV_uhm>            UV_pmap;

namespace SMP = CGAL::Surface_mesh_parameterization;

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
    std::cerr << "Usage: cgal_parameterize [mesh.off [corners.selection.txt | auto]]\n"
              << "(the default " << missing << " is not there)\n";
    return EXIT_FAILURE;
  }

  std::ifstream in(mesh_file);
  PolyMesh sm;
  if(!in || !(in >> sm) || faces(sm).empty()) {
    std::cerr << "Error: cannot read a polygon mesh from " << mesh_file << std::endl;
    return EXIT_FAILURE;
  }

  // A border halfedge: parameterize() maps its connected component.
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  if(bhd == halfedge_descriptor()) {
    std::cerr << "Error: " << mesh_file << " has no border (a closed mesh is not a disc;"
              << " cut it open with a CGAL::Seam_mesh, see seam_mesh.cpp)" << std::endl;
    return EXIT_FAILURE;
  }

  // The four corners: the first selected vertex goes to (0,0), the three
  // others follow counter-clockwise to (1,0), (1,1), (0,1).
  typedef diffuv::Diffusion_parameterizer_3<PolyMesh> Parameterizer;
  Parameterizer parameterizer; // automatic corners
  if(corner_file != "auto") {
    std::vector<vertex_descriptor> corners;
    try {
      corners = diffuv::selection_vertices(sm, diffuv::read_selection_file(corner_file), corner_file);
    } catch(const diffuv::Input_error& e) {
      std::cerr << "Error: " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
    parameterizer = Parameterizer(corners); // any other number than four: reported by parameterize()
  }

  // The 2D points of the uv parametrisation will be written into this map
  // (NaN for the vertices of other components: no texture coordinates).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  UV_uhm uv_uhm(Point_2(nan, nan));
  UV_pmap uv_map(uv_uhm);

  const SMP::Error_code err = SMP::parameterize(sm, parameterizer, bhd, uv_map);
  if(err != SMP::OK) {
    // diffuv::cgal_error_message(): CGAL 5.5's get_error_message() is off by one from code 4 on.
    std::cerr << "Error: " << diffuv::cgal_error_message(err) << " (" << parameterizer.status().what() << ")"
              << std::endl;
    return EXIT_FAILURE;
  }

  for(vertex_descriptor c : parameterizer.corners())
    std::cout << "corner at (" << get(uv_map, c) << ")\n";

  // As CGAL's example: the flattened component, in OFF.
  std::ofstream out("cgal_parameterize.off");
  SMP::IO::output_uvmap_to_off(sm, bhd, uv_map, out);
  if(!out) {
    std::cerr << "Error: cannot write cgal_parameterize.off" << std::endl;
    return EXIT_FAILURE;
  }

  // The mesh with its texture coordinates, in OBJ (the uv of a corner of a face
  // is the uv of its vertex here; a Seam_mesh has several per vertex).
  auto corner_uv = boost::make_function_property_map<halfedge_descriptor>(
      [&](halfedge_descriptor h) { return get(uv_map, target(h, sm)); });
  try {
    diffuv::write_obj("cgal_parameterize.obj", sm, get(CGAL::vertex_point, sm), corner_uv);
  } catch(const diffuv::Output_error& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote cgal_parameterize.off and cgal_parameterize.obj (" << num_vertices(sm) << " vertices)"
            << std::endl;
  return EXIT_SUCCESS;
}
