#pragma once
// The exception hierarchy of the library. Every precondition violation throws one of these, with a message
// that names the offending element, file or field.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace dlfl {

/// Base of every exception the library throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An argument is out of its documented range: a removed or out-of-range handle, a bad parameter value.
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

/// An operation would break the 2-manifold structure or is not defined on the given elements (for example
/// `delete_vertex` on a vertex that still has edges, or an edge that would be a self-loop).
class TopologyError : public Error {
 public:
  using Error::Error;
};

/// Reading or writing a file failed, or its content is malformed. `file()` and `line()` locate the problem
/// when known (`line() == 0` when no line applies, as in binary files).
class IoError : public Error {
 public:
  IoError(const std::string& message, std::string file = {}, std::size_t line = 0);
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }

 private:
  std::string file_;
  std::size_t line_;
};

}  // namespace dlfl
