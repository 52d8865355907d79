#include "support/cli_folder.h"

#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace gcx::test {

CliFolder::CliFolder(const std::string& tag)
    : dir_(fs::temp_directory_path() / fmt::format("gcx-{}-{}", tag, getpid())) {
  fs::create_directories(dir_);
}

CliFolder::~CliFolder() {
  std::error_code ignored;
  fs::remove_all(dir_, ignored);
}

fs::path CliFolder::write(const std::string& name, const std::string& bytes) const {
  const fs::path p = dir_ / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

CliResult CliFolder::gcx(const std::string& args) const {
  const fs::path out = dir_ / "stdout", err = dir_ / "stderr";
  const std::string cmd = fmt::format("cd {} && {} {} >{} 2>{}", dir_.string(), GCX_BINARY, args,
                                      out.string(), err.string());
  CliResult r;
  r.exitCode = WEXITSTATUS(std::system(cmd.c_str()));
  r.out = readFile(out);
  r.err = readFile(err);
  fs::remove(out), fs::remove(err); // the folder holds only what the test and gcx wrote
  return r;
}

} // namespace gcx::test
