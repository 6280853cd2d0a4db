#pragma once
// Internal to the operation registry: the table of operation files. Each file declares its operations in a
// function defined next to their implementation; adding a file of operations adds its declaration and its
// entry here, and nothing else.

#include <array>
#include <vector>

#include <dlfl/operations/operation.h>

namespace dlfl::detail {

std::vector<OperationSpec> euler_operation_specs();       // euler_operations.cpp
std::vector<OperationSpec> face_point_operation_specs();  // set_face_point.cpp
std::vector<OperationSpec> attribute_operation_specs();   // set_attribute.cpp
std::vector<OperationSpec> whole_mesh_operation_specs();  // whole_mesh_operations.cpp
std::vector<OperationSpec> history_operation_specs();     // history_operations.cpp

// Local editing (docs/modeling.md)

// Handles and connections (docs/modeling.md)

// Extrusions (docs/modeling.md)
std::vector<OperationSpec> extrude_face_operation_specs();  // extrude_face.cpp
std::vector<OperationSpec> inset_face_operation_specs();    // inset_face.cpp

// One entry per line, grouped as the declarations above (kept out of clang-format so that adding one
// entry touches one line).
// clang-format off
inline constexpr std::array operation_files = {
    &euler_operation_specs,
    &face_point_operation_specs,
    &attribute_operation_specs,
    &whole_mesh_operation_specs,
    &history_operation_specs,

    // Local editing

    // Handles and connections

    // Extrusions
    &extrude_face_operation_specs,
    &inset_face_operation_specs,
};
// clang-format on

}  // namespace dlfl::detail
