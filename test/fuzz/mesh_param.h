// libFuzzer target: the whole of `diffuv param` on a small mesh, through the
// library as src/cli (read_input, make_patches, parameterize_by_patches) does
// it: read_triangle_mesh(), the regions painted in the file
// (read_painted_labels() then face_labels_of_mesh()), disc_patches() and
// parameterize_patches() with default options (fast marching distances, folds
// repaired).
//
// The format comes from the content (see mesh_extension()): PLY, OFF, STL
// (ASCII or binary) or OBJ. Checked on success: the report matches the mesh,
// which is a valid triangle mesh; every face is in one patch; every mapped
// patch has finite (u,v).
#ifndef DIFFUV_FUZZ_MESH_PARAM_H
#define DIFFUV_FUZZ_MESH_PARAM_H

#include "fuzz_input.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/core/error.h>
#include <diffuv/io/painted_labels.h>
#include <diffuv/io/read_labels.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/layout/disc_patches.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace diffuv_fuzz {

/// Runs the target on one input.
inline void mesh_param(const std::uint8_t* data, std::size_t size)
{
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  using diffuv_fuzz::check;
  const std::string path = diffuv_fuzz::write_input(data, size, diffuv_fuzz::mesh_extension(data, size));

  Mesh mesh;
  diffuv::Mesh_read_report report;
  std::vector<int> face_labels;
  try {
    report = diffuv::read_triangle_mesh(path, mesh);
    const diffuv::Painted_labels painted = diffuv::read_painted_labels(path);
    if(painted.source != diffuv::Label_source::none)
      face_labels = diffuv::face_labels_of_mesh(painted.polygon_labels, report);
  } catch(const diffuv::Error& e) {
    diffuv_fuzz::note(e.what());
    return; // a documented rejection (Input_error; Error for labels that do not fit the mesh)
  }
  diffuv_fuzz::note(path + ": " + std::to_string(report.vertices) + " vertices, " + std::to_string(report.faces) +
                    " faces, " + (face_labels.empty() ? "no labels" : "painted labels"));
  check(report.vertices + report.repair.vertex_copies == num_vertices(mesh),
        "the file's points and the repair's copies are not the mesh's vertices");
  // The repair moves no point: a copy sits on its point, a merged point on the one it merged into.
  for(Mesh::Vertex_index v : vertices(mesh)) {
    check(report.point_of(v.idx()) < report.vertices, "a vertex copies no point of the file");
    check(mesh.point(v) == mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(report.point_of(v.idx())))),
          "a copy of a point is not where the point is");
  }
  for(std::size_t i = 0; i < report.vertices; ++i)
    check(mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(report.vertex_of(i)))) ==
              mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(i))),
          "a point merged into one at another position");
  check(report.faces == num_faces(mesh), "report.faces differs from the mesh");
  check(report.file_face.size() == report.faces, "report.file_face has not one entry per face");
  for(std::size_t j : report.file_face) check(j < report.faces_in_file, "report.file_face out of range");
  check(CGAL::is_triangle_mesh(mesh), "read_triangle_mesh made a face that is not a triangle");
  check(mesh.is_valid(false), "read_triangle_mesh made an invalid Surface_mesh");

  diffuv::Segmentation<Mesh> seg;
  diffuv::Patching_report patching;
  diffuv::disc_patches(mesh, mesh.points(), face_labels, seg, diffuv::Patching_options(), &patching);
  check(seg.face_patch.size() == num_faces(mesh), "the segmentation has not one patch per face");
  for(std::size_t p : seg.face_patch) check(p < seg.number_of_patches(), "a face in no patch");

  diffuv::Uv_atlas<Mesh> atlas(mesh);
  const auto results = diffuv::parameterize_patches(mesh, mesh.points(), seg, atlas);
  check(results.size() == seg.number_of_patches(), "parameterize_patches returned another number of results");
  std::size_t mapped = 0;
  for(const auto& r : results) {
    if(!r.status) {
      diffuv_fuzz::note("a patch failed: " + r.status.what());
      continue;
    }
    ++mapped;
    for(const auto& uv : atlas.chart(r.chart).uv)
      check(std::isfinite(uv.x()) && std::isfinite(uv.y()), "a mapped patch has a NaN or infinite (u,v)");
  }
  diffuv_fuzz::note(std::to_string(mapped) + " of " + std::to_string(results.size()) + " patches mapped");
}

} // namespace diffuv_fuzz

#endif // DIFFUV_FUZZ_MESH_PARAM_H
