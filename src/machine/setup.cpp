#include "machine/setup.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "diag/codes.h"
#include "machine/setup_syntax.h"

namespace gcx::machine {

namespace {

using json = nlohmann::json;
namespace code = diag::code;
using Path = std::vector<std::string>; // object keys and array indices, from the root

struct Span {
  std::size_t offset = 0;
  std::size_t length = 0;
};

struct Place {
  Span key;   // the quoted key; for array elements and the root, the value itself
  Span value; // the whole value, brackets included
};

// nlohmann's DOM keeps no positions, so a second walk over the text (which nlohmann has
// already accepted) records where every key and value is. A repeated key replaces the earlier
// one, as it does in nlohmann's DOM, and is remembered so that it can be reported.
class Locator {
public:
  struct Duplicate {
    Path path;
    Span first, again;
  };

  explicit Locator(std::string_view text) : t_(text) {
    if (t_.starts_with("\xEF\xBB\xBF")) i_ = 3; // nlohmann skips a UTF-8 BOM too
    space();
    Path root;
    value(root, Span{}, 0);
  }

  /// The place of path, or of its nearest recorded ancestor.
  Place at(Path path) const {
    for (;; path.pop_back()) {
      if (auto it = places_.find(path); it != places_.end()) return it->second;
      if (path.empty()) return Place{};
    }
  }
  const std::vector<Duplicate>& duplicates() const { return duplicates_; }

private:
  static constexpr int maxDepth = 64; // deeper values are jumped over; errors use an ancestor

  bool more() const { return i_ < t_.size(); }
  char peek() const { return more() ? t_[i_] : '\0'; }
  bool commentAhead() const { return t_.compare(i_, 2, "//") == 0 || t_.compare(i_, 2, "/*") == 0; }

  // Whitespace and the comments nlohmann accepts with ignore_comments.
  void space() {
    while (more()) {
      const char c = t_[i_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        ++i_;
      } else if (t_.compare(i_, 2, "//") == 0) {
        const auto end = t_.find('\n', i_);
        i_ = end == std::string_view::npos ? t_.size() : end;
      } else if (t_.compare(i_, 2, "/*") == 0) {
        const auto end = t_.find("*/", i_ + 2);
        i_ = end == std::string_view::npos ? t_.size() : end + 2;
      } else {
        return;
      }
    }
  }

  void skipString() { // from the opening quote to just past the closing one
    for (++i_; more() && t_[i_] != '"'; ++i_)
      if (t_[i_] == '\\') ++i_;
    i_ = std::min(i_ + 1, t_.size());
  }

  void skipNested() {
    int depth = 0;
    while (more()) {
      const char c = t_[i_];
      if (c == '"') {
        skipString();
        continue;
      }
      if (commentAhead()) {
        space();
        continue;
      }
      ++i_;
      if (c == '{' || c == '[')
        ++depth;
      else if ((c == '}' || c == ']') && --depth == 0)
        return;
    }
  }

  std::string keyText(Span key) const {
    try {
      return json::parse(t_.substr(key.offset, key.length)).get<std::string>();
    } catch (const json::exception&) {
      return std::string(t_.substr(key.offset + 1, key.length >= 2 ? key.length - 2 : 0));
    }
  }

  // Every loop below advances or returns, so a text nlohmann accepted and this walker
  // misreads still ends the walk (with fewer places recorded).
  void value(Path& path, Span key, int depth) {
    Place place{key, Span{i_, 0}};
    const char c = peek();
    if ((c == '{' || c == '[') && depth >= maxDepth) {
      skipNested();
    } else if (c == '{') {
      members(path, depth);
    } else if (c == '[') {
      elements(path, depth);
    } else if (c == '"') {
      skipString();
    } else {
      while (more() && (std::isalnum(static_cast<unsigned char>(t_[i_])) || t_[i_] == '+' ||
                        t_[i_] == '-' || t_[i_] == '.'))
        ++i_;
    }
    place.value.length = i_ - place.value.offset;
    if (place.key.length == 0) place.key = place.value;
    places_[path] = place;
  }

