#pragma once
// OpenMesh's mesh types for the peer benchmarks: double-precision points (as the other libraries use) and no
// attributes beyond the defaults, so no normals are kept up to date.

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace dlfl::bench {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

using OmPolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;
using OmTriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

}  // namespace dlfl::bench
