#pragma once
// The exception hierarchy of the library. Every precondition violation throws one of these, with a message
// that names the offending element, file or field.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

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

namespace detail {
/// An InvalidArgument that also names something (a parameter, a suggested name), apart from its message.
class NamingError : public InvalidArgument {
 public:
  NamingError(const std::string& message, std::string name)
      : InvalidArgument(message), name_(std::move(name)) {}

 protected:
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};
}  // namespace detail

/// A named parameter of an operation or scheme is unknown, missing, of the wrong type or out of its range.
/// Made from (message, parameter); `parameter()` is its name (for a nested value, a path such as
/// "params.t").
class ParameterError : public detail::NamingError {
 public:
  using NamingError::NamingError;
  const std::string& parameter() const { return name(); }
};

/// A name (of an operation, a scheme) that nothing is registered under. Made from (message, suggestion): the
/// message lists what is known and, when a known name is close, suggests it ("did you mean 'honeycomb'?");
/// `suggestion()` is that name or empty.
class UnknownNameError : public detail::NamingError {
 public:
  using NamingError::NamingError;
  const std::string& suggestion() const { return name(); }
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
