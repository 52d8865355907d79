// Source locations and the table of files they point into.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gcx {

using FileId = std::uint32_t;

/// A point in a source file. line and col are 1-based; col counts bytes, as clang does.
/// offset is the byte offset in the file, so a diagnostic can show the line without the
/// whole file being kept in memory (streaming).
struct SourceLoc {
  FileId file = 0;
  std::uint32_t line = 0;
  std::uint32_t col = 0;
  std::uint64_t offset = 0;

  bool valid() const { return line != 0; }
};

/// A run of bytes starting at begin (length may reach across lines for multi-line comments).
struct SourceRange {
  SourceLoc begin;
  std::uint32_t length = 0;
};

/// Owns file names and, for in-memory sources (tests, stdin), their text.
class SourceManager {
public:
  FileId addFile(std::string path);
  FileId addBuffer(std::string name, std::string text);

  const std::string& name(FileId id) const { return files_.at(id).name; }
  /// The text of the line holding loc (without its LF), or empty if it cannot be read.
  /// At most maxBytes are returned, so a 10 MB line does not flood a terminal.
  std::string lineText(const SourceLoc& loc, std::size_t maxBytes = 4096) const;

private:
  struct File {
    std::string name;
    bool inMemory = false;
    std::string text;
  };
  std::vector<File> files_;
};

} // namespace gcx
