// CGAL's seam_Polyhedron_3 example with diffuv's parameterizer: a mesh cut
// open along seam edges (a CGAL::Seam_mesh over a Polyhedron_3) is mapped
// onto the unit square with four automatic corners. A vertex on a seam is two
// vertices of the seam mesh, with two (u,v).
//
// Usage: seam_mesh [mesh.off] [seams.selection.txt]
// Default: CGAL's blob.off with blob.selection.txt (its third line lists the
// seam edges as pairs of vertex indices).
// Writes seam_mesh.off (the flattened mesh, x = u, y = v, as CGAL's example)
// and seam_mesh.obj (the mesh with per-corner texture coordinates).
//
// Our parameterizer needs a topological disc once cut. CGAL's own default,
// lion.off with lion.selection.txt, is not one: lion.off has holes, and
// after the cut four or five border loops remain, so parameterize() returns
// ERROR_NO_TOPOLOGICAL_DISC (CGAL's mean value coordinates, which this
// example replaces, map such a mesh with its holes inside the disc).
#include <diffuv/cgal/Diffusion_parameterizer_3.h>
#include <diffuv/output/write_obj.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Unique_hash_map.h>

#include <boost/property_map/function_property_map.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

typedef CGAL::Simple_cartesian<double>      Kernel;
typedef Kernel::Point_2                     Point_2;
typedef CGAL::Polyhedron_3<Kernel>          PolyMesh;

typedef boost::graph_traits<PolyMesh>::edge_descriptor SM_edge_descriptor;
typedef boost::graph_traits<PolyMesh>::halfedge_descriptor SM_halfedge_descriptor;
typedef boost::graph_traits<PolyMesh>::vertex_descriptor SM_vertex_descriptor;

typedef CGAL::Unique_hash_map<SM_halfedge_descriptor, Point_2> UV_uhm;
typedef CGAL::Unique_hash_map<SM_edge_descriptor, bool> Seam_edge_uhm;
typedef CGAL::Unique_hash_map<SM_vertex_descriptor, bool> Seam_vertex_uhm;

typedef boost::associative_property_map<UV_uhm> UV_pmap;
typedef boost::associative_property_map<Seam_edge_uhm> Seam_edge_pmap;
typedef boost::associative_property_map<Seam_vertex_uhm> Seam_vertex_pmap;

typedef CGAL::Seam_mesh<PolyMesh, Seam_edge_pmap, Seam_vertex_pmap> Mesh;

typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

// The files read when none are given: CGAL's, from the data folder that
// examples/CMakeLists.txt names (DIFFUV_DEFAULT_DATA_DIR) in diffuv's build;
// a copy of this file built elsewhere looks for them in the current folder
// (CGAL's meshes: data/meshes/ in libcgal-demo's
// /usr/share/doc/libcgal-dev/data.tar.gz).
#ifdef DIFFUV_DEFAULT_DATA_DIR
static const char* const default_mesh = DIFFUV_DEFAULT_DATA_DIR "/meshes/blob.off";
static const char* const default_selection = DIFFUV_DEFAULT_DATA_DIR "/selections/blob.selection.txt";
#else
static const char* const default_mesh = "blob.off";
static const char* const default_selection = "blob.selection.txt";
#endif

int main(int argc, char** argv)
{
  const std::string mesh_file = argc > 1 ? argv[1] : default_mesh;
  const std::string seam_file = argc > 2 ? argv[2] : default_selection;
  const char* const missing = argc < 2 && !std::ifstream(default_mesh)        ? default_mesh
                              : argc < 3 && !std::ifstream(default_selection) ? default_selection
                                                                              : nullptr;
  if(missing) {
    std::cerr << "Usage: seam_mesh [mesh.off [seams.selection.txt]]\n"
              << "(the default " << missing << " is not there)\n";
    return EXIT_FAILURE;
  }

  std::ifstream in_mesh(mesh_file);
  PolyMesh sm;
  if(!in_mesh || !(in_mesh >> sm) || faces(sm).empty()) {
    std::cerr << "Error: cannot read a polygon mesh from " << mesh_file << std::endl;
    return EXIT_FAILURE;
  }

  // Two property maps to store the seam edges and vertices
  Seam_edge_uhm seam_edge_uhm(false);
  Seam_edge_pmap seam_edge_pm(seam_edge_uhm);
  Seam_vertex_uhm seam_vertex_uhm(false);
  Seam_vertex_pmap seam_vertex_pm(seam_vertex_uhm);

  Mesh mesh(sm, seam_edge_pm, seam_vertex_pm);
  if(!std::ifstream(seam_file)) {
    std::cerr << "Error: cannot open " << seam_file << std::endl;
    return EXIT_FAILURE;
  }
  // Indices of the file are positions in vertices(sm); add_seams() checks them with at().
  SM_halfedge_descriptor smhd;
  try {
    smhd = mesh.add_seams(seam_file.c_str());
  } catch(const std::out_of_range&) {
    std::cerr << "Error: " << seam_file << ": a seam vertex index is out of range" << std::endl;
    return EXIT_FAILURE;
  }
  if(smhd == SM_halfedge_descriptor())
    std::cerr << "Warning: No seams in input" << std::endl;
  std::cout << mesh.number_of_seam_edges() << " seam edges: " << num_vertices(sm) << " vertices, "
            << num_vertices(mesh) << " in the seam mesh" << std::endl;

  // The 2D points of the uv parametrisation will be written into this map.
  // Note that this is a halfedge property map, and that uv values
  // are only stored for the canonical halfedges representing a vertex
  const double nan = std::numeric_limits<double>::quiet_NaN();
  UV_uhm uv_uhm(Point_2(nan, nan));
  UV_pmap uv_pm(uv_uhm);

  // A halfedge on the (possibly virtual) border
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  if(bhd == halfedge_descriptor()) {
    std::cerr << "Error: the mesh has no border once cut (a closed mesh needs seams)" << std::endl;
    return EXIT_FAILURE;
  }

  diffuv::Diffusion_parameterizer_3<Mesh> parameterizer; // automatic corners
  const SMP::Error_code err = SMP::parameterize(mesh, parameterizer, bhd, uv_pm);
  if(err != SMP::OK) {
    std::cerr << "Error: " << diffuv::cgal_error_message(err) << " (" << parameterizer.status().what() << ")"
              << std::endl;
    return EXIT_FAILURE;
  }

  std::ofstream out("seam_mesh.off");
  SMP::IO::output_uvmap_to_off(mesh, bhd, uv_pm, out);
  if(!out) {
    std::cerr << "Error: cannot write seam_mesh.off" << std::endl;
    return EXIT_FAILURE;
  }

  // The polyhedron itself, each corner of a face with the uv of its seam-mesh
  // vertex (the face's side of the seam): a vertex on a seam has two vt.
  auto corner_uv = boost::make_function_property_map<SM_halfedge_descriptor>(
      [&](SM_halfedge_descriptor h) { return get(uv_pm, target(halfedge_descriptor(h), mesh)); });
  try {
    diffuv::write_obj("seam_mesh.obj", sm, get(CGAL::vertex_point, sm), corner_uv);
  } catch(const diffuv::Output_error& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote seam_mesh.off and seam_mesh.obj" << std::endl;
  return EXIT_SUCCESS;
}
