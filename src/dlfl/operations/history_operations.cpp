// The operations on an editor's history. They are declared here, with the others, so that listings, logs
// and `dlfl edit` know them; the Editor carries them out (dlfl/history/editor.h).

#include <dlfl/operations/detail/operation_table.h>

namespace dlfl::detail {

std::vector<OperationSpec> history_operation_specs() {
  return {
      history_operation("undo", "undoes the latest entry of the history"),
      history_operation("redo", "redoes the latest undone entry"),
      history_operation("begin_group",
                        "starts a group: everything until the matching end_group is one undo entry",
                        {param("label", ParamType::text, "", "the entry's label in the history")}),
      history_operation("end_group", "ends the group begun last"),
      history_operation("clear_history", "forgets every undo and redo entry"),
  };
}

}  // namespace dlfl::detail
