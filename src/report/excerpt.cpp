#include "report/excerpt.h"

#include <algorithm>
#include <fstream>

namespace gcx::report {

std::vector<ExcerptLine> readExcerpt(const std::string& path, int line, int context,
                                     std::size_t maxBytes) {
  std::vector<ExcerptLine> out;
  if (line < 1 || context < 0) return out;
  std::ifstream in(path, std::ios::binary);
  if (!in) return out;
  const int first = std::max(1, line - context), last = line + context;
  int number = 1;
  std::string text;
  bool cut = false;
  auto endLine = [&] {
    if (number >= first) {
      if (!cut && !text.empty() && text.back() == '\r') text.pop_back();
      out.push_back({number, std::move(text)});
    }
    text.clear();
    cut = false;
    ++number;
  };
  char buf[1 << 16];
  while (number <= last && in.read(buf, sizeof buf).gcount() > 0) {
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got && number <= last; ++i) {
      if (buf[i] == '\n')
        endLine();
      else if (number < first || cut)
        continue;
      else if (text.size() < maxBytes)
        text += buf[i];
      else {
        text += "\xE2\x80\xA6"; // …
        cut = true;
      }
    }
  }
  if (number <= last && !text.empty()) endLine(); // a last line without a line end
  return out;
}

} // namespace gcx::report
