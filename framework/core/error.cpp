#include "framework/core/error.h"

namespace voroseal {

InputError::InputError(std::string file, long line, const std::string& message)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + message),
      file_(std::move(file)),
      line_(line),
      message_(message) {}

}  // namespace voroseal
