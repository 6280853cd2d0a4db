#pragma once
// Strong 32-bit handle types for the elements of a DLFL mesh.

#include <compare>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>

namespace dlfl {

/// A 32-bit index into one of the mesh's element arrays. The tag keeps vertex, edge, face and corner handles
/// from being mixed up; a default-constructed handle is invalid.
template <class Tag>
struct Handle {
  static constexpr std::uint32_t invalid_index = 0xFFFFFFFFu;

  std::uint32_t value = invalid_index;

  constexpr Handle() = default;
  constexpr explicit Handle(std::uint32_t index) : value(index) {}

  /// True unless this is the invalid (default) handle. Says nothing about whether the element still exists.
  constexpr bool valid() const { return value != invalid_index; }
  /// The array index of the element.
  constexpr std::uint32_t index() const { return value; }

  constexpr auto operator<=>(const Handle&) const = default;
};

using VertexId = Handle<struct VertexTag>;
using EdgeId = Handle<struct EdgeTag>;
using FaceId = Handle<struct FaceTag>;
using CornerId = Handle<struct CornerTag>;

/// The four element kinds of a mesh, in the order `Mesh::attributes()` sorts them.
enum class ElementKind : std::uint8_t { vertex, edge, face, corner };

/// The element kind a handle type names: `element_kind_v<FaceId> == ElementKind::face`.
template <class H>
inline constexpr ElementKind element_kind_v = ElementKind::vertex;
template <>
inline constexpr ElementKind element_kind_v<EdgeId> = ElementKind::edge;
template <>
inline constexpr ElementKind element_kind_v<FaceId> = ElementKind::face;
template <>
inline constexpr ElementKind element_kind_v<CornerId> = ElementKind::corner;

/// True for the four handle types.
template <class H>
inline constexpr bool is_handle_v = std::is_same_v<H, VertexId> || std::is_same_v<H, EdgeId> ||
                                    std::is_same_v<H, FaceId> || std::is_same_v<H, CornerId>;

/// Short names used in messages: "v12", "e3", "f7", "c40"; "v-" for an invalid handle.
std::string to_string(VertexId v);
std::string to_string(EdgeId e);
std::string to_string(FaceId f);
std::string to_string(CornerId c);
/// "vertex", "edge", "face" or "corner".
const char* to_string(ElementKind kind);

}  // namespace dlfl

template <class Tag>
struct std::hash<dlfl::Handle<Tag>> {
  std::size_t operator()(dlfl::Handle<Tag> h) const noexcept { return std::hash<std::uint32_t>{}(h.value); }
};
