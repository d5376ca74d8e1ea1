// Shared helpers of the tests: where CGAL's data set was extracted, a
// cache that loads each real mesh once for the whole test run, flat grids,
// files read by hand (independent of the readers under test), and the
// errors that a call must throw.
#ifndef DIFFUV_TEST_DATA_H
#define DIFFUV_TEST_DATA_H

#include <diffuv/core/error.h>
#include <diffuv/io/selection_file.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/iterator.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>
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

/// A flat grid in the z = 0 plane with vertex (i, j) at (xs[i], ys[j]), each
/// cell cut into two counter-clockwise triangles (normals along +z). Vertex
/// (i, j) has index j * nx + i with nx = xs.size(); cell (i, j) is faces
/// 2 (j (nx - 1) + i) (lower right triangle) and 2 (j (nx - 1) + i) + 1.
// The vertex indices of a CGAL selection file (data/selections/), and the
// same as vertices of a Mesh.
inline std::vector<std::size_t> selection_indices(const std::string& file)
{
  return diffuv::read_selection_file(data_path("selections/" + file));
}

inline std::vector<Mesh::Vertex_index> selection_corners(const std::string& file)
{
  std::vector<Mesh::Vertex_index> corners;
  for(std::size_t i : selection_indices(file)) corners.push_back(Mesh::Vertex_index(static_cast<Mesh::size_type>(i)));
  return corners;
}

inline Mesh make_grid_at(const std::vector<double>& xs, const std::vector<double>& ys)
{
  Mesh m;
  const std::size_t nx = xs.size() - 1, ny = ys.size() - 1;
  std::vector<Mesh::Vertex_index> v;
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i) v.push_back(m.add_vertex(Point_3(xs[i], ys[j], 0.)));
  auto at = [&](std::size_t i, std::size_t j) { return v[j * (nx + 1) + i]; };
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

/// A flat (nx by ny cells) grid of the unit square (`make_grid_at()`): vertex
/// (i, j) has index j * (nx + 1) + i and lies at (i / nx, j / ny).
inline Mesh make_grid(std::size_t nx, std::size_t ny)
{
  std::vector<double> xs(nx + 1), ys(ny + 1);
  for(std::size_t i = 0; i <= nx; ++i) xs[i] = double(i) / nx;
  for(std::size_t j = 0; j <= ny; ++j) ys[j] = double(j) / ny;
  return make_grid_at(xs, ys);
}

/// Vertex (i, j) of a grid made by make_grid(nx, ...).
inline Mesh::Vertex_index grid_vertex(std::size_t nx, std::size_t i, std::size_t j)
{
  return Mesh::Vertex_index(static_cast<Mesh::size_type>(j * (nx + 1) + i));
}

/// Signed area of a face in the uv map given as a vertex -> Point_2 function.
template <class UvOf>
double signed_uv_area(const Mesh& m, Mesh::Face_index f, UvOf uv_of)
{
  auto h = m.halfedge(f);
  const Point_2 a = uv_of(m.source(h)), b = uv_of(m.target(h)), c = uv_of(m.target(m.next(h)));
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
}

/// The vertex numbers of face `f`, from the target of `halfedge(f)` on.
inline std::vector<std::size_t> face_vertex_numbers(const Mesh& mesh, Mesh::Face_index f)
{
  std::vector<std::size_t> numbers;
  for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    numbers.push_back(std::size_t(target(h, mesh)));
  return numbers;
}

/// True if `a` is `b` up to a rotation (the same polygon from another corner).
inline bool same_cycle(std::vector<std::size_t> a, const std::vector<std::size_t>& b)
{
  for(std::size_t r = 0; r < a.size(); ++r) {
    if(a == b)
      return true;
    std::rotate(a.begin(), a.begin() + 1, a.end());
  }
  return false;
}

/// The points and faces of a mesh file, read by hand.
struct File_soup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
};

/// A face written "k i1 ... ik", read from `in`.
inline std::vector<std::size_t> read_face_indices(std::istream& in)
{
  std::size_t k = 0;
  in >> k;
  std::vector<std::size_t> f(k);
  for(std::size_t& i : f)
    in >> i;
  return f;
}

/// An OFF file as CGAL's data files write it: "OFF", three counts, one vertex
/// (three numbers) per line, then "k i1 ... ik" per face.
inline File_soup parse_off(const std::string& file)
{
  std::ifstream in(file);
  std::string keyword;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> keyword >> nv >> nf >> ne;
  EXPECT_EQ(keyword, "OFF");
  File_soup soup;
  for(std::size_t i = 0; i < nv; ++i) {
    std::array<double, 3> p;
    in >> p[0] >> p[1] >> p[2];
    soup.points.push_back(p);
  }
  for(std::size_t j = 0; j < nf; ++j)
    soup.faces.push_back(read_face_indices(in));
  EXPECT_TRUE(in) << file;
  return soup;
}

/// CGAL's PLY reader with face colours, and vertex colours if asked for. A
/// pitfall: CGAL 5.5 compiles it only when both are asked for, into the same
/// iterator type.
inline bool cgal_read_ply(const std::string& file, std::vector<Point_3>& points,
                          std::vector<std::vector<std::size_t>>& polygons, std::vector<CGAL::IO::Color>& face_colors,
                          bool binary = true, std::vector<CGAL::IO::Color>* vertex_colors = nullptr)
{
  std::vector<CGAL::IO::Color> ignored;
  return CGAL::IO::read_PLY(file, points, polygons,
                            CGAL::parameters::face_color_output_iterator(std::back_inserter(face_colors))
                              .vertex_color_output_iterator(std::back_inserter(vertex_colors ? *vertex_colors : ignored))
                              .use_binary_mode(binary)
                              .verbose(false));
}

/// The bytes of `file`.
inline std::string file_content(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The `Input_error` that `f()` throws (a failure if it throws none).
template <class F>
diffuv::Input_error input_error(F f)
{
  try {
    f();
  } catch(const diffuv::Input_error& e) {
    return e;
  }
  ADD_FAILURE() << "no Input_error";
  return diffuv::Input_error("", 0, "no error");
}

/// The message of the exception of type `E` that `f()` throws.
template <class E, class F>
std::string error_text(F f)
{
  try {
    f();
  } catch(const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception";
  return std::string();
}

/// A fixture with a fresh folder per test (named after the test and the
/// process), removed afterwards, and helpers to write files into it.
class Temp_dir_test : public ::testing::Test {
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // A parameterized test's names hold '/' ("Catalogue/BadInput", "Answer/3"):
    // one folder per test, not a tree that TearDown() would remove only the leaf of.
    std::string name = std::string("diffuv_test_") + std::to_string(::getpid()) + "_" +
                       info->test_suite_name() + "_" + info->name();
    std::replace(name.begin(), name.end(), '/', '_');
    dir_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// The path of `name` in the folder.
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Writes `content` to `name` in the folder and returns its path.
  std::string write(const std::string& name, const std::string& content) const
  {
    std::ofstream out(path(name), std::ios::binary);
    out << content;
    return path(name);
  }

  std::filesystem::path dir_;
};

} // namespace diffuv_test

#endif
