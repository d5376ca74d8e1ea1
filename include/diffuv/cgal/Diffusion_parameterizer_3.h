// diffuv: the diffusion parameterization as a model of CGAL's `Parameterizer_3`
// concept, for `CGAL::Surface_mesh_parameterization::parameterize()`.
//
//     namespace SMP = CGAL::Surface_mesh_parameterization;
//     diffuv::Diffusion_parameterizer_3<Mesh> parameterizer(c0, c1, c2, c3);  // or (corners), or () for automatic ones
//     SMP::Error_code err = SMP::parameterize(mesh, parameterizer, bhd, uv_map);
//
// works on any triangle mesh CGAL's parameterizers take: `CGAL::Surface_mesh`,
// `CGAL::Polyhedron_3` (no vertex ids needed), a `CGAL::Seam_mesh` (a closed
// or non-disc mesh cut open along seam edges), any kernel (points are read as
// doubles).
//
// How: the connected component of the mesh that contains the border halfedge
// `bhd` is copied into a temporary `CGAL::Surface_mesh<Epick::Point_3>` (one
// vertex per vertex of the input, in the order of `vertices(mesh)`, so a
// Seam_mesh's seam vertices are two vertices there), `parameterize_disc()`
// runs on the copy, and the (u,v) are written back through `uv_map`.
#ifndef DIFFUV_CGAL_DIFFUSION_PARAMETERIZER_3_H
#define DIFFUV_CGAL_DIFFUSION_PARAMETERIZER_3_H

#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Default.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <iterator>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {

/// The CGAL error code closest to a diffuv status:
/// - `empty_mesh` -> `ERROR_EMPTY_MESH`; `not_triangle_mesh` -> `ERROR_NON_TRIANGULAR_MESH`;
/// - not a disc (`no_border`, `several_borders`, `not_a_disc`, `non_manifold`,
///   `disconnected_mesh`) -> `ERROR_NO_TOPOLOGICAL_DISC`;
/// - `border_too_short` -> `ERROR_BORDER_TOO_SHORT`;
/// - bad corners (`corner_count`, `corner_out_of_range`, `corner_not_on_border`,
///   `corner_duplicated`) -> `ERROR_NON_CONVEX_BORDER`, the code CGAL's own
///   `Square_border_parameterizer_3` returns for corners not on the border;
/// - a distance computation that failed (`empty_source_range`, `empty_side`,
///   `negative_weight`, `unreachable_vertices`: NaN or infinite coordinates,
///   for instance) -> `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, CGAL's "the solver failed";
/// - `not_injective` (a map that still folds) -> `ERROR_NO_1_TO_1_MAPPING`;
/// - `no_labels` (not an input of this parameterizer) -> `ERROR_WRONG_PARAMETER`.
/// A switch without default: the compiler (-Wswitch) flags a code added to
/// `Status_code` and not mapped here; such a code gives `ERROR_WRONG_PARAMETER`.
inline CGAL::Surface_mesh_parameterization::Error_code to_cgal_error_code(Status_code code)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  switch(code) {
    case Status_code::ok: return SMP::OK;
    case Status_code::empty_mesh: return SMP::ERROR_EMPTY_MESH;
    case Status_code::not_triangle_mesh: return SMP::ERROR_NON_TRIANGULAR_MESH;
    case Status_code::disconnected_mesh:
    case Status_code::no_border:
    case Status_code::several_borders:
    case Status_code::not_a_disc:
    case Status_code::non_manifold: return SMP::ERROR_NO_TOPOLOGICAL_DISC;
    case Status_code::border_too_short: return SMP::ERROR_BORDER_TOO_SHORT;
    case Status_code::corner_count:
    case Status_code::corner_out_of_range:
    case Status_code::corner_not_on_border:
    case Status_code::corner_duplicated: return SMP::ERROR_NON_CONVEX_BORDER;
    case Status_code::empty_source_range:
    case Status_code::empty_side:
    case Status_code::negative_weight:
    case Status_code::unreachable_vertices: return SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    case Status_code::not_injective: return SMP::ERROR_NO_1_TO_1_MAPPING;
    case Status_code::no_labels: return SMP::ERROR_WRONG_PARAMETER;  // labels are not this parameterizer's input
  }
  return SMP::ERROR_WRONG_PARAMETER;
}

