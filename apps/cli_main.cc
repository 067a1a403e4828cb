// The command line: its commands (command.h) and their exit status.
//
// Exit status: 0 success, 1 failure while running, 2 bad input (one line on
// stderr naming the problem and what would fix it).
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "apps/command.h"
#include "scene/scene.h"
#include "solvers/distributed/comm.h"

namespace vivp::apps {

int Main(int argc, char** argv) {
  CLI::App app{
      "vivp: structure-preserving time integration from the action "
      "(summation-by-parts variational IVP solver)"};
  app.require_subcommand(1);
  const std::vector<std::pair<std::string, vivp::apps::Runner>> commands = {
      {"spectrum", vivp::apps::AddSpectrumCommand(app)},
      {"converge", vivp::apps::AddConvergeCommand(app)},
      {"bea", vivp::apps::AddBeaCommand(app)},
      {"bench", vivp::apps::AddBenchCommand(app)},
      {"run", vivp::apps::AddRunCommand(app)},
      {"scene", vivp::apps::AddSceneCommand(app)},
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "vivp: error: " << e.what() << " (see 'vivp --help')\n";
    return 2;
  }
  // Under mpirun every rank meets the same bad input: rank 0 says so.
  auto report = [](const std::string& line, int status) {
    if (vivp::distributed::Comm::World().root()) std::cerr << line << "\n";
    return status;
  };
  try {
    // Every rank of an MPI run would do the same work and write the same
    // files: only a field scene's march is spread over them.
    if (vivp::distributed::Comm::World().size() > 1 &&
        !app.got_subcommand("run"))
      throw vivp::apps::UsageError(
          "only `vivp run` of a field scene runs on several ranks; run this "
          "command without mpirun");
    for (const auto& [name, run] : commands)
      if (app.got_subcommand(name)) return run();
  } catch (const vivp::scene::SceneError& e) {
    // Already FILE:LINE:COL: what is wrong; what is expected.
    return report(e.what(), 2);
  } catch (const vivp::apps::UsageError& e) {
    return report(std::string("vivp: error: ") + e.what(), 2);
  } catch (const std::invalid_argument& e) {
    return report(std::string("vivp: error: ") + e.what(), 2);
  } catch (const std::exception& e) {
    return report(std::string("vivp: failed: ") + e.what(), 1);
  }
  return 0;
}

}  // namespace vivp::apps
