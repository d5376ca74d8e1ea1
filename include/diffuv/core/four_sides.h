// diffuv: the four sides of a disc patch, the convention of the whole library.
//
// The paper (section 2.7) needs four "edges" E_u1, E_v1, E_u2, E_v2 of each
// patch, like the sides of a rectangle, as source sets of the diffusion.
// Convention (counter-clockwise, so that charts are not mirrored):
//
//       corners[3] ---- v2 (v = 1) ---- corners[2]
//           |                               |
//       u1 (u = 0)                      u2 (u = 1)
//           |                               |
//       corners[0] ---- v1 (v = 0) ---- corners[1]
//
// corners[0] goes to (0,0), corners[1] to (1,0), corners[2] to (1,1),
// corners[3] to (0,1), and they follow each other along the boundary in the
// direction of the faces' orientation (counter-clockwise seen from the side
// the face normals point to). Each side includes both its corners, so a
// corner belongs to the two sides that meet there.
#ifndef DIFFUV_CORE_FOUR_SIDES_H
#define DIFFUV_CORE_FOUR_SIDES_H

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace diffuv {

/// One of the four sides of a patch, in the order the boundary walks them
/// from corners[0]: v1, u2, v2, u1.
enum class Side { v1 = 0, u2 = 1, v2 = 2, u1 = 3 };

/// The four sides in the order of `Side`, for loops over them.
constexpr std::array<Side, 4> all_sides = {Side::v1, Side::u2, Side::v2, Side::u1};

/// The side's name: "v1", "u2", "v2" or "u1".
inline const char* side_name(Side s)
{
  switch(s) {
    case Side::v1: return "v1";
    case Side::u2: return "u2";
    case Side::v2: return "v2";
    case Side::u1: return "u1";
  }
  return "?";
}

/// The side opposite to `s` (v1 and v2, u1 and u2).
constexpr Side opposite_side(Side s) { return static_cast<Side>((static_cast<int>(s) + 2) % 4); }

/// The four sides of a disc patch, each a polyline of boundary vertices.
template <class VertexDescriptor>
struct Four_sides {
  std::array<VertexDescriptor, 4> corners; ///< (0,0), (1,0), (1,1), (0,1), counter-clockwise
  std::vector<VertexDescriptor> v1;        ///< corners[0] .. corners[1], where v = 0
  std::vector<VertexDescriptor> u2;        ///< corners[1] .. corners[2], where u = 1
  std::vector<VertexDescriptor> v2;        ///< corners[2] .. corners[3], where v = 1
  std::vector<VertexDescriptor> u1;        ///< corners[3] .. corners[0], where u = 0

  /// Side `s`.
  std::vector<VertexDescriptor>& operator[](Side s) { return s == Side::v1 ? v1 : s == Side::u2 ? u2 : s == Side::v2 ? v2 : u1; }
  const std::vector<VertexDescriptor>& operator[](Side s) const
  {
    return s == Side::v1 ? v1 : s == Side::u2 ? u2 : s == Side::v2 ? v2 : u1;
  }
};

namespace internal {

// Throws std::out_of_range, naming `function` and the side, if a vertex of
// `sides` has an index (in `index`) outside [0, vertex_count): it is then not
// a vertex of the graph the sides are used on, and indexing by it would read
// or write past the graph's arrays.
template <class VertexDescriptor, class VertexIndexMap>
void check_side_vertices(const Four_sides<VertexDescriptor>& sides, VertexIndexMap index, std::size_t vertex_count,
                         const char* function)
{
  for(Side s : all_sides)
    for(const VertexDescriptor& v : sides[s]) {
      const std::size_t i = static_cast<std::size_t>(get(index, v));
      if(i >= vertex_count)
        throw std::out_of_range(std::string(function) + ": a vertex of side " + side_name(s) + " (index " +
                                std::to_string(i) + ") is not a vertex of the graph (" + std::to_string(vertex_count) +
                                " vertices)");
    }
}

} // namespace internal

} // namespace diffuv

#endif // DIFFUV_CORE_FOUR_SIDES_H