/// The English sentence of a CGAL parameterization error code.
///
/// Use it rather than `CGAL::Surface_mesh_parameterization::get_error_message()`,
/// whose table in CGAL 5.5 lacks the sentence of `ERROR_NO_TOPOLOGICAL_BALL`:
/// from that code on it returns the next code's sentence, and a null pointer for
/// `ERROR_WRONG_PARAMETER`.
inline const char* cgal_error_message(CGAL::Surface_mesh_parameterization::Error_code code)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  switch(code) {
    case SMP::OK: return "Success";
    case SMP::ERROR_EMPTY_MESH: return "Input mesh is empty";
    case SMP::ERROR_NON_TRIANGULAR_MESH: return "Input mesh is not triangular";
    case SMP::ERROR_NO_TOPOLOGICAL_DISC: return "Input mesh is not a topological disc";
    case SMP::ERROR_NO_TOPOLOGICAL_BALL: return "Input mesh is not a topological ball";
    case SMP::ERROR_BORDER_TOO_SHORT: return "This border parameterization requires a longer border";
    case SMP::ERROR_NON_CONVEX_BORDER: return "This parameterization method requires a convex border";
    case SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "Cannot solve linear system";
    case SMP::ERROR_NO_1_TO_1_MAPPING: return "Parameterization failed: no one-to-one mapping";
    case SMP::ERROR_WRONG_PARAMETER: return "A method received an unexpected parameter";
  }
  return "Unknown error";
}

