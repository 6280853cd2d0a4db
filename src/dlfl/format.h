#pragma once
// Numbers and names in messages: every message of the library formats numbers the same way, so that a value
// that is not allowed is shown as it is (1.000000001 stays 1.000000001, not "1").

#include <span>
#include <string>
#include <string_view>

namespace dlfl {

/// The shortest decimal text that reads back as exactly `x` ("0.5", "1.000000001", "1e+300", "nan", "inf").
std::string format_number(double x);

/// The known name closest to `name` by edit distance, if it is close enough to be a likely misspelling (at
/// most a third of the longer name's letters differ); empty otherwise.
std::string closest_name(std::string_view name, std::span<const std::string> known);

/// "unknown KIND 'name' (did you mean 'x'?; known: a, b, c)" as thrown by the registries.
std::string unknown_name_message(std::string_view kind, std::string_view name,
                                 std::span<const std::string> known, const std::string& suggestion);

}  // namespace dlfl
