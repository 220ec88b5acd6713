#pragma once
// What a run writes for each accepted state: the contact responses (gap on
// the axis, contact radius), the load-curve row, the force on every body, the
// Exodus step and a progress line.
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "cgcm/app/Results.hpp"
#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/io/CsvWriter.hpp"
#include "cgcm/solver/Checkpoint.hpp"
#include "cgcm/solver/PathFollower.hpp"

namespace cgcm::app {

/// Gap on the axis and contact radius of a two-body contact state.
class ContactProbe {
 public:
  ContactProbe(const mesh::ContactGeometry& c, const mesh::Mesh& m, assembly::Problem& problem);

  /// Distance along the axis between the apex nodes. Collective.
  Real gap(const assembly::Vector& u) const;

  /// Radial position where the upper surface is first farther than the
  /// contact distance from the lower surface (0 if the apex already is): in
  /// 2D the radius x, in 3D the distance from the vertical line through the
  /// upper apex. Collective.
  Real contactRadius(const assembly::Vector& u) const;

 private:
  mesh::ContactGeometry c_;
  const mesh::Mesh& mesh_;
  assembly::Problem& problem_;
  LocalIndex upper_, lower_;
};

/// Turns converged states into load_curve.csv rows (flushed, so a run that
/// stops leaves a valid file), body_forces.csv rows, Exodus steps and
/// progress lines.
class Recorder {
 public:
  /// `resume` (a restart): continues the files of `dir` after the checkpoint's
  /// last row (later rows, written after it, are dropped) and starts the curve
  /// with the checkpoint's rows.
  /// `eigenvalues` (Output/Eigenvalues): the columns negative_eigenvalues, eigenvalue_1 .. _n,
  /// stable_by_folds and branch_point, and the critical mode in results.e; 0: none. `foldCurve`
  /// (LOCA/Bifurcation/Type = Turning Point): the column fold_curve, 1 on the rows of the fold followed.
  Recorder(const solver::ProblemSetup& setup, const solver::Discretization& disc, const ContactProbe* probe,
           const std::string& dir, bool exodus, int parameterIndex, bool print, std::ostream& log,
           const solver::Checkpoint* resume = nullptr, int eigenvalues = 0, bool foldCurve = false);

  /// Steps in results.e so far (rank 0; 0 without Exodus output).
  int exodusSteps() const { return results_ ? results_->numSteps() : 0; }
  /// Wall time of results.e: its mesh (before the path), its steps (0 without the file).
  double resultsMeshSeconds() const { return results_ ? results_->meshSeconds() : 0.0; }
  double resultsStepSeconds() const { return results_ ? results_->stepSeconds() : 0.0; }

  /// Records an accepted state of the path (its step, flags and solver figures with it). Collective.
  void record(const solver::PathState& state);

  std::vector<solver::LoadPoint> curve;

 private:
  const solver::ProblemSetup& setup_;
  const mesh::Mesh& mesh_;  ///< the mesh the problem assembles (solver::Discretization::mesh)
  solver::ModelEvaluator& model_;
  const ContactProbe* probe_;
  int parameterIndex_, eigenvalues_;
  bool foldCurve_, root_, print_;
  std::ostream& log_;
  assembly::Vector f_;
  std::vector<std::string> columns_;
  std::unique_ptr<io::CsvWriter> csv_, bodyCsv_;
  std::unique_ptr<ResultsWriter> results_;
};

}  // namespace cgcm::app
