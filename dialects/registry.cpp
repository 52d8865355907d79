// The table of dialects gcx knows. Adding a dialect = adding a row here and its folder
// (docs/adding-a-dialect.md).
#include <algorithm>
#include <filesystem>

#include "dialect/dialect.h"
#include "dialects/fms3000/emitter.h"
#include "dialects/fms3000/lexical_rules.h"
#include "dialects/fms3000/profile.h"
#include "dialects/fms3000/reader.h"
#include "dialects/nct/emitter.h"
#include "dialects/nct/lexical_rules.h"
#include "dialects/nct/profile.h"
#include "dialects/nct/reader.h"
#include "dialects/wl4/emitter.h"
#include "dialects/wl4/lexical_rules.h"
#include "dialects/wl4/profile.h"
#include "dialects/wl4/reader.h"

namespace gcx {

namespace {

class NctSource : public BlockSource {
public:
  NctSource(std::istream& in, FileId file, diag::Engine& diags, front::Encoding encoding)
      : reader_(in, file, diags, {}, encoding) {}
  bool next(ir::Block& out) override { return reader_.next(out); }
  bool sawInput() const override { return reader_.sawInput(); }
  std::size_t failedBlocks() const override { return reader_.stats().failed; }
  bool canReadInParts() const override { return reader_.canReadInParts(); }
  void startAt(std::uint64_t offset, std::uint32_t line) override { reader_.startAt(offset, line); }
  void stopAt(std::uint64_t offset) override { reader_.stopAt(offset); }
  std::optional<SourceLoc> stoppedAt() const override { return reader_.stoppedAt(); }
  void shiftLines(std::int64_t delta) override { reader_.shiftLines(delta); }
  bool stateless() const override { return reader_.stateless(); }

private:
  nct::Reader reader_;
};

class Fms3000Source : public BlockSource {
public:
  Fms3000Source(std::istream& in, FileId file, diag::Engine& diags, front::Encoding encoding)
      : reader_(in, file, diags, {}, encoding) {}
  bool next(ir::Block& out) override { return reader_.next(out); }
  bool sawInput() const override { return reader_.sawInput(); }
  std::size_t failedBlocks() const override { return reader_.failedBlocks(); }

private:
  fms3000::Reader reader_;
};

} // namespace

const std::vector<Dialect>& dialects() {
  static const std::vector<Dialect> all = {
      Dialect{"nct",
              {".nct"},
              &nct::profile,
              &nct::lexicalRules,
              [](std::istream& in, FileId f, diag::Engine& d,
                 front::Encoding e) -> std::unique_ptr<BlockSource> {
                return std::make_unique<NctSource>(in, f, d, e);
              },
              &nct::makeEmitter,
              &nct::emitterCapabilities,
              {},
              true},
      Dialect{"fms3000",
              {".fms"},
              &fms3000::profile,
              &fms3000::lexicalRules,
              [](std::istream& in, FileId f, diag::Engine& d,
                 front::Encoding e) -> std::unique_ptr<BlockSource> {
                return std::make_unique<Fms3000Source>(in, f, d, e);
              },
              &fms3000::makeEmitter,
              &fms3000::emitterCapabilities,
              {},
              true},
      Dialect{"wl4",
              {".wl4"},
              &wl4::profile,
              &wl4::lexicalRules,
              [](std::istream& in, FileId f, diag::Engine& d,
                 front::Encoding e) -> std::unique_ptr<BlockSource> {
                return std::make_unique<wl4::Reader>(in, f, d, e);
              },
              &wl4::makeEmitter,
              &wl4::emitterCapabilities,
              {},
              true},
  };
  return all;
}

const Dialect* findDialect(const std::string& name) {
  for (const Dialect& d : dialects())
    if (d.name == name) return &d;
  return nullptr;
}

const Dialect* dialectForPath(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  for (const Dialect& d : dialects())
    for (const std::string& e : d.extensions)
      if (e == ext) return &d;
  return nullptr;
}

std::vector<std::string> dialectNames() {
  std::vector<std::string> names;
  for (const Dialect& d : dialects())
    names.push_back(d.name);
  return names;
}

} // namespace gcx