/// Maps a disc-shaped triangle mesh onto the unit square by diffusion
/// coordinates (README, doc/design.md), as a model of CGAL's `Parameterizer_3`
/// concept: pass it to `CGAL::Surface_mesh_parameterization::parameterize()`.
///
/// **Corners and orientation.** Four corner vertices, given to the
/// constructor (as to CGAL's `Square_border_*_parameterizer_3`) or, when none
/// are given, chosen as `parameterize_disc()` chooses them without corners
/// (equal arcs from the sharpest border vertex, four_sides.h). The first goes to (0,0); the three others, in
/// any order, follow **counter-clockwise** along the border (the direction of
/// the faces' orientation) to (1,0), (1,1), (0,1). The chart is not mirrored:
/// a face counter-clockwise on the surface is counter-clockwise in (u,v).
/// CGAL's square border parameterizers differ on both points: they walk the
/// border from `source(bhd)` in the order of its border halfedges, which
/// mirrors the chart. Every corner lands exactly on its corner of the square;
/// the border vertices between them land on the square's sides; the map may
/// fold (the paper's edge-path distances do on curved patches), and `OK` does
/// not promise a one-to-one map (as with CGAL's LSCM or ARAP).
///
/// **What is parameterized.** The connected component (through edges) of the
/// faces incident to `bhd`, as CGAL's parameterizers do; it must be a
/// topological disc (one border loop, Euler characteristic 1, manifold,
/// triangles only), else nothing is written and an `Error_code` comes back
/// (see `to_cgal_error_code()`). Each vertex of the component gets its (u,v)
/// in `uvmap` and `true` in `vpmap`; other vertices are not touched, nor is
/// anything on failure. `vimap` is not used.
///
/// **Cost of the copy.** The component is copied into a temporary
/// `CGAL::Surface_mesh<Epick::Point_3>` (this works for any input type:
/// Polyhedron_3 without vertex ids, Seam_mesh's halfedge-based vertices, exact
/// kernels), the diffusion runs on the copy, and the (u,v) are copied back.
/// That is not free (doc/performance.md, "Cost of the CGAL adapter"): the copy,
/// a second mesh in memory and the (u,v) written through `uvmap`; through
/// CGAL's `parameterize()`, which builds its own vertex index map too, it
/// costs more than calling `parameterize_disc()`
/// (parameterization/parameterize_disc.h) directly on a `CGAL::Surface_mesh`. That native API needs no copy and gives
/// the same (u,v): the copy keeps the order of `vertices(mesh)` and, for a
/// whole mesh, of `faces(mesh)` (tested equal on a Surface_mesh and a
/// Polyhedron_3). Use it, or `parameterize_patches()` for a mesh that is not a
/// disc, when speed matters; use this class for CGAL's interface and mesh types.
///
/// **Diagnostics.** `Error_code` is coarse; `status()` gives the
/// `diffuv::Status` of the last call (code and detail, e.g. which corner is not
/// on the border) and `corners()` the four corners used. `parameterize()` of
/// CGAL takes the parameterizer by value; the copies share this state, so the
/// object you passed reports it afterwards (and copies must not be used from
/// several threads at once).
///
/// \tparam TriangleMesh_ a model of `FaceListGraph` and `VertexListGraph` with a
///         `vertex_point` property map, as `parameterize()` of CGAL requires
///         (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, `CGAL::Seam_mesh`, ...)
/// \tparam DistanceTag the distance diffused from each side: `Graph_distance_tag`,
///         `Fmm_distance_tag` or `Exact_distance_tag` (graph/distance_tags.h);
///         `CGAL::Default` (the default) calls `parameterize_disc()` without a
///         tag, so this class always uses the library's default distance
/// \tparam HeapTag the heap of the distance runs (graph/heap_tags.h), which
///         changes the time, not the result; `CGAL::Default`: the library's
///         default (`Fibonacci_heap_tag`, named here when `DistanceTag` is)
template <class TriangleMesh_, class DistanceTag = CGAL::Default, class HeapTag = CGAL::Default>
class Diffusion_parameterizer_3 {
public:
  typedef TriangleMesh_ TriangleMesh;  ///< as the `Parameterizer_3` concept names it
  typedef TriangleMesh_ Triangle_mesh; ///< as CGAL's own parameterizers also name it
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  /// The mesh the diffusion actually runs on.
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Work_kernel;
  typedef CGAL::Surface_mesh<Work_kernel::Point_3> Work_mesh;

  /// Corners chosen automatically, as `parameterize_disc()` does without corners.
  Diffusion_parameterizer_3() : state_(std::make_shared<State>()) {}

  /// Corners given: `v0` goes to (0,0), the three others, in any order, follow
  /// counter-clockwise along the border to (1,0), (1,1), (0,1). They must be
  /// four distinct vertices of the border loop of the component parameterized
  /// (for a Seam_mesh: seam-mesh vertices, e.g. `target(h, seam_mesh)`), else
  /// `parameterize()` returns `ERROR_NON_CONVEX_BORDER`.
  Diffusion_parameterizer_3(vertex_descriptor v0, vertex_descriptor v1, vertex_descriptor v2, vertex_descriptor v3)
    : given_corners_{v0, v1, v2, v3}, corners_given_(true), state_(std::make_shared<State>())
  {}

  /// Corners given as a list, e.g. the vertices of a selection file
  /// (`selection_vertices()`, io/selection_file.h): four vertices, as for the
  /// four-vertex constructor. A list of any other length (none included: the
  /// default constructor is the one for automatic corners) is kept as given,
  /// and `parameterize()` reports it, writing nothing: `ERROR_NON_CONVEX_BORDER`,
  /// with `status()` `corner_count` ("exactly four corner vertices are needed
  /// (3 given)").
  explicit Diffusion_parameterizer_3(std::vector<vertex_descriptor> corners)
    : given_corners_(std::move(corners)), corners_given_(true), state_(std::make_shared<State>())
  {}

