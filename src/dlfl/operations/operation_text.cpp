#include <dlfl/operations/operation_text.h>

#include <vector>

#include <dlfl/errors.h>

namespace dlfl {
namespace {

// Whitespace-separated words; quotes group, and are removed.
std::vector<std::string> words(std::string_view text) {
  std::vector<std::string> out;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (char ch : text) {
    if (quote) {
      if (ch == quote) {
        quote = 0;
      } else {
        word += ch;
      }
    } else if (ch == '\'' || ch == '"') {
      quote = ch;
      in_word = true;
    } else if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') {
      if (in_word) out.push_back(std::move(word));
      word.clear();
      in_word = false;
    } else {
      word += ch;
      in_word = true;
    }
  }
  if (quote) throw InvalidArgument("operation '" + std::string(text) + "': unterminated quote");
  if (in_word) out.push_back(std::move(word));
  return out;
}

}  // namespace

std::pair<std::string, Params> parse_operation_text(std::string_view text) {
  const std::vector<std::string> items = words(text);
  if (items.empty())
    throw InvalidArgument("an operation needs a name, e.g. 'insert_edge corner1=0 corner2=2'");
  std::pair<std::string, Params> op{items[0], {}};
  for (std::size_t i = 1; i < items.size(); ++i) {
    const auto eq = items[i].find('=');
    if (eq == std::string::npos || eq == 0) {
      throw ParameterError(op.first + ": '" + items[i] + "' is not of the form name=value", items[i]);
    }
    const std::string key = items[i].substr(0, eq);
    Value value(items[i].substr(eq + 1));
    const auto dot = key.find('.');
    Params* target = &op.second;
    std::string field = key;
    Params nested;
    if (dot != std::string::npos) {
      // A dotted key: the nested set is rebuilt with the new entry (Values are immutable).
      const std::string outer = key.substr(0, dot);
      field = key.substr(dot + 1);
      if (outer.empty() || field.empty()) {
        throw ParameterError(op.first + ": '" + key + "' is not a parameter name", key);
      }
      if (auto it = op.second.find(outer); it != op.second.end()) {
        if (it->second.kind() != Value::Kind::params) {
          throw ParameterError(op.first + ": parameter " + outer + " given twice", outer);
        }
        nested = it->second.as_params();
      }
      if (nested.has(field)) throw ParameterError(op.first + ": parameter " + key + " given twice", key);
      nested[field] = std::move(value);
      op.second[outer] = std::move(nested);
      continue;
    }
    if (target->has(field)) throw ParameterError(op.first + ": parameter " + field + " given twice", field);
    (*target)[field] = std::move(value);
  }
  return op;
}

}  // namespace dlfl
