// A copy of a test mesh tessellated otherwise (isotropic remeshing), shared by
// the correspondence tests of the library and of the tool.
#ifndef DIFFUV_TEST_REMESHED_COPY_H
#define DIFFUV_TEST_REMESHED_COPY_H

#include "test_data.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

namespace diffuv_test {

/// `m` remeshed to `edge_factor` times its mean edge length (3 iterations,
/// as the correspondence bench's `fine` and `coarse` copies), garbage collected.
inline Mesh remeshed_copy(const Mesh& m, double edge_factor)
{
  Mesh copy = m;
  double mean_edge = 0.;
  for(auto e : edges(m)) mean_edge += CGAL::Polygon_mesh_processing::edge_length(e, m);
  mean_edge /= num_edges(m);
  CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(copy), edge_factor * mean_edge, copy,
                                                     CGAL::parameters::number_of_iterations(3));
  copy.collect_garbage();
  return copy;
}

} // namespace diffuv_test

#endif // DIFFUV_TEST_REMESHED_COPY_H
