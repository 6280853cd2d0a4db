#pragma once
// Internal to the operations that build a new mesh (replace operations): the input's named attributes on the
// result, with the values of the elements the result's elements stand for.

#include <span>

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl::detail {

/// Declares every named attribute of `from` on `to` (same kind, name and default), then gives each element of
/// `to` whose origin is an element of `from` of the attribute's kind that element's value: a vertex standing
/// for a vertex keeps its vertex attributes, a face for a face its face attributes, and so on; the others
/// read the default. `corners` holds the origins of `to`'s corners (indexed by corner handle; shorter is
/// none). O(size of `to` x attributes).
void carry_attributes(const Mesh& from, const Origins& origins, std::span<const Origin> corners, Mesh& to);

}  // namespace dlfl::detail
