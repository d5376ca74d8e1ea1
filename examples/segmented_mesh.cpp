// A closed mesh parameterized patch by patch: automatic disc patches (or
// region labels), canonical sides from the neighbouring regions, one chart
// per patch.
//
// Usage: segmented_mesh [mesh.off [labels.txt]]   (default: CGAL's cow.off, automatic patches)
#include <diffuv/io/read_labels.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/parameterization/diffusion_patches.h>

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
static const char* const default_mesh = DIFFUV_DEFAULT_DATA_DIR "/meshes/cow.off";
#else
static const char* const default_mesh = "cow.off";
#endif

int main(int argc, char** argv)
{
  if(argc < 2 && !std::ifstream(default_mesh)) {
    std::cerr << "Usage: segmented_mesh [mesh.off [labels.txt]]\n"
              << "(no mesh given, and the default " << default_mesh << " is not there)\n";
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : default_mesh;
  Mesh mesh;
  std::vector<int> labels; // empty: automatic patches
  try {
    const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(file, mesh);
    if(argc > 2)
      labels = diffuv::face_labels_of_mesh(diffuv::read_face_labels(argv[2], report.faces_in_file), report);
  } catch(const diffuv::Error& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  diffuv::Segmentation<Mesh> seg;
  diffuv::Patching_report patching;
  const diffuv::Status status = diffuv::diffusion_patches(mesh, labels, seg, {}, &patching);
  if(!status) {
    std::cerr << "Error: " << status.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << seg.number_of_patches() << " disc patches (" << (patching.automatic ? "automatic" : "from labels")
            << ", " << patching.caps_split << " caps split)\n";

  diffuv::Uv_atlas<Mesh> atlas(mesh);
  const auto results = diffuv::parameterize_patches(mesh, mesh.points(), seg, atlas);
  std::size_t mapped = 0;
  for(std::size_t p = 0; p < results.size(); ++p) {
    if(!results[p].status) {
      std::cerr << "patch " << p << ": " << results[p].status.what() << std::endl;
      continue;
    }
    ++mapped;
  }
  // A vertex on a patch border has one (u,v) per patch it belongs to.
  const Mesh::Vertex_index v(0);
  auto entries = atlas.entries(v);
  std::cout << mapped << " charts; vertex " << v << " is in " << (entries.second - entries.first) << " of them:";
  for(auto e = entries.first; e != entries.second; ++e)
    std::cout << " patch " << e->chart << " at (" << atlas.uv(e->chart, e->local) << ")";
  std::cout << std::endl;
  return mapped == results.size() ? EXIT_SUCCESS : EXIT_FAILURE;
}
