#pragma once
// Where the elements of a scheme's output come from: one element of the input for every output vertex, edge
// and face, so that a user can carry their own per-element data across a subdivision step.
// Every scheme function takes an optional `Origins*`; its header says what each output element's origin is,
// and docs/schemes.md tables them.

#include <cstdint>
#include <vector>

#include <dlfl/handles.h>

namespace dlfl {

/// One element of the input mesh: the element an output element stems from.
struct Origin {
  enum class Kind : std::uint8_t {
    none,    ///< no input element (a tombstone slot of the output)
    vertex,  ///< an input vertex (a vertex point, a face around an old vertex)
    edge,    ///< an input edge (an edge point, a face across an old edge)
    face,    ///< an input face (a face point, a shrunken copy of a face)
    corner,  ///< an input corner: a vertex in one face (a honeycomb or Doo-Sabin vertex)
  };
  Kind kind = Kind::none;
  std::uint32_t index = 0xFFFFFFFFu;  ///< the input handle's index

  VertexId vertex() const { return kind == Kind::vertex ? VertexId(index) : VertexId(); }
  EdgeId edge() const { return kind == Kind::edge ? EdgeId(index) : EdgeId(); }
  FaceId face() const { return kind == Kind::face ? FaceId(index) : FaceId(); }
  CornerId corner() const { return kind == Kind::corner ? CornerId(index) : CornerId(); }
  friend bool operator==(const Origin&, const Origin&) = default;
};

inline Origin origin_of(VertexId v) { return {Origin::Kind::vertex, v.index()}; }
inline Origin origin_of(EdgeId e) { return {Origin::Kind::edge, e.index()}; }
inline Origin origin_of(FaceId f) { return {Origin::Kind::face, f.index()}; }
inline Origin origin_of(CornerId c) { return {Origin::Kind::corner, c.index()}; }

/// The origin of every element of a scheme's output, indexed by output handle (sized by the output's
/// capacities; tombstone slots have Kind::none). Handles of the input are those of the mesh given to the
/// scheme, even when the scheme compacts a copy of it internally.
struct Origins {
  std::vector<Origin> vertices;
  std::vector<Origin> edges;
  std::vector<Origin> faces;

  Origin of(VertexId v) const { return v.index() < vertices.size() ? vertices[v.index()] : Origin{}; }
  Origin of(EdgeId e) const { return e.index() < edges.size() ? edges[e.index()] : Origin{}; }
  Origin of(FaceId f) const { return f.index() < faces.size() ? faces[f.index()] : Origin{}; }
};

}  // namespace dlfl
