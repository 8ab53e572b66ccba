#pragma once

#include <stdexcept>
#include <string>

namespace roadscale {

// Every error a user can cause (bad file, bad option, bad model) is reported as an
// Error. The command-line tool prints what() on one line and exits non-zero, so the
// message must name the file, the line when there is one, and what was expected.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "PATH: MESSAGE" or "PATH:LINE: MESSAGE" (LINE counts from 1; 0 means no line).
[[noreturn]] void ThrowFileError(const std::string& path, int line, const std::string& message);
[[noreturn]] void ThrowFileError(const std::string& path, const std::string& message);

// The system's reason for an errno value in the style of the other messages, lower case:
// "permission denied", "no such file or directory".
std::string ErrnoReason(int error_number);

// Throws Error("invalid option NAME: MESSAGE") unless the condition holds. Used by the
// Check() method of every options struct.
void CheckOption(bool condition, const char* name, const std::string& message);

}  // namespace roadscale
