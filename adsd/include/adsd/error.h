#pragma once
/// \file
/// \brief The one exception type the library throws for bad user input.

#include <stdexcept>
#include <string>

namespace adsd {

/// \brief Bad input from the user: a mesh, a pose, an option or a file that cannot be used.
///
/// The message names what is wrong and where (file, line, field, index), in one line, so that a
/// command-line program can print it as it is. Our own bugs are assertions, never this type.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace adsd
