// Running the `vivp` executable from the CLI tests: one shell command,
// stdout and stderr captured separately, exit status decoded.
#pragma once

#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace vivp::testing {

struct CliRun {
  int status;  // exit status; -1 when killed by a signal
  std::string out, err;
};

// Runs `exe args` through /bin/sh (args may hold redirections of stdin).
inline CliRun RunCommand(const std::string& exe, const std::string& args) {
  char err_file[] = "/tmp/vivp_cli_test_XXXXXX";
  const int fd = mkstemp(err_file);
  if (fd < 0) throw std::runtime_error("cannot create a temporary file");
  close(fd);
  const std::string cmd = exe + " " + args + " 2>" + err_file;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + cmd);
  std::string out;
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), pipe))
    out.append(buf.data(), n);
  const int raw = pclose(pipe);
  std::ifstream in(err_file);
  std::string err((std::istreambuf_iterator<char>(in)),
                  std::istreambuf_iterator<char>());
  std::remove(err_file);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out, err};
}

#ifdef VIVP_EXE
inline CliRun RunVivp(const std::string& args) {
  return RunCommand(VIVP_EXE, args);
}
#endif

// The whole text of a file (empty if it cannot be read).
inline std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
}

// A scratch directory of this test process (PREFIX and the process id in
// the temporary directory), removed with everything in it at the end.
struct ScratchDirectory {
  std::filesystem::path dir;
  explicit ScratchDirectory(const std::string& prefix)
      : dir(std::filesystem::temp_directory_path() /
            (prefix + std::to_string(getpid()))) {
    std::filesystem::create_directories(dir);
  }
  ~ScratchDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

// Number of lines in a message.
inline int Lines(const std::string& s) {
  int n = 0;
  for (const char c : s) n += c == '\n';
  return n;
}

}  // namespace vivp::testing
