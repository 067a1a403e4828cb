// vivp: trajectories of initial value problems from their action.
//
// Exit status: 0 success, 1 failure while running, 2 bad input (one line on
// stderr naming the problem and what would fix it).
//
// Started by mpirun (`mpirun -np N vivp run SCENE`), the program starts MPI
// for the whole run and a field scene's space is spread over the ranks
// (solvers/distributed/comm.h); otherwise MPI is never touched.
#include "solvers/distributed/comm.h"

namespace vivp::apps {
int Main(int argc, char** argv);  // cli_main.cc
}  // namespace vivp::apps

int main(int argc, char** argv) {
  const vivp::distributed::Session mpi(&argc, &argv);
  return vivp::apps::Main(argc, argv);
}
