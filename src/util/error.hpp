// Error types shared by the whole library.
#pragma once

#include <stdexcept>
#include <string>

namespace hoct {

// Any failure the user can act on: bad input, inconsistent mesh, ill-posed request.
// The message is complete and user-facing (file, line or cell, what is wrong).
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Malformed or unsupported input file. Readers prefix the message with the file name
// (and line or byte offset where known).
class InputError : public Error {
public:
  using Error::Error;
};

} // namespace hoct