  /// Whether the corners were given to the constructor.
  bool corners_given() const { return corners_given_; }

  /// The detailed outcome of the last `parameterize()` call of this object or
  /// of a copy of it (`ok` before any call).
  const Status& status() const { return state_->status; }

  /// The four corners used by the last successful call, in the order of
  /// (0,0), (1,0), (1,1), (0,1); empty before it or after a failure.
  const std::vector<vertex_descriptor>& corners() const { return state_->corners; }

  /// Computes the (u,v) of every vertex of the connected component of `mesh`
  /// that contains the border halfedge `bhd`.
  ///
  /// \tparam VertexUVMap a `ReadWritePropertyMap` from `vertex_descriptor` to a
  ///         2D point constructible from two doubles (the kernel's `Point_2`)
  /// \tparam VertexIndexMap any (unused; CGAL's `parameterize()` passes one)
  /// \tparam VertexParameterizedMap a `ReadWritePropertyMap` from `vertex_descriptor` to `bool`
  /// \param mesh the mesh
  /// \param bhd a border halfedge (its face is null) of the component to
  ///        parameterize; a non-border halfedge selects the component of its
  ///        face, which is then reported as not a disc if it has no border;
  ///        a null halfedge (what `longest_border()` returns for a closed mesh)
  ///        gives `ERROR_NO_TOPOLOGICAL_DISC`. Through CGAL's free function
  ///        `parameterize()` check for a null `bhd` first: CGAL 5.5 indexes the
  ///        component of `bhd` before calling this and crashes on a null one
  ///        (a precondition that Release builds do not check).
  /// \returns `OK`, or the error closest to the problem found (`to_cgal_error_code()`)
  template <class VertexUVMap, class VertexIndexMap, class VertexParameterizedMap>
  CGAL::Surface_mesh_parameterization::Error_code parameterize(const TriangleMesh& mesh, halfedge_descriptor bhd,
                                                               VertexUVMap uvmap, VertexIndexMap /* vimap */,
                                                               VertexParameterizedMap vpmap)
  {
    state_->corners.clear();
    state_->status = run(mesh, bhd, uvmap, vpmap);
    return to_cgal_error_code(state_->status.code);
  }

private:
  typedef typename boost::graph_traits<Work_mesh>::vertex_descriptor work_vertex;

  struct State {
    Status status;
    std::vector<vertex_descriptor> corners;
  };

  template <class VertexUVMap, class VertexParameterizedMap>
  Status run(const TriangleMesh& mesh, halfedge_descriptor bhd, VertexUVMap uvmap, VertexParameterizedMap vpmap)
  {
    typedef boost::graph_traits<TriangleMesh> GT;
    if(corners_given_ && given_corners_.size() != 4)
      return Status(Status_code::corner_count, std::to_string(given_corners_.size()) + " given");
    if(bhd == GT::null_halfedge())
      return Status(Status_code::no_border, "the border halfedge given is null (a closed mesh has none)");
    face_descriptor seed = face(bhd, mesh);
    if(seed == GT::null_face()) seed = face(opposite(bhd, mesh), mesh);
    if(seed == GT::null_face())
      return Status(Status_code::empty_mesh, "the halfedge given has no face on either side");

    // The component, through edges, as CGAL's parameterizers take it.
    std::vector<face_descriptor> component;
    CGAL::Polygon_mesh_processing::connected_component(seed, mesh, std::back_inserter(component));

    // Its vertices, numbered in the order of vertices(mesh).
    std::unordered_map<vertex_descriptor, work_vertex> to_work;
    to_work.reserve(3 * component.size());
    for(face_descriptor f : component)
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        to_work.emplace(v, work_vertex());

    Work_mesh work;
    work.reserve(static_cast<typename Work_mesh::size_type>(to_work.size()), 0,
                 static_cast<typename Work_mesh::size_type>(component.size()));
    std::vector<vertex_descriptor> from_work; // work vertex index -> input vertex
    from_work.reserve(to_work.size());
    auto vpm = get(CGAL::vertex_point, mesh);
    for(vertex_descriptor v : vertices(mesh)) {
      auto it = to_work.find(v);
      if(it == to_work.end()) continue;
      const auto& p = get(vpm, v);
      it->second = work.add_vertex(Work_kernel::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                                        CGAL::to_double(p.z())));
      from_work.push_back(v);
    }
    // The faces in the order of faces(mesh) when the component is all of it.
    if(component.size() == static_cast<std::size_t>(num_faces(mesh)))
      component.assign(faces(mesh).begin(), faces(mesh).end());
    std::vector<work_vertex> corners_of_face;
    for(face_descriptor f : component) {
      corners_of_face.clear();
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        corners_of_face.push_back(to_work.at(v));
      if(work.add_face(corners_of_face) == Work_mesh::null_face())
        return Status(Status_code::non_manifold, "a face of the component cannot be added to a manifold copy");
    }

