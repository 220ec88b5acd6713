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
//
// In a distributed run no rank holds a whole vector: the ranks send rank 0
// their entries a window at a time as it writes (solver::streamToRoot), and on
// a restart every rank reads the file a window at a time, keeping its own
// entries. The file is the same whoever writes it.
#include <cstdint>
#include <string>
#include <vector>

#include "cgcm/assembly/TpetraTypes.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/solver/LoadPoint.hpp"
#include "cgcm/solver/LoadStepper.hpp"
#include "cgcm/solver/RootStream.hpp"

namespace cgcm::solver {

struct Checkpoint {
  StepperState stepper;
  Real lastDisplacement = 0.0;  ///< the continuity check's reference u
  int exodusSteps = 0;  ///< steps in results.e (0 without Exodus output)
  std::vector<LoadPoint> curve;
  /// By global dof (previous: empty unless stepper.havePrevious): what the one-process forms below write
  /// and read; the distributed ones leave them empty and read and write the ranks' vectors.
  std::vector<Real> u, previous;
  std::uint64_t unknowns = 0;  ///< the length of u in the file (readCheckpoint, readCheckpointHeader)
};

/// The file in `dir`.
std::string checkpointPath(const std::string& dir);

/// Writes `c` with its vectors atomically (one process). False if the disk refused (the previous
/// checkpoint, if any, is left as it was).
bool writeCheckpoint(const std::string& dir, const Checkpoint& c);

/// There is no checkpoint to read: the file cannot be opened.
struct MissingCheckpoint : InputError {
  using InputError::InputError;
};

/// Reads the checkpoint of `dir` with its vectors (one process). Throws
/// MissingCheckpoint if there is none, InputError naming the file if it is
/// damaged (its checksum does not match: truncated or changed), of another
/// format version, or not a checkpoint.
Checkpoint readCheckpoint(const std::string& dir);

/// The distributed form of writeCheckpoint: `c`'s header and curve (rank 0's), u and, if not null,
/// previous streamed from the ranks to rank 0 (streamToRoot, `windowBytes` at a time), which writes the
/// same file. Returns on every rank whether rank 0 wrote it. Collective.
bool writeCheckpoint(const assembly::Comm& comm, const std::string& dir, const Checkpoint& c, const assembly::Vector& u,
                     const assembly::Vector* previous, std::size_t windowBytes = kRootStreamWindowBytes);

/// The checkpoint of `dir` without its vectors' values (c.unknowns: u's length): the file checked
/// whole and read a window at a time. Throws as readCheckpoint.
Checkpoint readCheckpointHeader(const std::string& dir, std::size_t windowBytes = kRootStreamWindowBytes);

/// The vectors of `dir`'s checkpoint into this rank's entries of u and, if not null, previous: every rank
/// reads the file (checked whole first) a window at a time. Throws as readCheckpoint, and InputError if
/// a vector's length in the file is not the vector's (nothing is written to the vectors then).
void readCheckpointVectors(const std::string& dir, assembly::Vector& u, assembly::Vector* previous,
                           std::size_t windowBytes = kRootStreamWindowBytes);

}  // namespace cgcm::solver
