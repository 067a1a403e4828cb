// Field data as HDF5 files (The HDF Group's library, its C interface), for
// a person with h5dump and for a program:
//
//   checkpoint   a stopped march (solvers/spacetime/checkpoint.h): the
//                run's settings and the boundary's node and time as
//                attributes of the root group, the hand-off state as the
//                datasets /phi and /phi_t, and what carries to the next
//                window under /carry. Written to PATH.tmp and renamed, so
//                that a run killed while writing leaves the last complete
//                checkpoint.
//   slices       kept slices of a run: /t (the times), /phi and /phi_t of
//                shape slices × N_{d−1} × … × N_0 × m (axis 0 fastest, as
//                the grid's flat index), the grid's axes as attributes.
//
// Every failure (a file that cannot be created or read, a dataset missing
// or of the wrong size) throws std::runtime_error naming the file and the
// part.
#pragma once

#include <string>
#include <vector>

#include "core/sbp/space_grid.h"
#include "solvers/spacetime/checkpoint.h"

namespace vivp::scene {

void WriteCheckpoint(const std::string& path,
                     const spacetime::FieldCheckpoint& c);
spacetime::FieldCheckpoint ReadCheckpoint(const std::string& path);

// t: the slices' times; phi, phi_t: slice-major, value (s·N + j)·m + a;
// phi_t empty: no /phi_t (a charged field's values, which are not a state).
// Refuses to overwrite an existing file.
void WriteFieldSlices(const std::string& path,
                      const sbp::SpaceGrid<double>& grid, int m,
                      const std::vector<double>& t,
                      const std::vector<double>& phi,
                      const std::vector<double>& phi_t);

}  // namespace vivp::scene
