#pragma once
// Internal to the operation registry: the declaration function of each operation, defined next to its
// implementation and listed once in operation_registry.cpp.

#include <vector>

#include <dlfl/operations/operation.h>

namespace dlfl::detail {

// The kernel's Euler operators (euler_operations.cpp).
std::vector<OperationSpec> euler_operation_specs();
// set_face_point (set_face_point.cpp).
std::vector<OperationSpec> face_point_operation_specs();
// load, mesh, subdivide (whole_mesh_operations.cpp).
std::vector<OperationSpec> whole_mesh_operation_specs();
// undo, redo, begin_group, end_group, clear_history (history_operations.cpp).
std::vector<OperationSpec> history_operation_specs();

}  // namespace dlfl::detail
