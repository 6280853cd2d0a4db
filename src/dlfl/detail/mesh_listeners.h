#pragma once
// The containers attached to a mesh (`MeshData`), which `Mesh::compact()` tells how handles moved.
//
// The mesh creates the registry when the first container attaches and owns it through a shared_ptr; the
// registry moves with the mesh's data (move, swap) and is not copied (a copied mesh starts with none).
// Containers hold a weak_ptr, so one that outlives its mesh notices and simply stops following it.
// Attaching and detaching are not synchronised: see `MeshData`.

#include <algorithm>
#include <memory>
#include <vector>

#include <dlfl/compact_map.h>

namespace dlfl {
class Mesh;
}

namespace dlfl::detail {

/// What a container implements to follow compaction.
class CompactListener {
 public:
  virtual void on_compact(const CompactMap& map) = 0;

 protected:
  ~CompactListener() = default;
};

/// The listeners of one mesh.
struct MeshListeners {
  /// The mesh whose data this registry follows; `Mesh`'s move operations keep it current.
  const Mesh* mesh = nullptr;
  std::vector<CompactListener*> listeners;

  void add(CompactListener* listener) { listeners.push_back(listener); }
  void remove(CompactListener* listener) {
    const auto it = std::find(listeners.begin(), listeners.end(), listener);
    if (it == listeners.end()) return;
    *it = listeners.back();
    listeners.pop_back();
  }
  void replace(CompactListener* from, CompactListener* to) {
    std::replace(listeners.begin(), listeners.end(), from, to);
  }
  void compact(const CompactMap& map) const {
    for (CompactListener* listener : listeners) listener->on_compact(map);
  }
};

/// The mesh's member that holds its registry. Copying gives an empty slot, and assigning a copy drops the
/// target's registry (its containers detach); moving carries the registry along.
struct ListenerSlot {
  ListenerSlot() = default;
  ListenerSlot(const ListenerSlot&) {}
  ListenerSlot& operator=(const ListenerSlot& other) {
    if (this != &other) registry.reset();
    return *this;
  }
  ListenerSlot(ListenerSlot&&) noexcept = default;
  ListenerSlot& operator=(ListenerSlot&&) noexcept = default;

  std::shared_ptr<MeshListeners> registry;
};

}  // namespace dlfl::detail
