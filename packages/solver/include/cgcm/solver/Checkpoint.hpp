#pragma once
// checkpoint.bin: the last accepted state of a displacement-controlled run,
// enough to go on exactly where it stood: the load stepper's state (segment,
// u, next increment, step count, the secant predictor's previous state), the
// continuity check's last u, the load-curve rows so far, the Exodus steps
// written, and the displacement vectors (by global dof). Written by rank 0
// after every accepted state, through a temporary file and a rename, so a run
// killed at any moment leaves either the previous checkpoint or the new one,
// never a torn file. The file ends with a CRC-32 of all its bytes before it
// (format 2, magic "cgcmckp2"): a file cut or changed after the write is
// refused on reading.
#include <string>
#include <vector>

#include "cgcm/assembly/TpetraTypes.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/solver/LoadPoint.hpp"
#include "cgcm/solver/LoadStepper.hpp"

namespace cgcm::solver {

struct Checkpoint {
  StepperState stepper;
  Real lastDisplacement = 0.0;  ///< the continuity check's reference u
  int exodusSteps = 0;  ///< steps in results.e (0 without Exodus output)
  std::vector<LoadPoint> curve;
  std::vector<Real> u, previous;  ///< by global dof (previous: empty unless stepper.havePrevious)
};

/// The file in `dir`.
std::string checkpointPath(const std::string& dir);

/// Writes atomically (rank 0 only). False if the disk refused (the previous
/// checkpoint, if any, is left as it was).
bool writeCheckpoint(const std::string& dir, const Checkpoint& c);

/// There is no checkpoint to read: the file cannot be opened.
struct MissingCheckpoint : InputError {
  using InputError::InputError;
};

/// Reads the checkpoint of `dir` (every rank reads the file). Throws
/// MissingCheckpoint if there is none, InputError naming the file if it is
/// damaged (its checksum does not match: truncated or changed), of another
/// format version, or not a checkpoint.
Checkpoint readCheckpoint(const std::string& dir);

/// A distributed vector gathered on rank 0 in global dof order, and back.
class RootGather {
 public:
  explicit RootGather(const Teuchos::RCP<const assembly::Map>& owned);
  /// All values on rank 0, empty elsewhere. Collective.
  std::vector<Real> gather(const assembly::Vector& x);
  /// x from `values`, every dof in global order, given on every rank (rank 0's are used; a
  /// wrong length throws InputError on every rank). Collective.
  void scatter(const std::vector<Real>& values, assembly::Vector& x);
  /// The gathered vector of the last gather (rank 0: every dof).
  const assembly::Vector& all() const { return *all_; }

 private:
  Teuchos::RCP<const assembly::Import> import_;
  Teuchos::RCP<assembly::Vector> all_;
};

}  // namespace cgcm::solver
