// Error categories of voroseal. Each is thrown where the problem is found and caught once,
// in the CLI (or the Python module), where it becomes a message and an exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace voroseal {

/// A file that cannot be read: malformed, truncated, inconsistent counts, bad indices.
/// what() is "file:line: message" (line 0 when the problem is not tied to one line).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, long line, const std::string& message);
  const std::string& file() const { return file_; }
  long line() const { return line_; }
  /// The message without the "file:line: " prefix.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  long line_;
  std::string message_;
};

/// A structural model that violates what an algorithm requires (not sealed, no regions, ...).
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A parameter out of range, of the wrong type, or unknown.
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A mesher (remesher, TetGen) that could not produce a valid result.
class MesherError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An output that could not be written (permissions, disk full, would overwrite an input).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace voroseal
