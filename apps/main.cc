// vivp: trajectories of initial value problems from their action.
//
// Exit status: 0 success, 1 failure while running, 2 bad input (one line on
// stderr naming the problem and what would fix it).

namespace vivp::apps {
int Main(int argc, char** argv);  // cli_main.cc
}  // namespace vivp::apps

int main(int argc, char** argv) { return vivp::apps::Main(argc, argv); }
