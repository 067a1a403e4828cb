// A field's march with space spread over the ranks of an MPI run
// (docs/distributed.md): SolveField (solvers/spacetime/solve.h) with the
// window of one rank's slab (window.h). Every rank passes the whole initial
// slice and gets the march's status, end state and reports; the kept slices
// are gathered on rank 0 only.
//
//   const auto& comm = vivp::distributed::Comm::World();
//   auto s = vivp::distributed::SolveField(comm, density, space, grid,
//                                          phi0, pi0);
//   // on comm.root(): s.phi, as SolveField's
//
// What it refuses, with the fix: an interval axis, a grid whose planes or
// plane do not divide over the ranks, slabs thinner than the halo, error
// control, checkpoints, boundary data and the sparse-LU solver (docs/
// distributed.md §4 says why each is not here yet).
#pragma once

#include <memory>
#include <stdexcept>
#include <vector>

#include "solvers/distributed/comm.h"
#include "solvers/distributed/window.h"
#include "solvers/spacetime/solve.h"

namespace vivp::distributed {

template <class Density>
spacetime::FieldSolution SolveField(const Comm& comm, const Density& density,
                                    const sbp::SpaceGrid<double>& space,
                                    const spacetime::FieldGrid& grid,
                                    std::vector<double> phi0,
                                    std::vector<double> pi0,
                                    spacetime::FieldSolveOptions options = {}) {
  auto refuse = [](const std::string& what) {
    throw std::invalid_argument(
        what +
        " is not built across ranks: run it on one process, without mpirun");
  };
  if (options.tolerance.enabled()) refuse("error control (a tolerance)");
  if (options.on_checkpoint || options.resume) refuse("a checkpointed march");
  if (options.linear != spacetime::WindowLinearSolver::kModes)
    refuse("the sparse-LU window solver");
  if (options.boundary.left.kind != action::BoundaryKind::kNatural ||
      options.boundary.right.kind != action::BoundaryKind::kNatural ||
      !options.boundary.faces.empty())
    refuse("boundary data");
  // The grid against the ranks, before anything is solved.
  const Slab check(comm, space);
  options.keep_field = options.keep_field && comm.root();
  if (!comm.root()) options.on_window = {};
  auto s = spacetime::SolveFieldWith(
      density, space, grid, std::move(phi0), std::move(pi0), options,
      [&](const spacetime::FieldWindowOptions& wo, const std::vector<double>&,
          const std::vector<double>&) {
        return std::make_unique<DistributedWindow<Density>>(comm, density,
                                                            space, grid.op, wo);
      });
  s.ranks = comm.size();
  return s;
}

}  // namespace vivp::distributed
