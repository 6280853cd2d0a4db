#include <dlfl/errors.h>

namespace dlfl {
namespace {
std::string located(const std::string& message, const std::string& file, std::size_t line) {
  if (file.empty()) return message;
  if (line == 0) return file + ": " + message;
  return file + ":" + std::to_string(line) + ": " + message;
}
}  // namespace

IoError::IoError(const std::string& message, std::string file, std::size_t line)
    : Error(located(message, file, line)), file_(std::move(file)), line_(line) {}

}  // namespace dlfl
