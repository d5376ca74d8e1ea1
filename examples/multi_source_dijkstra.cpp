// Distance of every vertex of a mesh to its boundary: one multi-source
// Dijkstra run with all border vertices as sources, over CGAL's BGL view of a
// Surface_mesh, with edge lengths computed once.
//
// Usage: multi_source_dijkstra [mesh.off]   (default: CGAL's mushroom.off)
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/multi_source_dijkstra.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

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
    std::cerr << "Usage: multi_source_dijkstra [mesh.off]\n"
              << "(no mesh given, and the default " << default_mesh << " is not there)\n";
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : default_mesh;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || is_empty(mesh)) {
    std::cerr << "Error: cannot read " << file << std::endl;
    return EXIT_FAILURE;
  }

  std::vector<vertex_descriptor> border;
  for(vertex_descriptor v : vertices(mesh))
    if(is_border(v, mesh)) border.push_back(v);

  // The distance map is a Surface_mesh property; any ReadWritePropertyMap works.
  auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance", 0.).first;
  const diffuv::Status status =
      diffuv::multi_source_dijkstra(mesh, border, diffuv::edge_length_map(mesh), distance);
  if(!status) { // empty_source_range on a closed mesh
    std::cerr << "Error: " << status.what() << std::endl;
    return EXIT_FAILURE;
  }

  vertex_descriptor farthest = *vertices(mesh).begin();
  for(vertex_descriptor v : vertices(mesh))
    if(distance[v] > distance[farthest]) farthest = v;
  std::cout << border.size() << " border vertices; the farthest vertex from the border is " << farthest
            << " at " << distance[farthest] << std::endl;
  return EXIT_SUCCESS;
}