  void members(Path& path, int depth) {
    ++i_;
    space();
    if (peek() == '}') {
      ++i_;
      return;
    }
    while (more()) {
      space();
      if (peek() != '"') return;
      Span key{i_, 0};
      skipString();
      key.length = i_ - key.offset;
      path.push_back(keyText(key));
      if (auto old = places_.find(path); old != places_.end()) {
        duplicates_.push_back({path, old->second.key, key});
        eraseSubtree(path);
      }
      space();
      if (peek() != ':') {
        path.pop_back();
        return;
      }
      ++i_;
      space();
      value(path, key, depth + 1);
      path.pop_back();
      space();
      if (peek() != ',') break;
      ++i_;
    }
    if (peek() == '}') ++i_;
  }

  void elements(Path& path, int depth) {
    ++i_;
    space();
    if (peek() == ']') {
      ++i_;
      return;
    }
    for (std::size_t n = 0; more(); ++n) {
      space();
      path.push_back(std::to_string(n));
      value(path, Span{}, depth + 1);
      path.pop_back();
      space();
      if (peek() != ',') break;
      ++i_;
    }
    if (peek() == ']') ++i_;
  }

  void eraseSubtree(const Path& path) {
    auto it = places_.lower_bound(path);
    while (it != places_.end() && it->first.size() >= path.size() &&
           std::equal(path.begin(), path.end(), it->first.begin()))
      it = places_.erase(it);
  }

  std::string_view t_;
  std::size_t i_ = 0;
  std::map<Path, Place> places_;
  std::vector<Duplicate> duplicates_;
};

// byte offset -> line:col, as the rest of gcx counts them (1-based, col in bytes)
class Lines {
public:
  explicit Lines(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }

  SourceRange range(FileId file, Span s) const {
    const auto line = static_cast<std::size_t>(
        std::upper_bound(starts_.begin(), starts_.end(), s.offset) - starts_.begin());
    SourceLoc loc{file, static_cast<std::uint32_t>(line),
                  static_cast<std::uint32_t>(s.offset - starts_[line - 1] + 1), s.offset};
    return {loc, static_cast<std::uint32_t>(std::clamp<std::size_t>(s.length, 1, UINT32_MAX))};
  }

private:
  std::vector<std::size_t> starts_{0};
};

// Only finds the first syntax error and where it is; the DOM is built afterwards.
class SyntaxProbe : public json::json_sax_t {
public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t at, const std::string& lastToken,
                   const json::exception& ex) override {
    failed = true;
    position = at;
    token = lastToken;
    id = ex.id;
    what = ex.what();
    return false;
  }

  bool failed = false;
  std::size_t position = 0; // 1-based index of the last byte read
  std::string token;
  int id = 0;
  std::string what;
};

// "[json.exception.parse_error.101] parse error at line 1, column 4: syntax error ..." ->
// "syntax error ...": our own location replaces nlohmann's, which counts differently.
std::string parseErrorDetail(const std::string& what) {
  std::size_t from = 0;
  if (auto col = what.find(", column "); col != std::string::npos) {
    if (auto colon = what.find(": ", col); colon != std::string::npos) from = colon + 2;
  } else if (auto bracket = what.find("] "); bracket != std::string::npos) {
    from = bracket + 2;
  }
  std::string detail = what.substr(from);
  // an unterminated string makes "last read" the rest of the file
  if (const std::size_t cap = 200; detail.size() > cap) {
    std::size_t cut = cap;
    while (cut > 0 && (static_cast<unsigned char>(detail[cut]) & 0xC0) == 0x80)
      --cut;
    detail = detail.substr(0, cut) + "...";
  }
  return detail;
}

std::string typeName(const json& v) {
  switch (v.type()) {
  case json::value_t::object:
    return "an object";
  case json::value_t::array:
    return "an array";
  case json::value_t::string:
    return "a string";
  case json::value_t::boolean:
    return v.get<bool>() ? "true" : "false";
  case json::value_t::null:
    return "null";
  default:
    return "a number";
  }
}

// A key as it appears in a message: JSON-quoted (control bytes escaped), long ones cut.
std::string keyName(const std::string& key) {
  return json(key.size() > 40 ? key.substr(0, 40) + "..." : key)
      .dump(-1, ' ', false, json::error_handler_t::replace);
}

// Decimal digits only, no sign or spaces; nullopt otherwise or when absurdly long.
std::optional<long> digits(std::string_view s) {
  if (s.empty() || s.size() > 9) return std::nullopt;
  long n = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + (c - '0');
  }
  return n;
}

