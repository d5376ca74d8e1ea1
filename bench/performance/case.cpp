// diffuv performance bench: the meshes. CGAL's mesh, its given patches
// (disc_patches()), and its Loop-subdivided copies with the parent's patches.
#include "performance/performance_bench.h"

#include <diffuv/core/error.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/region_sides.h>

#include <CGAL/subdivision_method_3.h>

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace diffuv_bench {

namespace {

// One Loop subdivision step; `labels` (by face index) are carried from each
// parent face to its four children. The children of a face are the face
// itself (CGAL's Euler operations keep it, with its index) and the faces
// reached from it across edges joining two new (edge-midpoint) vertices:
// such an edge lies inside one parent face. Checked: every face is reached,
// each parent face has exactly four children.
std::vector<int> loop_subdivide(Mesh& m, const std::vector<int>& labels)
{
  const std::size_t v0 = m.number_of_vertices(), f0 = m.number_of_faces();
  if(m.has_garbage()) m.collect_garbage();
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
  if(m.number_of_faces() != 4 * f0) throw std::runtime_error("Loop subdivision: face count is not 4x");
  constexpr int unset = std::numeric_limits<int>::min();
  std::vector<int> out(m.number_of_faces(), unset);
  std::vector<std::uint32_t> group(m.number_of_faces(), 0), group_size(f0, 0);
  std::vector<face_descriptor> queue;
  for(std::size_t i = 0; i < f0; ++i) {
    const face_descriptor f(static_cast<Mesh::size_type>(i));
    out[i] = labels[i];
    group[i] = static_cast<std::uint32_t>(i);
    ++group_size[i];
    queue.assign(1, f);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(queue[q]), m)) {
        if(m.source(h).idx() < v0 || m.target(h).idx() < v0) continue;
        const halfedge_descriptor o = m.opposite(h);
        if(m.is_border(o)) continue;
        const face_descriptor g = m.face(o);
        if(out[g.idx()] != unset) continue;
        out[g.idx()] = labels[i];
        group[g.idx()] = static_cast<std::uint32_t>(i);
        ++group_size[i];
        queue.push_back(g);
      }
  }
  for(std::size_t i = 0; i < out.size(); ++i)
    if(out[i] == unset) throw std::runtime_error("Loop subdivision: a face with no parent");
  for(std::size_t i = 0; i < f0; ++i)
    if(group_size[i] != 4) throw std::runtime_error("Loop subdivision: a parent face without four children");
  return out;
}

} // namespace

Case make_case(const std::string& name_or_path, int level)
{
  const auto t0 = Clock::now();
  Case c;
  c.name = read_named_mesh(name_or_path, c.mesh);
  // The given patches of the base mesh: automatic (closed meshes) or the whole disc.
  Seg base;
  const diffuv::Status status = diffuv::disc_patches(c.mesh, c.mesh.points(), std::vector<int>{}, base);
  if(!status) throw std::runtime_error(c.name + ": disc_patches: " + status.what());
  if(level == 0) {
    c.seg = std::move(base);
    c.labels_from = "disc_patches";
  } else {
    std::vector<int> labels(c.mesh.number_of_faces());
    for(auto f : c.mesh.faces()) labels[f.idx()] = static_cast<int>(base.face_patch[f.idx()]);
    for(int l = 0; l < level; ++l) labels = loop_subdivide(c.mesh, labels);
    c.seg = diffuv::patches_from_labels(c.mesh, c.mesh.points(), labels);
    if(c.seg.number_of_patches() != base.number_of_patches())
      throw std::runtime_error(c.name + ": the subdivided patches differ in number from the parent's");
    c.labels_from = "parent patches";
  }
  const std::size_t P = c.seg.number_of_patches();
  c.sides.resize(P);
  c.patch_ok.assign(P, false);
  for(std::size_t p = 0; p < P; ++p) {
    diffuv::Status s = diffuv::check_patch_disc(c.mesh, c.seg, p);
    if(s) s = diffuv::region_sides(c.mesh, c.mesh.points(), c.seg, p, c.sides[p]);
    c.patch_ok[p] = static_cast<bool>(s);
    if(c.patch_ok[p] && (!c.patch_ok[c.largest_patch] ||
                         c.seg.patch_faces[p].size() > c.seg.patch_faces[c.largest_patch].size()))
      c.largest_patch = p;
  }
  c.setup_seconds = ms_since(t0) / 1000.;
  return c;
}

} // namespace diffuv_bench
