// diffuv correspondence bench: the second meshes. Mesh B of each kind
// (fine, coarse, shuffled, loop, noise) made from mesh A, with its labels and
// the true image on B of every vertex of A.
#include "correspondence/correspondence_bench.h"

#include <diffuv/correspondence/nearest_face_labels.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/bounding_box.h>
#include <CGAL/subdivision_method_3.h>

#include <numeric>
#include <random>
#include <stdexcept>

namespace diffuv_bench {

double mean_edge_length(const Mesh& m)
{
  double sum = 0.;
  for(auto e : m.edges()) sum += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  return m.number_of_edges() ? sum / static_cast<double>(m.number_of_edges()) : 0.;
}

double bounding_diagonal(const Mesh& m)
{
  const auto box = CGAL::bounding_box(m.points().begin(), m.points().end());
  return std::sqrt(CGAL::squared_distance(box.min(), box.max()));
}

namespace {

using Aabb_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

void collect(Mesh& m)
{
  m.collect_garbage();
  if(!CGAL::is_triangle_mesh(m)) throw std::runtime_error("a variant is not a triangle mesh");
}

Mesh remeshed(const Mesh& a, double target)
{
  Mesh b = a; // A stays untouched
  auto constrained = b.add_property_map<Mesh::Edge_index, bool>("e:bench_border", false).first;
  for(auto e : b.edges())
    if(b.is_border(e)) constrained[e] = true; // keep a border where it is (the default meshes are closed)
  PMP::isotropic_remeshing(b.faces(), target, b,
                           CGAL::parameters::number_of_iterations(3).edge_is_constrained_map(constrained));
  b.remove_property_map(constrained);
  collect(b);
  return b;
}

Mesh loop_subdivided(const Mesh& a)
{
  Mesh b = a;
  CGAL::Subdivision_method_3::Loop_subdivision(b, CGAL::parameters::number_of_iterations(1));
  collect(b);
  return b;
}

Mesh noisy(const Mesh& a, double amplitude, unsigned seed)
{
  Mesh b = a;
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0., 1.);
  for(auto v : b.vertices()) {
    double x, y, z, n;
    do {
      x = normal(random);
      y = normal(random);
      z = normal(random);
      n = std::sqrt(x * x + y * y + z * z);
    } while(n < 1e-12);
    const double s = amplitude / n;
    b.point(v) = Point_3(b.point(v).x() + s * x, b.point(v).y() + s * y, b.point(v).z() + s * z);
  }
  return b;
}

// A copy with vertices and faces in a random order and each face starting at a
// random corner; `new_vertex[v]` is the copy of vertex v of `a`, `new_face[f]`
// the copy of face f.
Mesh shuffled(const Mesh& a, unsigned seed, std::vector<vertex_descriptor>& new_vertex,
              std::vector<face_descriptor>& new_face)
{
  std::mt19937 random(seed);
  std::vector<std::size_t> vorder(a.number_of_vertices()), forder(a.number_of_faces());
  std::iota(vorder.begin(), vorder.end(), std::size_t(0));
  std::iota(forder.begin(), forder.end(), std::size_t(0));
  std::shuffle(vorder.begin(), vorder.end(), random);
  std::shuffle(forder.begin(), forder.end(), random);
  Mesh b;
  new_vertex.assign(a.number_of_vertices(), Mesh::null_vertex());
  new_face.assign(a.number_of_faces(), Mesh::null_face());
  for(std::size_t old : vorder) new_vertex[old] = b.add_vertex(a.point(vertex_descriptor(static_cast<Mesh::size_type>(old))));
  std::uniform_int_distribution<int> rotation(0, 2);
  for(std::size_t old : forder) {
    const auto c = corners(face_descriptor(static_cast<Mesh::size_type>(old)), a);
    const int r = rotation(random);
    new_face[old] = b.add_face(new_vertex[c[r].idx()], new_vertex[c[(r + 1) % 3].idx()], new_vertex[c[(r + 2) % 3].idx()]);
    if(new_face[old] == Mesh::null_face()) throw std::runtime_error("shuffled copy: add_face failed");
  }
  return b;
}

// The closest point on B of every vertex of A.
std::vector<Location> closest_points(const Mesh& a, const Mesh& b)
{
  Aabb_tree tree;
  PMP::build_AABB_tree(b, tree);
  std::vector<Location> truth(a.number_of_vertices());
  for(auto v : a.vertices()) truth[v.idx()] = PMP::locate_with_AABB_tree(a.point(v), tree, b);
  return truth;
}

} // namespace

Variant make_variant(const std::string& name, const Mesh& a, const std::vector<int>& labels_a, double mean_edge)
{
  Variant out;
  out.name = name;
  if(name == "shuffled") {
    std::vector<vertex_descriptor> new_vertex;
    std::vector<face_descriptor> new_face;
    out.mesh = shuffled(a, 20240601u, new_vertex, new_face);
    out.labels.assign(a.number_of_faces(), 0);
    for(auto f : a.faces()) out.labels[new_face[f.idx()].idx()] = labels_a[f.idx()];
    out.truth.resize(a.number_of_vertices());
    for(auto v : a.vertices()) out.truth[v.idx()] = PMP::locate_vertex<double>(new_vertex[v.idx()], out.mesh);
    out.how = "vertices and faces permuted, labels carried exactly, truth = the vertex itself";
    return out;
  }
  if(name == "fine") {
    out.mesh = remeshed(a, 0.7 * mean_edge);
    out.how = "isotropic remeshing, target 0.7 x mean edge, 3 iterations";
  } else if(name == "coarse") {
    out.mesh = remeshed(a, 1.6 * mean_edge);
    out.how = "isotropic remeshing, target 1.6 x mean edge, 3 iterations";
  } else if(name == "loop") {
    out.mesh = loop_subdivided(a);
    out.how = "1 Loop subdivision step";
  } else if(name == "noise") {
    out.mesh = noisy(a, 0.05 * mean_edge, 20240602u);
    out.how = "vertices moved by 0.05 x mean edge in random directions";
  } else {
    throw std::invalid_argument("unknown pair '" + name + "' (fine, coarse, shuffled, loop, noise)");
  }
  out.labels = diffuv::nearest_face_labels(a, labels_a, out.mesh);
  out.truth = closest_points(a, out.mesh);
  out.how += "; labels by nearest face of A, truth = closest point on B";
  return out;
}

} // namespace diffuv_bench
