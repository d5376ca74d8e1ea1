// diffuv: region labels cleaned before two meshes are put in correspondence.
//
// Labels painted or transferred onto two meshes of one object disagree at the
// region borders: jagged borders, one-face islands, a region touching itself
// at a vertex. Points of the two meshes are matched through (label, u, v), so
// both meshes must get the same regions wherever their labels agree. The
// cleaning is therefore a fixed rule that reads only the labels and the
// surface (areas, edge lengths, adjacency, orientation), never the face or
// vertex numbering nor the coordinate axes.
//
// The rule. A round applies, in this order:
//
//  1. Islands. The components (faces joined across edges) of equal labels; a
//     component whose area is below `island_fraction` times the area of the
//     largest component of its label (measured at the start of the round) is
//     an island. Islands are absorbed smallest first: an island takes the
//     label with which it shares the longest border (3D edge length, summed
//     over the neighbouring components of that label; ties: smaller label)
//     and becomes part of those components. A component that grew this way
//     is absorbed in its turn if it is still an island, so an island inside
//     an island ends in the region around both. Islands of equal area and
//     label are decided together from the same state (they are never
//     adjacent), so no order between them is needed. A label with several
//     large components (two hands painted with one label) keeps them all.
//  2. Border smoothing, in synchronous passes (every face decides from the
//     labels of the previous pass, so the face order does not matter): a face
//     with two or more edge-neighbours of one other label L takes L (the
//     label with most such neighbours; ties: smaller label). Mesh-border edges
//     are not neighbours. Two neighbouring faces that would move differently
//     (typically swapping labels) do not both move: the one with more of its
//     new label than of its own around its corners (by area) goes, then the
//     one whose move shortens the region borders most, then the one moving to
//     the smaller label, then from the smaller label; the other waits for the
//     next pass. Each pass then strictly shortens the total border length, so
//     passes never oscillate. Passes stop after `smoothing_passes` or when one
//     changes nothing.
//  3. Pinches. Around a vertex, the faces of one label may form several fans
//     (separated by faces of other labels or by the mesh border): the region
//     touches itself there, and its boundary passes the vertex twice. The fan
//     of largest area is kept; every face of the other fans of that label
//     takes the label most common among its edge-neighbours of another label
//     (or, if it has none, among the faces sharing a vertex with it; ties:
//     smaller label), read from the labels before this step. When two fans
//     tie for the largest area nothing tells them apart, so none is kept and
//     the region leaves the vertex on both sides. When several labels are
//     pinched at one vertex (a saddle: L, M, L, M around it), the label whose
//     fans to remove have the least area (then the smaller label) is cut
//     first; this reconnects the other label, which then needs no cut. (Fans
//     kept apart by a single triangle are usually joined by smoothing first:
//     that triangle has two edges towards the region.)
//
// Rounds repeat until one changes nothing, at most `max_rounds` times. Areas
// and lengths are rounded to integer multiples of 2^-32 times the largest face
// area and the longest edge: integer sums do not depend on the order in which
// faces are visited, so ties are ties on every numbering of the mesh.
//
// Cost per round: O(F log F) for the islands (components merged small into
// large; an island is scanned again only when it grew and is still an
// island), O(F) per smoothing pass, O(sum of vertex degrees) for the pinches.
#ifndef DIFFUV_CORRESPONDENCE_CLEAN_LABELS_H
#define DIFFUV_CORRESPONDENCE_CLEAN_LABELS_H

#include <diffuv/correspondence/internal/label_cleaning_mesh.h>
#include <diffuv/correspondence/internal/label_cleaning_rules.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

/// Options of `clean_labels()`.
struct Label_cleaning_options {
  double island_fraction = 0.1;     ///< a component of a label whose area is below this fraction of the label's largest component is an island (in [0, 1])
  std::size_t smoothing_passes = 4; ///< synchronous border-smoothing passes per round
  std::size_t max_rounds = 10;      ///< the three rules are repeated until nothing changes, at most this many times
};

/// What `clean_labels()` did.
struct Label_cleaning_report {
  std::size_t islands = 0;        ///< islands absorbed (a component absorbed twice, as an island inside an island, counts twice)
  std::size_t island_faces = 0;   ///< faces relabelled by the island rule (relabellings, summed over islands)
  std::size_t smoothed_faces = 0; ///< faces relabelled by border smoothing (relabellings, summed over passes)
  std::size_t pinches = 0;        ///< (vertex, label) pairs where a region touched itself and was cut
  std::size_t pinch_faces = 0;    ///< faces relabelled by the pinch rule (summed over rounds)
  std::size_t rounds = 0;         ///< rounds run, the last one included (1 when the labels were clean)
  std::size_t changed = 0;        ///< faces whose final label differs from their input label

  /// Returns how many faces end with another label than they came with (faces, not events).
  std::size_t changed_faces() const { return changed; }

  /// Returns true if no rule fired and no face changed.
  bool empty() const { return changed == 0 && islands == 0 && smoothed_faces == 0 && pinches == 0; }
};

/// Cleans region labels by a fixed rule that depends only on the labels and
/// the surface (see the top of this file): absorbs islands, smooths jagged
/// region borders, cuts regions that touch themselves at a vertex; repeated
/// until nothing changes. Two meshes of one object cleaned this way get the
/// same regions wherever their labels agree, whatever their numbering.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` with
///         internal face and vertex indices, triangles only
/// \tparam VertexPointMap a readable property map from vertex to a CGAL point
/// \param face_labels #F entries, by face index: the labels, changed in place
/// \returns what each rule did and how many faces changed label
/// \throws std::invalid_argument if `face_labels` does not have `num_faces(tm)`
///         entries, a face is not a triangle, or `options.island_fraction` is
///         not a number in [0, 1]
template <class TriangleMesh, class VertexPointMap>
Label_cleaning_report clean_labels(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int>& face_labels,
                                   const Label_cleaning_options& options = Label_cleaning_options())
{
  static_assert(std::is_convertible<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                                    typename boost::property_traits<VertexPointMap>::key_type>::value,
                "clean_labels: VertexPointMap must be a property map from the mesh's vertex_descriptor to a point");
  if(face_labels.size() != static_cast<std::size_t>(num_faces(tm)))
    throw std::invalid_argument("clean_labels: face_labels must have one entry per face");
  if(!CGAL::is_triangle_mesh(tm))
    throw std::invalid_argument("clean_labels: the mesh must have triangle faces only");
  if(!(options.island_fraction >= 0. && options.island_fraction <= 1.))
    throw std::invalid_argument("clean_labels: options.island_fraction must be in [0, 1]");

  const internal::Label_cleaning_mesh m = internal::make_label_cleaning_mesh(tm, vpm);
  const std::vector<int> input = face_labels;
  Label_cleaning_report r;
  for(std::size_t round = 0; round < options.max_rounds; ++round) {
    ++r.rounds;
    const std::vector<int> start = face_labels;
    r.islands += internal::absorb_islands(m, face_labels, options.island_fraction, r.island_faces);
    r.smoothed_faces += internal::smooth_borders_synchronously(m, face_labels, options.smoothing_passes);
    r.pinches += internal::cut_pinches(m, face_labels, r.pinch_faces);
    if(face_labels == start) break;
  }
  for(std::size_t f = 0; f < input.size(); ++f)
    if(face_labels[f] != input[f]) ++r.changed;
  return r;
}

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_CLEAN_LABELS_H
