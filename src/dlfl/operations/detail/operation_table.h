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
std::vector<OperationSpec> collapse_edge_operation_specs();   // collapse_edge.cpp
std::vector<OperationSpec> splice_corners_operation_specs();  // splice_corners.cpp
std::vector<OperationSpec> divide_edge_operation_specs();     // divide_edge.cpp
std::vector<OperationSpec> flip_edge_operation_specs();       // flip_edge.cpp
std::vector<OperationSpec> hole_flag_operation_specs();       // hole_flag.cpp (make_hole, fill_hole)

std::vector<OperationSpec> stellate_face_operation_specs();        // stellate_face.cpp
std::vector<OperationSpec> subdivide_face_operation_specs();       // subdivide_face.cpp
std::vector<OperationSpec> triangulate_operation_specs();          // triangulate.cpp
std::vector<OperationSpec> reverse_orientation_operation_specs();  // reverse_orientation.cpp
std::vector<OperationSpec> transform_operation_specs();            // transform.cpp

// Handles and connections (docs/modeling.md)
std::vector<OperationSpec> connect_edges_operation_specs();  // connect_edges.cpp
std::vector<OperationSpec> connect_faces_operation_specs();  // connect_faces.cpp

// Extrusions (docs/modeling.md)
std::vector<OperationSpec> extrude_face_operation_specs();  // extrude_face.cpp
std::vector<OperationSpec> inset_face_operation_specs();    // inset_face.cpp

// Shells and frames (docs/modeling.md)
std::vector<OperationSpec> crust_operation_specs();      // crust.cpp
std::vector<OperationSpec> rind_operation_specs();       // rind.cpp
std::vector<OperationSpec> wireframe_operation_specs();  // wireframe.cpp
std::vector<OperationSpec> columns_operation_specs();    // columns.cpp

// High genus (docs/modeling.md)
std::vector<OperationSpec> sierpinski_operation_specs();  // sierpinski.cpp
std::vector<OperationSpec> menger_operation_specs();      // menger.cpp

// Cutting (docs/modeling.md)
std::vector<OperationSpec>
cutting_operation_specs();  // cutting.cpp (truncate_vertex, chamfer_edge, cut_face)
std::vector<OperationSpec> plane_cut_operation_specs();  // plane_cut.cpp

// Cleanup and shape (docs/modeling.md)
std::vector<OperationSpec> dissolve_coplanar_operation_specs();  // dissolve_coplanar.cpp
std::vector<OperationSpec> remove_2gons_operation_specs();       // remove_2gons.cpp
std::vector<OperationSpec> remove_valence2_operation_specs();    // remove_valence2.cpp
std::vector<OperationSpec> planarize_operation_specs();          // planarize.cpp
std::vector<OperationSpec> hexagonalize_operation_specs();       // hexagonalize.cpp
std::vector<OperationSpec> smooth_operation_specs();             // smooth.cpp
std::vector<OperationSpec> spheralize_operation_specs();         // spheralize.cpp

// Hulls (docs/modeling.md)
std::vector<OperationSpec> convex_hull_operation_specs();    // convex_hull.cpp
std::vector<OperationSpec> dual_hull_operation_specs();      // dual_hull.cpp
std::vector<OperationSpec> multi_connect_operation_specs();  // multi_connect.cpp

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
    &collapse_edge_operation_specs,
    &splice_corners_operation_specs,
    &divide_edge_operation_specs,
    &flip_edge_operation_specs,
    &hole_flag_operation_specs,

    &stellate_face_operation_specs,
    &subdivide_face_operation_specs,
    &triangulate_operation_specs,
    &reverse_orientation_operation_specs,
    &transform_operation_specs,

    // Handles and connections
    &connect_edges_operation_specs,
    &connect_faces_operation_specs,

    // Extrusions
    &extrude_face_operation_specs,
    &inset_face_operation_specs,

    // Shells and frames
    &crust_operation_specs,
    &rind_operation_specs,
    &wireframe_operation_specs,
    &columns_operation_specs,

    // High genus
    &sierpinski_operation_specs,
    &menger_operation_specs,

    // Cutting
    &cutting_operation_specs,
    &plane_cut_operation_specs,

    // Cleanup and shape
    &dissolve_coplanar_operation_specs,
    &remove_2gons_operation_specs,
    &remove_valence2_operation_specs,
    &planarize_operation_specs,
    &hexagonalize_operation_specs,
    &smooth_operation_specs,
    &spheralize_operation_specs,

    // Hulls
    &convex_hull_operation_specs,
    &dual_hull_operation_specs,
    &multi_connect_operation_specs,
};
// clang-format on

}  // namespace dlfl::detail