constexpr std::string_view topKeys = "work_offsets, tools, parameters, variables, "
                                     "initial_position, block_skip, reference_points, rapid_rate";
constexpr std::string_view sectionKeys = "parameters, variables";

struct Problem {
  const char* code;
  Span at;
  std::string message;
  std::optional<Span> first; // where a repeated entry was first given
};

// Walks the DOM, fills the Setup and collects every problem with its place in the text.
class Checker {
public:
  Checker(const Locator& locator, const SetupDialects& dialects)
      : loc_(locator), dialects_(dialects) {}

  std::vector<Problem> problems;

  void root(const json& v, Setup& out) {
    const Path p;
    if (!v.is_object()) {
      atValue(p, code::SetupWrongType,
              fmt::format("the setup must be a JSON object {{\"work_offsets\": ..., ...}}, not {}",
                          typeName(v)));
      return;
    }
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const Path child{k};
      if (k == "work_offsets")
        workOffsets(it.value(), child, out);
      else if (k == "tools")
        tools(it.value(), child, out);
      else if (k == "parameters" || k == "variables") {
        if (dialects_.own) sectionEntry(k, it.value(), child, *dialects_.own, out);
      } else if (const SetupSyntax* d = dialects_.find(k))
        section(it.value(), child, *d, out);
      else if (k == "initial_position") {
        if (auto xyz = triple(it.value(), child, "initial_position")) out.initialPosition = *xyz;
      } else if (k == "block_skip")
        blockSkip(it.value(), child, out);
      else if (k == "reference_points")
        referencePoints(it.value(), child, out);
      else if (k == "rapid_rate")
        rapidRate(it.value(), child, out);
      else
        atKey(child, code::SetupUnknownKey,
              fmt::format("unknown key {} in the setup; the keys are {}{}", keyName(k), topKeys,
                          sectionNames()));
    }
    for (const Locator::Duplicate& d : loc_.duplicates())
      problems.push_back({code::SetupBadValue, d.again,
                          fmt::format("key {} given twice", keyName(d.path.back())), d.first});
  }

