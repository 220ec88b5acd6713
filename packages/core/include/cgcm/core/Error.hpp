#pragma once
// Error types. InputError is for a bad deck or argument (the message names the
// parameter and the allowed values); NumericalError for a failed evaluation
// that the load stepper may recover from by cutting the step back.
#include <stdexcept>
#include <string>

namespace cgcm {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An element turned inside out (J <= 0) during an evaluation.
struct InvertedElementError : NumericalError {
  using NumericalError::NumericalError;
};

}  // namespace cgcm
