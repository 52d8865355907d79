#include "ir/source.h"

#include <algorithm>
#include <fstream>

namespace gcx {

FileId SourceManager::addFile(std::string path) {
  files_.push_back(File{std::move(path), false, {}});
  return static_cast<FileId>(files_.size() - 1);
}

FileId SourceManager::addBuffer(std::string name, std::string text) {
  files_.push_back(File{std::move(name), true, std::move(text)});
  return static_cast<FileId>(files_.size() - 1);
}

std::string SourceManager::lineText(const SourceLoc& loc, std::size_t maxBytes) const {
  if (loc.file >= files_.size() || !loc.valid() || loc.col == 0) return {};
  const File& f = files_[loc.file];
  const std::uint64_t lineStart = loc.offset >= loc.col - 1 ? loc.offset - (loc.col - 1) : 0;
  std::string out;
  if (f.inMemory) {
    if (lineStart > f.text.size()) return {};
    const auto end = f.text.find('\n', lineStart);
    out = f.text.substr(
        lineStart, std::min<std::size_t>(
                       (end == std::string::npos ? f.text.size() : end) - lineStart, maxBytes));
  } else {
    std::ifstream in(f.name, std::ios::binary);
    if (!in) return {};
    in.seekg(static_cast<std::streamoff>(lineStart));
    out.resize(maxBytes);
    in.read(out.data(), static_cast<std::streamsize>(maxBytes));
    out.resize(static_cast<std::size_t>(in.gcount()));
    if (auto nl = out.find('\n'); nl != std::string::npos) out.resize(nl);
  }
  if (!out.empty() && out.back() == '\r') out.pop_back();
  return out;
}

} // namespace gcx