private:
  void atKey(const Path& p, const char* c, std::string message) {
    problems.push_back({c, loc_.at(p).key, std::move(message), std::nullopt});
  }
  void atValue(const Path& p, const char* c, std::string message) {
    problems.push_back({c, loc_.at(p).value, std::move(message), std::nullopt});
  }

  static Path child(Path p, std::string k) {
    p.push_back(std::move(k));
    return p;
  }

  bool object(const json& v, const Path& p, std::string_view what) {
    if (v.is_object()) return true;
    atValue(p, code::SetupWrongType,
            fmt::format("{} must be an object {{...}}, not {}", what, typeName(v)));
    return false;
  }

  std::optional<double> number(const json& v, const Path& p, std::string_view what) {
    if (v.is_number()) return v.get<double>();
    atValue(p, code::SetupWrongType, fmt::format("{} must be a number, not {}", what, typeName(v)));
    return std::nullopt;
  }

  std::optional<std::array<double, 3>> triple(const json& v, const Path& p, std::string_view what) {
    if (!v.is_array()) {
      atValue(p, code::SetupWrongType,
              fmt::format("{} must be an array of 3 numbers [x, y, z], not {}", what, typeName(v)));
      return std::nullopt;
    }
    bool ok = v.size() == 3;
    if (!ok)
      atValue(p, code::SetupBadValue,
              fmt::format("{} must have exactly 3 numbers [x, y, z], not {}", what, v.size()));
    std::array<double, 3> xyz{};
    for (std::size_t i = 0; i < v.size(); ++i) {
      const auto n = number(v[i], child(p, std::to_string(i)),
                            i < 3 ? fmt::format("{} {}", what, "xyz"[i]) : std::string(what));
      if (!n)
        ok = false;
      else if (i < 3)
        xyz[i] = *n;
    }
    return ok ? std::optional(xyz) : std::nullopt;
  }

  // Two spellings of one entry (a parameter in two cases, "#500" and "#0500"): the later one is
  // the error, the earlier one its note.
  void once(std::map<std::string, Path>& seen, const std::string& id, const Path& p,
            std::string_view what) {
    auto [it, fresh] = seen.emplace(id, p);
    if (fresh) return;
    Span first = loc_.at(it->second).key, again = loc_.at(p).key;
    std::string firstKey = it->second.back(), againKey = p.back();
    if (again.offset < first.offset) std::swap(first, again), std::swap(firstKey, againKey);
    problems.push_back(
        {code::SetupBadValue, again,
         fmt::format("{} and {} are both {}", keyName(firstKey), keyName(againKey), what), first});
  }

  void workOffsets(const json& v, const Path& p, Setup& out) {
    if (!object(v, p, "work_offsets")) return;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const Path at = child(p, k);
      const bool good = isWorkOffset(k);
      if (!good) {
        const auto fix = workOffsetSpelling(k);
        atKey(at, code::SetupBadValue,
              fix ? fmt::format("work offset {} should be written \"{}\"", keyName(k), *fix)
                  : fmt::format("{} is not a work offset; the keys are {}", keyName(k),
                                workOffsetHelp()));
      }
      const auto xyz = triple(it.value(), at, fmt::format("work offset {}", good ? k : keyName(k)));
      if (good && xyz) out.workOffsets[k] = *xyz;
    }
  }

  void tools(const json& v, const Path& p, Setup& out) {
    if (!object(v, p, "tools")) return;
    std::map<std::string, Path> seen;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const Path at = child(p, k);
      const auto n = digits(k);
      const bool good = n && *n <= 999;
      if (good)
        once(seen, std::to_string(*n), at, fmt::format("tool {}", *n));
      else
        atKey(at, code::SetupBadValue,
              fmt::format("{} is not a tool number; tools are numbered 0..999", keyName(k)));
      const std::string what = good ? fmt::format("tool {}", *n) : "a tool";
      if (!object(it.value(), at, what)) continue;
      ToolData tool;
      bool ok = good;
      for (auto f = it.value().begin(); f != it.value().end(); ++f) {
        const Path field = child(at, f.key());
        if (f.key() == "turning") {
          if (auto t = triple(f.value(), field, fmt::format("{} turning", what)))
            tool.turning = *t;
          else
            ok = false;
          continue;
        }
        double* target = f.key() == "length"        ? &tool.length
                         : f.key() == "radius"      ? &tool.radius
                         : f.key() == "nose_radius" ? &tool.noseRadius
                                                    : nullptr;
        if (!target) {
          atKey(field, code::SetupUnknownKey,
                fmt::format("unknown key {} in {}; the keys are length, radius, nose_radius, "
                            "turning",
                            keyName(f.key()), what));
          continue;
        }
        if (auto x = number(f.value(), field, fmt::format("{} {}", what, f.key()))) {
          *target = *x;
          if (target == &tool.noseRadius && *x < 0) { // Rt is positive (002:1324-1326)
            atValue(
                field, code::SetupBadValue,
                fmt::format("{} nose_radius {:g} is negative: a nose radius is >= 0", what, *x));
            ok = false;
          }
        } else {
          ok = false;
        }
      }
      if (ok) out.tools[static_cast<int>(*n)] = tool;
    }
  }

  // A dialect's section: its parameters and variables, for its programs only.
  void section(const json& v, const Path& p, const SetupSyntax& d, Setup& out) {
    if (!object(v, p, fmt::format("the {} section", d.dialect))) return;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const Path at = child(p, it.key());
      if (it.key() == "parameters" || it.key() == "variables")
        sectionEntry(it.key(), it.value(), at, d, out);
      else
        atKey(at, code::SetupUnknownKey,
              fmt::format("unknown key {} in the {} section; the keys are {}", keyName(it.key()),
                          d.dialect, sectionKeys));
    }
  }

  void sectionEntry(const std::string& k, const json& v, const Path& p, const SetupSyntax& d,
                    Setup& out) {
    const bool apply = dialects_.own && dialects_.own->dialect == d.dialect;
    if (k == "parameters")
      parameters(v, p, d, apply, out);
    else
      variables(v, p, d, apply, out);
  }

  void parameters(const json& v, const Path& p, const SetupSyntax& d, bool apply, Setup& out) {
    if (!object(v, p, "parameters")) return;
    std::map<std::string, Path>& seen = seenParameters_[d.dialect];
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const Path at = child(p, k);
      const auto name = d.parameterKey(k);
      if (name) {
        once(seen, *name, at, fmt::format("parameter {}", *name));
      } else {
        const auto dot = k.find('.');
        const bool digitBit = d.parameterBits && dot != std::string::npos && dot + 1 < k.size() &&
                              d.parameterKey(k.substr(0, dot)) &&
                              digits(std::string_view(k).substr(dot + 1));
        atKey(at, code::SetupBadValue,
              digitBit ? fmt::format("{}: bit numbers are 0..7", keyName(k))
                       : fmt::format("{} is not a parameter; {}", keyName(k), d.parameterHelp()));
      }
      const auto x = number(it.value(), at, fmt::format("parameter {}", name ? *name : keyName(k)));
      if (!name || !x) continue;
      if (d.parameterBits && name->find('.') != std::string::npos && *x != 0 && *x != 1) {
        atValue(at, code::SetupBadValue,
                fmt::format("bit parameter {} must be 0 or 1, not {}", *name, *x));
        continue;
      }
      if (const ModelledValues* m = d.modelled(*name);
          m && std::find(m->values.begin(), m->values.end(), *x) == m->values.end()) {
        atValue(at, code::SetupBadValue, fmt::format("{} = {}: {}", *name, *x, m->why));
        continue;
      }
      if (apply) out.parameters[*name] = *x;
    }
  }

  void variables(const json& v, const Path& p, const SetupSyntax& d, bool apply, Setup& out) {
    if (!object(v, p, "variables")) return;
    std::map<std::string, Path>& seen = seenVariables_[d.dialect];
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const Path at = child(p, k);
      const auto n = k.starts_with('#') ? digits(std::string_view(k).substr(1)) : std::nullopt;
      const bool good = n && d.presettable(static_cast<long long>(*n));
      if (!n)
        atKey(at, code::SetupBadValue,
              fmt::format("{} is not a macro variable; write #n, e.g. \"#500\"", keyName(k)));
      else if (!good)
        atKey(at, code::SetupBadValue,
              fmt::format("#{} cannot be preset; {}", *n, d.variableHelp()));
      else
        once(seen, std::to_string(*n), at, fmt::format("variable #{}", *n));
      const auto x = number(it.value(), at, good ? fmt::format("#{}", *n) : keyName(k));
      if (good && x && apply) out.variables[static_cast<int>(*n)] = *x;
    }
  }

  void blockSkip(const json& v, const Path& p, Setup& out) {
    if (!v.is_array()) {
      atValue(
          p, code::SetupWrongType,
          fmt::format("block_skip must be an array of switch numbers 1..9, not {}", typeName(v)));
      return;
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Path at = child(p, std::to_string(i));
      const auto x = number(v[i], at, "a block-skip switch");
      if (!x) continue;
      if (*x != std::floor(*x) || *x < 1 || *x > 9) {
        atValue(at, code::SetupBadValue, fmt::format("block-skip switches are 1..9, not {}", *x));
        continue;
      }
      out.blockSkip.insert(static_cast<int>(*x));
    }
  }

  void referencePoints(const json& v, const Path& p, Setup& out) {
    if (!object(v, p, "reference_points")) return;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const Path at = child(p, k);
      const bool good = k.size() == 1 && k[0] >= '1' && k[0] <= '4';
      if (!good)
        atKey(at, code::SetupBadValue,
              fmt::format("{} is not a reference point; the keys are \"1\"..\"4\"", keyName(k)));
      const auto xyz = triple(it.value(), at, good ? "reference point " + k : "a reference point");
      if (good && xyz) out.referencePoints[k[0] - '0'] = *xyz;
    }
  }

  void rapidRate(const json& v, const Path& p, Setup& out) {
    const auto x = number(v, p, "rapid_rate");
    if (!x) return;
    if (*x <= 0) {
      atValue(p, code::SetupBadValue,
              fmt::format("rapid_rate must be more than 0 mm/min, not {}", *x));
      return;
    }
    out.rapidRate = *x;
  }

  // Work-offset keys: the program's dialect's, or any known dialect's (a setup shared by the
  // programs of a translation names the offsets of both).
  bool isWorkOffset(std::string_view k) const {
    if (dialects_.own && dialects_.own->isWorkOffset(k)) return true;
    return std::any_of(dialects_.all.begin(), dialects_.all.end(),
                       [&](const SetupSyntax& d) { return d.isWorkOffset(k); }) ||
           (!dialects_.own && dialects_.all.empty());
  }
  std::optional<std::string> workOffsetSpelling(std::string_view k) const {
    if (dialects_.own)
      if (auto fix = dialects_.own->workOffsetSpelling(k)) return fix;
    for (const SetupSyntax& d : dialects_.all)
      if (auto fix = d.workOffsetSpelling(k)) return fix;
    return std::nullopt;
  }
  std::string workOffsetHelp() const {
    if (dialects_.own) return dialects_.own->workOffsetHelp();
    return dialects_.all.empty() ? std::string("\"common\"")
                                 : dialects_.all.front().workOffsetHelp();
  }
  std::string sectionNames() const {
    std::vector<std::string> names;
    for (const SetupSyntax& d : dialects_.all)
      names.push_back(d.dialect);
    return names.empty() ? std::string()
                         : fmt::format(", and the dialect sections {}", fmt::join(names, ", "));
  }

  const Locator& loc_;
  const SetupDialects& dialects_;
  std::map<std::string, std::map<std::string, Path>> seenParameters_, seenVariables_;
};

} // namespace

