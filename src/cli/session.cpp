#include "cli/session.h"

#include <filesystem>
#include <fmt/format.h>
#include <iostream>

#include "diag/codes.h"

namespace gcx::cli {

bool Session::open(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    reportUsage(fmt::format("{}: is a directory [{}]", path, diag::code::CannotRead));
    return false;
  }
  const Dialect* dialect = opt_.dialect.empty() ? dialectForPath(path) : findDialect(opt_.dialect);
  if (!dialect) {
    if (opt_.dialect.empty())
      reportUsage(
          fmt::format("{}: cannot tell the dialect from the extension; use --dialect", path));
    else
      reportUsage(fmt::format("unknown dialect '{}'", opt_.dialect));
    return false;
  }
  dialect_ = *dialect;
  if (!opt_.encoding.empty()) dialect_->encoding = front::encodingByName(opt_.encoding);
  in_.open(path, std::ios::binary);
  if (!in_) {
    reportUsage(fmt::format("{}: cannot open: {} [{}]", path, std::strerror(errno),
                            diag::code::CannotRead));
    return false;
  }
  file_ = sources_.addFile(path);
  path_ = path;
  source_ = dialect_->open(in_, file_, diags_);
  return true;
}

void Session::flushDiagnostics() {
  if (opt_.json) {
    std::cout << diag::renderJson(diags_.all(), sources_);
  } else {
    for (const diag::Diagnostic& d : diags_.all())
      std::cerr << diag::renderText(d, sources_);
  }
  std::cout.flush();
}

} // namespace gcx::cli
