#pragma once
// Numbers and names in messages: every message of the library formats numbers the same way, so that a value
// that is not allowed is shown as it is (1.000000001 stays 1.000000001, not "1").

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/errors.h>

namespace dlfl {

/// The shortest decimal text that reads back as exactly `x` ("0.5", "1.000000001", "1e+300", "nan", "inf").
std::string format_number(double x);

/// The known name closest to `name` by edit distance, if it is close enough to be a likely misspelling (at
/// most a third of the longer name's letters differ); empty otherwise.
std::string closest_name(std::string_view name, std::span<const std::string> known);

/// "unknown KIND 'name' (did you mean 'x'?; known: a, b, c)" as thrown by the registries.
std::string unknown_name_message(std::string_view kind, std::string_view name,
                                 std::span<const std::string> known, const std::string& suggestion);

/// The names of a registry's entries (anything with a `name`), in its order.
template <class Table>
std::vector<std::string> names_of(const Table& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.push_back(entry.name);
  return names;
}

/// The registry entry called `name`. Throws UnknownNameError with `unknown_name_message`, `kind` naming the
/// registry ("scheme"), and the closest name as its suggestion.
template <class Table>
const auto& find_named(const Table& table, std::string_view kind, std::string_view name) {
  for (const auto& entry : table) {
    if (entry.name == name) return entry;
  }
  const std::vector<std::string> names = names_of(table);
  const std::string suggestion = closest_name(name, names);
  throw UnknownNameError(unknown_name_message(kind, name, names, suggestion), suggestion);
}

}  // namespace dlfl
