#pragma once
// Internal to truncate_vertex, chamfer_edge and cut_face: cutting a "cap" off the mesh. A cap is a set of
// vertices with the edges among them that go with them (none for a vertex, the edge for an edge, the face's
// sides for a face). Every other edge leaving the cap is cut at `offset` of its length from the cap, a
// section edge joins consecutive cut points inside each face around the cap, and the cap (its vertices, its
// edges, the stubs to the cut points and the faces between) is deleted: one new face takes its place.
//
// For a cap of n vertices, i inner edges and m edges leaving it, the cap and the faces inside it form a disk,
// so the counts are V + m - n, E + m - i, F + 1 - (faces inside the cap). The Euler operators do it all
// through the Transaction: m subdivide_edge, one insert_edge per run of the cap along a face, then
// delete_edge and delete_vertex.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/cutting.h>
#include <dlfl/operations/detail/handle_selection.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/transaction.h>
#include <dlfl/parameters.h>

namespace dlfl::detail {

/// One element to cut off: its vertices and the edges that are removed with them.
struct Cap {
  std::vector<VertexId> vertices;
  std::vector<EdgeId> inner_edges;
  /// Faces whose every side is an inner edge (cut_face's face): they go with the cap.
  long inner_faces = 0;
  /// The element as messages name it ("v3", "e5", "f2").
  std::string label;
};

/// What a cut of caps does to the counts: V+vertices, E+edges, F+faces.
struct CapCounts {
  long vertices = 0, edges = 0, faces = 0;
};

/// Refuses, with ParameterError naming "offset", an offset that is not finite or not in (0, 0.5); and,
/// naming `parameter`: an element given twice, two caps sharing a vertex, a cap with fewer than two edges
/// leaving it, an edge leaving a cap that comes back to it, a face around the cap that would get a section
/// edge from a cut point to itself, cut points that would not be finite. Returns the counts of the cut.
/// O(the edges and faces around the caps).
CapCounts check_caps(const Mesh& mesh, std::string_view op, std::string_view parameter,
                     std::span<const Cap> caps, double offset);

/// Checks (as check_caps), then cuts every cap off, as one operation. The new faces are in the order of the
/// caps; a new face is a hole face when a hole face was around its cap (the cut then widens the boundary).
CutResult cut_caps(Transaction& tx, std::string_view op, std::string_view parameter,
                   std::span<const Cap> caps, double offset);

/// The parameter that holds the offset, for the three operations.
ParamSpec offset_param();

/// The outputs of a registered cut: `faces`, `vertices` and, when one element was given, `face`.
Params cut_outputs(const CutResult& cut, bool one_element);

/// One of the three cutting operations: its name, its two element parameters (`one` element or a list of
/// `many`, exactly one of them given) and how the elements it is given become caps, refusing those it cannot
/// cut with a ParameterError naming the parameter. The library functions and the registered operation of
/// each are this, with its own `caps_of`.
template <class H>
struct CapCutter {
  using CapsOf = std::vector<Cap> (*)(const Mesh& mesh, std::span<const H> elements,
                                      std::string_view parameter);
  std::string_view op;
  std::string_view one;
  std::string_view many;
  CapsOf caps_of;

  CutResult cut(Transaction& tx, std::span<const H> elements, double offset,
                std::string_view parameter) const {
    const std::vector<Cap> caps = caps_of(tx.mesh(), elements, parameter);
    return cut_caps(tx, op, parameter, caps, offset);
  }

  void check(const Mesh& mesh, std::span<const H> elements, double offset, std::string_view parameter) const {
    check_caps(mesh, op, parameter, caps_of(mesh, elements, parameter), offset);
  }

  /// The declaration: `one`, `many` (documented by `one_doc` and `many_doc`) and `offset`.
  OperationSpec spec(std::string doc, std::string one_doc, std::string many_doc, std::string counts) const {
    const CapCutter self = *this;
    auto selection = [self](const Params& p) { return selected_handles<H>(self.op, p, self.one, self.many); };
    return edit_operation(
        std::string(op), std::move(doc),
        {selection_param<H>(one, many, false, std::move(one_doc)),
         selection_param<H>(one, many, true, std::move(many_doc)), offset_param()},
        std::move(counts),
        [self, selection](Transaction& tx, const Params& p) {
          const HandleSelection<H> s = selection(p);
          return cut_outputs(self.cut(tx, s.handles, p.number("offset"), s.parameter),
                             s.parameter == self.one);
        },
        [self, selection](const Mesh& mesh, Params& p) {
          const HandleSelection<H> s = selection(p);
          self.check(mesh, s.handles, p.number("offset"), s.parameter);
        });
  }
};

}  // namespace dlfl::detail
