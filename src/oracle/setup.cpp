#include "oracle/setup.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <charconv>

namespace gcx::oracle {

namespace {

int workOffsetIndex(const std::string& name) {
  static const char* const names[] = {"G54", "G55", "G56", "G57", "G58", "G59"};
  for (int i = 0; i < 6; ++i)
    if (name == names[i]) return i + 1;
  return 0;
}

// {"parameters": ..., "variables": ...}: a dialect's own section, which gcx's reader checks
bool isDialectSection(const nlohmann::json& v) {
  if (!v.is_object() || v.empty()) return false;
  for (auto it = v.begin(); it != v.end(); ++it)
    if (it.key() != "parameters" && it.key() != "variables") return false;
  return true;
}

} // namespace

bool parseSetupJson(std::string_view text, OracleSetup& out, std::string& error) {
  out = {};
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.begin(), text.end(), nullptr, true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    error = fmt::format("setup JSON: {}", e.what());
    return false;
  }
  if (!j.is_object()) {
    error = "setup JSON: the top level must be an object";
    return false;
  }
  for (const auto& [key, value] : j.items()) {
    if (key == "work_offsets") {
      if (!value.is_object()) {
        error = "setup JSON: work_offsets must be an object";
        return false;
      }
      for (const auto& [name, v] : value.items()) {
        const int index = workOffsetIndex(name);
        if (name == "common" && v.is_array() && v.size() == 3 && v[0] == 0 && v[1] == 0 &&
            v[2] == 0)
          continue; // a zero common offset changes nothing
        if (index == 0) {
          error = fmt::format(
              "setup JSON: work offset '{}' cannot be given to rs274 (only G54..G59)", name);
          return false;
        }
        if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
            !v[2].is_number()) {
          error = fmt::format("setup JSON: work offset {} must be [x, y, z]", name);
          return false;
        }
        OracleWorkOffset o;
        o.index = index;
        o.offsetMm = Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
        out.workOffsets.push_back(o);
      }
    } else if (key == "tools") {
      if (!value.is_object()) {
        error = "setup JSON: tools must be an object";
        return false;
      }
      for (const auto& [num, v] : value.items()) {
        int n = 0;
        auto [p, ec] = std::from_chars(num.data(), num.data() + num.size(), n);
        if (ec != std::errc() || p != num.data() + num.size() || n <= 0) {
          error = fmt::format("setup JSON: tool key '{}' is not a positive number", num);
          return false;
        }
        if (!v.is_object()) {
          error = fmt::format("setup JSON: tool {} must be an object", n);
          return false;
        }
        OracleTool t;
        t.number = n;
        for (const auto& [field, fv] : v.items()) {
          if (!fv.is_number()) {
            error = fmt::format("setup JSON: tool {} {} must be a number", n, field);
            return false;
          }
          if (field == "length")
            t.lengthMm = fv.get<double>();
          else if (field == "radius")
            t.diameterMm = 2 * fv.get<double>();
          else {
            error = fmt::format("setup JSON: tool {}: unknown field '{}'", n, field);
            return false;
          }
        }
        out.tools.push_back(t);
      }
    } else if (key == "initial_position") {
      // rs274's standalone machine starts at 0,0,0; another start cannot be given to it
      if (!value.is_array() || value.size() != 3 || value[0] != 0 || value[1] != 0 ||
          value[2] != 0) {
        error = "setup JSON: a non-zero initial_position cannot be given to rs274";
        return false;
      }
    } else if (key == "block_skip") {
      if (!value.is_array() || !value.empty()) {
        error = "setup JSON: block_skip switches cannot be given to rs274 (it runs `/` blocks)";
        return false;
      }
    } else if (key == "rapid_rate") {
      if (!value.is_number() || value.get<double>() <= 0) {
        error = "setup JSON: rapid_rate must be a number above 0";
        return false;
      }
      out.rapidRate = value.get<double>();
    } else if (key == "parameters" || key == "variables" || key == "reference_points" ||
               isDialectSection(value)) {
      // not needed by rs274 for the common subset (no macros, no G28/G30 in the corpus)
    } else {
      error = fmt::format("setup JSON: unknown key '{}'", key);
      return false;
    }
  }
  return true;
}

void applySetup(const OracleSetup& setup, Rs274Options& options) {
  options.workOffsets = setup.workOffsets;
  options.tools = setup.tools;
}

} // namespace gcx::oracle