    std::vector<work_vertex> work_corners;
    for(std::size_t c = 0; c < given_corners_.size(); ++c) {
      auto it = to_work.find(given_corners_[c]);
      if(it == to_work.end())
        return Status(Status_code::corner_not_on_border,
                      "corner #" + std::to_string(c + 1) + " is not a vertex of the component of the border halfedge");
      work_corners.push_back(it->second);
    }

    Uv_atlas<Work_mesh> atlas(work);
    Four_sides<work_vertex> sides;
    Status status = run_parameterize_disc(work, work_corners, atlas, sides);
    if(!status) return status;

    typedef typename boost::property_traits<VertexUVMap>::value_type Uv;
    auto uv = atlas.vertex_uv_map();
    for(work_vertex w : vertices(work)) {
      const auto& p = get(uv, w);
      const vertex_descriptor v = from_work[static_cast<std::size_t>(w)];
      put(uvmap, v, Uv(p.x(), p.y()));
      put(vpmap, v, true);
    }
    for(work_vertex w : sides.corners)
      state_->corners.push_back(from_work[static_cast<std::size_t>(w)]);
    return status;
  }

  // parameterize_disc() with the library's defaults for what is CGAL::Default
  // here, so that this class follows the library's default distance and heap.
  // A map that still folds after the repair (numerically degenerate input
  // only) is `not_injective`, which CGAL callers see as ERROR_NO_1_TO_1_MAPPING.
  static Status run_parameterize_disc(const Work_mesh& work, const std::vector<work_vertex>& corners,
                                      Uv_atlas<Work_mesh>& atlas, Four_sides<work_vertex>& sides)
  {
    typedef typename CGAL::Default::Get<DistanceTag, Default_distance_tag>::type Distance;
    typedef typename CGAL::Default::Get<HeapTag, Fibonacci_heap_tag>::type Heap;
    Disc_parameterization_report<Work_mesh> report;
    // CGAL's uv map gets the canonical (u,v) on the unit square: no warps to fit.
    Disc_parameterization_options options;
    options.drawing.pieces = 0;
    Status status = parameterize_disc<Distance, Heap>(work, get(CGAL::vertex_point, work), corners, atlas, options, &report);
    if(status && report.repair.remaining_folded_faces > 0)
      status = Status(Status_code::not_injective,
                      internal::count_text(report.repair.remaining_folded_faces, "folded face"));
    sides = std::move(report.sides);
    return status;
  }

  std::vector<vertex_descriptor> given_corners_; // as given; unused unless corners_given_
  bool corners_given_ = false;                   // false: automatic corners
  std::shared_ptr<State> state_;
};

} // namespace diffuv

#endif // DIFFUV_CGAL_DIFFUSION_PARAMETERIZER_3_H
