// Shared helpers of the tests: where CGAL's data set was extracted, and a
// cache that loads each real mesh once for the whole test run.
#ifndef DIFFUV_TEST_DATA_H
#define DIFFUV_TEST_DATA_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace diffuv_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Point_2 = Kernel::Point_2;
using Mesh = CGAL::Surface_mesh<Point_3>;

/// Absolute path of a file of CGAL's data set, e.g. data_path("meshes/cow.off").
inline std::string data_path(const std::string& relative)
{
  return std::string(DIFFUV_TEST_DATA_DIR) + "/" + relative;
}

/// CGAL's mesh `name` (e.g. "cow.off"), read once per test run.
inline const Mesh& cgal_mesh(const std::string& name)
{
  static std::map<std::string, Mesh> cache;
  auto it = cache.find(name);
  if(it == cache.end()) {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(data_path("meshes/" + name), m))
      ADD_FAILURE() << "cannot read " << name;
    it = cache.emplace(name, std::move(m)).first;
  }
  return it->second;
}

} // namespace diffuv_test

#endif
