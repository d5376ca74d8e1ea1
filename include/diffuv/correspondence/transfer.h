// diffuv: per-vertex data of mesh B pulled onto mesh A through a correspondence.
//
// A vertex of A lands on a face of B with barycentric coordinates; its value is
// the same barycentric mix of the values at that face's three vertices.
#ifndef DIFFUV_CORRESPONDENCE_TRANSFER_H
#define DIFFUV_CORRESPONDENCE_TRANSFER_H

#include <diffuv/core/color.h>
#include <diffuv/correspondence/correspondence.h>

#include <CGAL/barycenter.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace diffuv {
namespace internal {

template <class T> struct is_std_array : std::false_type {};
template <class T, std::size_t N> struct is_std_array<std::array<T, N>> : std::true_type {};

// w0 a + w1 b + w2 c, rounded and clamped for integer types (colours).
template <class T>
T weighted_scalar(const T& a, const T& b, const T& c, const std::array<double, 3>& w)
{
  const double x = w[0] * static_cast<double>(a) + w[1] * static_cast<double>(b) + w[2] * static_cast<double>(c);
  if constexpr(std::is_integral_v<T>) {
    const double r = std::round(x);
    return static_cast<T>(std::clamp(r, static_cast<double>(std::numeric_limits<T>::lowest()),
                                     static_cast<double>((std::numeric_limits<T>::max)())));
  } else {
    return static_cast<T>(x);
  }
}

template <class Value>
Value weighted_value(const Value& a, const Value& b, const Value& c, const std::array<double, 3>& w)
{
  if constexpr(std::is_arithmetic_v<Value>) {
    return weighted_scalar(a, b, c, w);
  } else if constexpr(is_std_array<Value>::value) {
    Value out;
    for(std::size_t k = 0; k < out.size(); ++k) out[k] = weighted_scalar(a[k], b[k], c[k], w);
    return out;
  } else if constexpr(std::is_same_v<Value, Color>) {
    return Color{weighted_scalar(a.r, b.r, c.r, w), weighted_scalar(a.g, b.g, c.g, w), weighted_scalar(a.b, b.b, c.b, w)};
  } else {
    // CGAL points (Point_2, Point_3): an affine combination.
    return CGAL::barycenter(a, w[0], b, w[1], c, w[2]);
  }
}

} // namespace internal

/// The value at surface point `p` of B: the barycentric mix of `values` at the
/// three vertices of its face. Works for arithmetic values (rounded and clamped
/// for integer types), `std::array`s of them, `Color`s (each channel rounded
/// and clamped), and CGAL points (texture coordinates, positions).
/// \pre `p.mapped()`
template <class MeshB, class Point_3, class VertexValueMap>
typename boost::property_traits<VertexValueMap>::value_type
interpolate_at(const MeshB& b, const Surface_point<MeshB, Point_3>& p, VertexValueMap values)
{
  const auto h = halfedge(p.face, b);
  return internal::weighted_value(get(values, source(h, b)), get(values, target(h, b)),
                                  get(values, target(next(h, b), b)), p.barycentric);
}

/// Pulls per-vertex `values` of B onto the points `images` (e.g. the images of
/// A's vertices from `Atlas_correspondence::map_vertices()`); unmapped points
/// get `fallback`.
/// \returns one value per entry of `images`
template <class MeshB, class Point_3, class VertexValueMap>
std::vector<typename boost::property_traits<VertexValueMap>::value_type>
transfer_vertex_values(const MeshB& b, const std::vector<Surface_point<MeshB, Point_3>>& images, VertexValueMap values,
                       const typename boost::property_traits<VertexValueMap>::value_type& fallback)
{
  std::vector<typename boost::property_traits<VertexValueMap>::value_type> out;
  out.reserve(images.size());
  for(const auto& p : images) out.push_back(p.mapped() ? interpolate_at(b, p, values) : fallback);
  return out;
}

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_TRANSFER_H
