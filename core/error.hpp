// dartcheck's errors: one hierarchy, so that the command line turns each
// kind into its exit status in one place (cli/command_line.cpp) and no
// library lets a standard exception of its own choosing cross its
// boundary.
//
//   Error                  every error dartcheck throws
//   ├── ValueError         a value the papers' definitions do not allow
//   ├── InputError         the same with where it was read (exit 2)
//   │   └── UsageError     ... in the command's arguments (exit 2)
//   ├── OutputError        an output that could not be written (exit 4)
//   └── InternalError      a broken invariant: a defect of dartcheck (exit 3)
//
// (InputError and UsageError: core/input_error.hpp; OutputError:
// core/output_file.hpp. AtOffset<Base> adds a byte offset in a text read
// inside a longer one: TermError, JerboaCodeError, OrbitNotationError.)
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace dartcheck {

/// Every error dartcheck throws; what() is a sentence for the user.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A value that a definition of the papers does not allow (a rule whose
/// hooks do not cover L, a word that does not parse, a modification that
/// would not give a map), found by the function it was given to, which
/// does not know where it was read: the reader that knows rethrows it as
/// an InputError at that position. One that reaches the command line is
/// reported as bad input (exit 2) without a position.
class ValueError : public Error {
 public:
  using Error::Error;
};

/// A broken invariant of dartcheck itself (a table out of step with its
/// map, a walk that does not end): never the input's fault. The command
/// line reports it as a defect of dartcheck (exit 3).
class InternalError : public Error {
 public:
  using Error::Error;
};

/// An error at a byte of a text that was read inside a longer one (a term
/// in a catalog, Java code in a .jme, an orbit type in a term): `offset`
/// is 0-based in that text, and the caller that knows where the text
/// starts turns it into a position.
template <class Base>
class AtOffset : public Base {
 public:
  AtOffset(std::size_t offset, const std::string& message) : Base(message), offset_(offset) {}
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

}  // namespace dartcheck
