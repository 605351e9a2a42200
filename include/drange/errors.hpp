// drange/errors.hpp: the typed exceptions thrown by the library.
//
// Every message names the problem precisely (file, line, value, dimension); the `drange`
// command prints the message and exits with the code documented in `drange --help`.
#pragma once

#include <stdexcept>
#include <string>

namespace drange {

// Base of every exception drange throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The input cannot be read: unreadable path, malformed line, wrong count, NaN or infinite
// coordinate, inconsistent dimension. The message names the file and the line.
class InputError : public Error {
 public:
  using Error::Error;
};

// The input is well formed but has no d-dimensional triangulation: fewer than d+1 distinct
// points, or all points in one hyperplane (the message gives the dimension of their hull).
class DegenerateInputError : public Error {
 public:
  using Error::Error;
};

// A caller passed an invalid argument to the library (bad dimension, unknown option name).
class UsageError : public Error {
 public:
  using Error::Error;
};

// An invariant of the engine failed: a bug in drange, never a property of the input. The
// engine stops at once rather than return, or keep computing, a wrong result (for example,
// more simplices than any triangulation of the points can have).
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace drange