std::array<double, 3> Setup::workOffset(const std::string& key) const {
  const auto it = workOffsets.find(key);
  return it == workOffsets.end() ? std::array<double, 3>{0, 0, 0} : it->second;
}

double Setup::parameter(const std::string& key, double fallback) const {
  if (parameters.empty()) return fallback; // the common case, asked for on every block
  const auto it = parameters.find(key);
  return it == parameters.end() ? fallback : it->second;
}

std::optional<Setup> parseSetup(const std::string& text, FileId file, diag::Engine& diags,
                                const SetupDialects& dialects) {
  const Lines lines(text);
  SyntaxProbe probe;
  json::sax_parse(text, &probe, json::input_format_t::json, true, /*ignore_comments=*/true);
  if (probe.failed) {
    const std::size_t last = std::min(probe.position > 0 ? probe.position - 1 : 0, text.size());
    if (probe.id == 406) { // a number beyond double: valid JSON, so a range error at the number
      const std::size_t start = last + 1 >= probe.token.size() ? last + 1 - probe.token.size() : 0;
      diags.error(code::SetupBadValue, lines.range(file, {start, probe.token.size()}),
                  fmt::format("number {} is out of range", probe.token));
    } else {
      diags.error(code::SetupNotJson, lines.range(file, {last, 1}),
                  "setup file is not valid JSON: " + parseErrorDetail(probe.what));
    }
    return std::nullopt;
  }

  json dom;
  try {
    dom = json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::exception& e) { // the probe accepted it, so this should not happen
    diags.error(code::SetupNotJson, lines.range(file, {0, 1}),
                "setup file is not valid JSON: " + parseErrorDetail(e.what()));
    return std::nullopt;
  }

  const Locator locator(text);
  Checker check(locator, dialects);
  Setup setup;
  check.root(dom, setup);
  if (check.problems.empty()) return setup;

  // nlohmann iterates keys sorted; report in the order of the file
  std::stable_sort(check.problems.begin(), check.problems.end(),
                   [](const Problem& a, const Problem& b) { return a.at.offset < b.at.offset; });
  for (Problem& p : check.problems) {
    diag::Diagnostic d{
        diag::Severity::Error, p.code, std::move(p.message), lines.range(file, p.at), {}};
    if (p.first) d.notes.push_back({lines.range(file, *p.first), "first given here"});
    diags.report(std::move(d));
  }
  return std::nullopt;
}

std::optional<Setup> loadSetup(const std::string& path, SourceManager& sources, diag::Engine& diags,
                               const SetupDialects& dialects) {
  auto fail = [&](const std::string& why) {
    diags.error(code::SetupCannotRead, {},
                fmt::format("{}: cannot read the setup file: {}", path, why));
    return std::nullopt;
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return fail("is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(std::strerror(errno));
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) return fail("read error");
  const FileId file = sources.addBuffer(path, text);
  return parseSetup(text, file, diags, dialects);
}

} // namespace gcx::machine
