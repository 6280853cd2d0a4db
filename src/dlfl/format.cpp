#include <dlfl/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

namespace dlfl {

std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

namespace {
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}
}  // namespace

std::string closest_name(std::string_view name, std::span<const std::string> known) {
  std::string best;
  std::size_t best_distance = 0;
  for (const auto& k : known) {
    const std::size_t d = edit_distance(name, k);
    const std::size_t allowed = std::max<std::size_t>(1, std::max(name.size(), k.size()) / 3);
    if (d <= allowed && (best.empty() || d < best_distance)) {
      best = k;
      best_distance = d;
    }
  }
  return best;
}

std::string unknown_name_message(std::string_view kind, std::string_view name,
                                 std::span<const std::string> known, const std::string& suggestion) {
  std::string message = "unknown " + std::string(kind) + " '" + std::string(name) + "'";
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  message += " (";
  if (!suggestion.empty()) message += "did you mean '" + suggestion + "'?; ";
  message += list.empty() ? std::string("none is known") : "known: " + list;
  return message + ")";
}

}  // namespace dlfl
