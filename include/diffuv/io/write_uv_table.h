// diffuv: the uv-map as a per-vertex table (CSV).
#ifndef DIFFUV_IO_WRITE_UV_TABLE_H
#define DIFFUV_IO_WRITE_UV_TABLE_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/io/atomic_file.h>

#include <iomanip>
#include <string>

namespace diffuv {

/// Writes one CSV row `vertex,patch,u,v` per (vertex, chart) pair of `atlas`,
/// vertices in the order of the mesh (a vertex on a patch border has one row
/// per patch; a vertex in no chart has none), after the header line
/// `vertex,patch,u,v`. Vertex numbers are the mesh's vertex indices (0-based,
/// the order of the input file); u and v have 17 significant digits.
///
/// \throws Output_error naming `path` if it cannot be written; an existing file is then left as it was
template <class TriangleMesh, class Kernel>
void write_uv_table(const std::string& path, const Uv_atlas<TriangleMesh, Kernel>& atlas)
{
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << "vertex,patch,u,v\n" << std::setprecision(17);
  auto vindex = get(boost::vertex_index, atlas.mesh());
  for(auto v : vertices(atlas.mesh())) {
    auto range = atlas.entries(v);
    for(auto e = range.first; e != range.second; ++e) {
      const auto& uv = atlas.uv(e->chart, e->local);
      out << get(vindex, v) << ',' << e->chart << ',' << uv.x() << ',' << uv.y() << '\n';
    }
  }
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_IO_WRITE_UV_TABLE_H
