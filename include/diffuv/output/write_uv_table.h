// diffuv: the uv-map as a per-vertex table (CSV).
#ifndef DIFFUV_OUTPUT_WRITE_UV_TABLE_H
#define DIFFUV_OUTPUT_WRITE_UV_TABLE_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/internal/number_format.h>

#include <iomanip>
#include <string>

namespace diffuv {

/// Writes one CSV row `vertex,patch,u,v` per (vertex, chart) pair of `atlas`,
/// vertices in the order of the mesh (a vertex on a patch border has one row
/// per patch; a vertex in no chart has none), after the header line
/// `vertex,patch,u,v`. Vertex numbers are the mesh's vertex indices (0-based,
/// the order of the input file); u and v in the shortest form that reads back exactly.
///
/// \throws Output_error naming `path` if it cannot be written; an existing file is then left as it was
template <class TriangleMesh, class Kernel>
void write_uv_table(std::ostream& out, const Uv_atlas<TriangleMesh, Kernel>& atlas)
{
  out << "vertex,patch,u,v\n";
  auto vindex = get(boost::vertex_index, atlas.mesh());
  for(auto v : vertices(atlas.mesh())) {
    auto range = atlas.entries(v);
    for(auto e = range.first; e != range.second; ++e) {
      const auto& uv = atlas.uv(e->chart, e->local);
      out << get(vindex, v) << ',' << e->chart << ',';
      internal::write_shortest(out, CGAL::to_double(uv.x()));
      out << ',';
      internal::write_shortest(out, CGAL::to_double(uv.y()));
      out << '\n';
    }
  }
}

/// Same as above, into the file `path` through `Atomic_output_file`.
/// \throws Output_error naming `path` if it cannot be written; an existing file is then left as it was
template <class TriangleMesh, class Kernel>
void write_uv_table(const std::string& path, const Uv_atlas<TriangleMesh, Kernel>& atlas)
{
  Atomic_output_file file(path);
  write_uv_table(file.stream(), atlas);
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_OUTPUT_WRITE_UV_TABLE_H
