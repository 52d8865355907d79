// A folder of this test process's own in which the tests run the gcx binary (ctest runs tests as
// parallel processes), and what a run printed.
#pragma once
#include <string>

#include "support/test_support.h"

namespace gcx::test {

struct CliResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

class CliFolder {
public:
  /// A fresh folder named after tag and the process, removed by the destructor.
  explicit CliFolder(const std::string& tag);
  ~CliFolder();
  CliFolder(const CliFolder&) = delete;
  CliFolder& operator=(const CliFolder&) = delete;

  /// Writes name (with its folders) under the folder.
  fs::path write(const std::string& name, const std::string& bytes) const;
  /// Runs `gcx args` in the folder.
  CliResult gcx(const std::string& args) const;
  const fs::path& path() const { return dir_; }

private:
  fs::path dir_;
};

} // namespace gcx::test
