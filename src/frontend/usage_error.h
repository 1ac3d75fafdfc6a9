// The errors a front end (the command line, the Python package) turns into a message for the
// user, and the helpers that raise them from the layers' results.
#pragma once

#include <stdexcept>
#include <utility>

#include "datomsim/result.h"

namespace datomsim::frontend {

// A bad value on the command line or in an input; the command line prints it and exits with
// status 1, Python raises it as datomsim.Error.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A check that ran and found a problem (e.g. counterexamples); exit status 1.
class CheckFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The value of a result, or a UsageError carrying its message.
template <typename T>
T unwrap(Result<T>&& result) {
  if (!result.ok()) throw UsageError(result.error());
  return std::move(result).value();
}

// Nothing, or a UsageError carrying the status's message.
inline void check(const Status& status) {
  if (!status.ok()) throw UsageError(status.error());
}

}  // namespace datomsim::frontend
