// SPDX-License-Identifier: GPL-3.0-or-later
// parse_external_job (external_job.h): field by field, each problem named by
// its JSON pointer.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <regex>

#include "core/input_error.h"
#include "external/external_job.h"

namespace gridfree {
namespace {

using nlohmann::json;

const std::string kExt = "/case/external";

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

// A relative path that stays inside its folder ("a/b", not "/a" or "../a").
bool is_inside_relative(const std::string& s) {
  const std::filesystem::path p(s);
  if (s.empty() || p.is_absolute()) return false;
  for (const auto& part : p)
    if (part == "..") return false;
  return true;
}

std::string ext_string(const json& obj, const std::string& key, const std::string& where, ProblemList& problems,
                       bool required) {
  if (!obj.contains(key)) {
    if (required) problems.add(where + "/" + key, "required");
    return "";
  }
  const auto& v = obj.at(key);
  if (!v.is_string()) {
    problems.add(where + "/" + key, "must be a string");
    return "";
  }
  return v.get<std::string>();
}

std::vector<std::string> ext_string_list(const json& obj, const std::string& key, const std::string& where,
                                         ProblemList& problems) {
  std::vector<std::string> out;
  if (!obj.contains(key)) return out;
  const auto& v = obj.at(key);
  if (!v.is_array()) {
    problems.add(where + "/" + key, "must be an array of strings");
    return out;
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_string()) problems.add(where + "/" + key + "/" + std::to_string(i), "must be a string");
    else out.push_back(v[i].get<std::string>());
  }
  return out;
}

// A regex with at least `groups` capture groups, else a problem at `where`.
void check_regex(const std::string& text, std::size_t groups, const std::string& where, ProblemList& problems) {
  try {
    const std::regex re(text, std::regex::ECMAScript);
    if (re.mark_count() < groups) problems.add(where, "needs a capture group ( ) around the number");
  } catch (const std::regex_error& e) {
    problems.add(where, std::string("is not a valid regular expression: ") + e.what());
  }
}

std::optional<double> positive_number(const json& obj, const std::string& key, const std::string& where,
                                      ProblemList& problems) {
  if (!obj.contains(key)) return std::nullopt;
  const auto& v = obj.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() <= 0) {
    problems.add(where + "/" + key, "must be a positive number");
    return std::nullopt;
  }
  return v.get<double>();
}

QuantitySpec parse_quantity(const std::string& name, const json& q, const std::string& where, ProblemList& problems) {
  QuantitySpec s;
  s.name = name;
  if (!q.is_object()) {
    problems.add(where, "must be an object with file + column or log + regex");
    return s;
  }
  static const char* kKnown[] = {"units", "description", "file", "column", "log", "regex"};
  for (const auto& [key, value] : q.items()) {
    (void)value;
    if (std::find(std::begin(kKnown), std::end(kKnown), key) == std::end(kKnown))
      problems.add(where + "/" + key, "unknown field (expected units, description, file + column or log + regex)");
  }
  s.units = ext_string(q, "units", where, problems, false);
  s.description = ext_string(q, "description", where, problems, false);
  s.file = ext_string(q, "file", where, problems, false);
  s.log = ext_string(q, "log", where, problems, false);
  s.regex = ext_string(q, "regex", where, problems, false);
  const bool by_file = q.contains("file") || q.contains("column");
  const bool by_log = q.contains("log") || q.contains("regex");
  if (by_file == by_log) {
    problems.add(where, "give either file + column or log + regex");
    return s;
  }
  if (by_file) {
    if (!q.contains("file")) problems.add(where + "/file", "required with column");
    else if (!is_inside_relative(s.file)) problems.add(where + "/file", "must be a path relative to the case folder");
    if (!q.contains("column")) problems.add(where + "/column", "required with file");
    else if (!q.at("column").is_number_integer() || q.at("column").get<long long>() < 0 ||
             q.at("column").get<long long>() > 100000)
      problems.add(where + "/column", "must be a column index 0, 1, 2, ... (0-based)");
    else s.column = static_cast<int>(q.at("column").get<long long>());
  } else {
    if (!q.contains("log")) problems.add(where + "/log", "required with regex");
    else if (!is_inside_relative(s.log)) problems.add(where + "/log", "must be a path relative to the case folder");
    if (!q.contains("regex")) problems.add(where + "/regex", "required with log");
    else check_regex(s.regex, 1, where + "/regex", problems);
  }
  return s;
}

CollectSpec parse_collect(const json& ext, ProblemList& problems) {
  CollectSpec c;
  const std::string where = kExt + "/collect";
  if (!ext.contains("collect")) return c;
  const auto& col = ext.at("collect");
  if (!col.is_object()) {
    problems.add(where, "must be an object");
    return c;
  }
  for (const auto& [key, value] : col.items()) {
    (void)value;
    if (key != "quantities" && key != "failure_patterns" && key != "logs" && key != "residual" &&
        key != "steady_tolerance")
      problems.add(where + "/" + key,
                   "unknown field (expected quantities, failure_patterns, logs, residual, steady_tolerance)");
  }
  if (col.contains("quantities")) {
    if (!col.at("quantities").is_object()) problems.add(where + "/quantities", "must be an object: name → how to read it");
    else
      for (const auto& [name, q] : col.at("quantities").items())
        c.quantities.push_back(parse_quantity(name, q, where + "/quantities/" + name, problems));
  }
  c.failure_patterns = ext_string_list(col, "failure_patterns", where, problems);
  for (std::size_t i = 0; i < c.failure_patterns.size(); ++i) {
    if (c.failure_patterns[i].empty()) problems.add(where + "/failure_patterns/" + std::to_string(i), "is empty");
    else check_regex(c.failure_patterns[i], 0, where + "/failure_patterns/" + std::to_string(i), problems);
  }
  c.logs = ext_string_list(col, "logs", where, problems);
  for (std::size_t i = 0; i < c.logs.size(); ++i)
    if (c.logs[i].empty() || !is_inside_relative(c.logs[i]))
      problems.add(where + "/logs/" + std::to_string(i), "must be a path (or glob) relative to the case folder");
  if (col.contains("residual")) {
    const auto& r = col.at("residual");
    const std::string rw = where + "/residual";
    if (!r.is_object()) {
      problems.add(rw, "must be an object with log, regex and tolerance");
    } else {
      ResidualSpec s;
      s.log = ext_string(r, "log", rw, problems, true);
      if (r.contains("log") && r.at("log").is_string() && !is_inside_relative(s.log))
        problems.add(rw + "/log", "must be a path relative to the case folder");
      s.regex = ext_string(r, "regex", rw, problems, true);
      if (r.contains("regex") && r.at("regex").is_string()) check_regex(s.regex, 1, rw + "/regex", problems);
      const auto tol = positive_number(r, "tolerance", rw, problems);
      if (!r.contains("tolerance")) problems.add(rw + "/tolerance", "required");
      s.tolerance = tol.value_or(0);
      c.residual = s;
    }
  }
  c.steady_tolerance = positive_number(col, "steady_tolerance", where, problems);
  return c;
}

}  // namespace

bool is_external_job(const nlohmann::json& doc) {
  return doc.is_object() && doc.contains("case") && doc.at("case").is_object() && doc.at("case").contains("external");
}

ExternalJob parse_external_job(const nlohmann::json& doc, const std::filesystem::path& job_dir) {
  ProblemList problems;
  ExternalJob job;
  if (!is_external_job(doc)) throw InputError(kExt, "required for an external job");
  if (doc.at("case").contains("name") && doc.at("case").at("name").is_string())
    job.name = doc.at("case").at("name").get<std::string>();
  const auto& ext = doc.at("case").at("external");
  if (!ext.is_object()) throw InputError(kExt, "must be an object");
  static const char* kKnown[] = {"template_dir", "template_sha256", "render",  "variables", "constants", "levels",
                                 "setup",        "command",         "version", "collect"};
  for (const auto& [key, value] : ext.items()) {
    (void)value;
    if (std::find(std::begin(kKnown), std::end(kKnown), key) == std::end(kKnown))
      problems.add(kExt + "/" + key, "unknown field");
  }

  const std::string dir = ext_string(ext, "template_dir", kExt, problems, true);
  if (!dir.empty()) {
    const std::filesystem::path p(dir);
    job.template_dir = p.is_absolute() ? p : (job_dir / p);
  } else if (ext.contains("template_dir") && ext.at("template_dir").is_string()) {
    problems.add(kExt + "/template_dir", "is empty");
  }
  job.template_sha256 = ext_string(ext, "template_sha256", kExt, problems, true);
  if (ext.contains("template_sha256") && ext.at("template_sha256").is_string() &&
      (job.template_sha256.size() != 64 ||
       job.template_sha256.find_first_not_of("0123456789abcdef") != std::string::npos))
    problems.add(kExt + "/template_sha256", "must be 64 lowercase hex digits (a SHA-256)");

  job.render = ext_string_list(ext, "render", kExt, problems);
  for (std::size_t i = 0; i < job.render.size(); ++i)
    if (!is_inside_relative(job.render[i]))
      problems.add(kExt + "/render/" + std::to_string(i), "must be a path relative to the template folder");

  if (ext.contains("variables")) {
    const auto& vars = ext.at("variables");
    if (!vars.is_object()) problems.add(kExt + "/variables", "must be an object: name → number");
    else
      for (const auto& [name, value] : vars.items()) {
        const std::string w = kExt + "/variables/" + name;
        if (!is_identifier(name)) problems.add(w, "a variable name is letters, digits and _, not starting with a digit");
        else if (!value.is_number() || !std::isfinite(value.get<double>())) problems.add(w, "must be a finite number");
        else job.variables.emplace_back(name, value.get<double>());
      }
  }
  for (const char* key : {"constants", "levels"}) {  // text placeholders
    if (!ext.contains(key)) continue;
    const auto& texts = ext.at(key);
    const std::string at = kExt + "/" + key;
    if (!texts.is_object()) {
      problems.add(at, "must be an object: placeholder name → its text");
      continue;
    }
    for (const auto& [name, value] : texts.items()) {
      const std::string w = at + "/" + name;
      const auto taken = [&](const auto& list) {
        return std::any_of(list.begin(), list.end(), [&](const auto& v) { return v.first == name; });
      };
      if (!is_identifier(name)) problems.add(w, "a placeholder name is letters, digits and _, not starting with a digit");
      else if (!value.is_string()) problems.add(w, "must be a string (the text written in its place)");
      else if (taken(job.variables) || taken(job.levels))
        problems.add(w, "'" + name + "' is also another placeholder's name; a placeholder has one value");
      else job.levels.emplace_back(name, value.get<std::string>());
    }
  }
  job.setup = ext_string_list(ext, "setup", kExt, problems);
  job.command = ext_string_list(ext, "command", kExt, problems);
  if (!ext.contains("command")) problems.add(kExt + "/command", "required: the program and its arguments");
  else if (ext.at("command").is_array() && ext.at("command").empty())
    problems.add(kExt + "/command", "is empty: give the program and its arguments");
  else if (!job.command.empty() && job.command[0].empty())
    problems.add(kExt + "/command/0", "the program name is empty");
  job.version = ext_string(ext, "version", kExt, problems, false);
  job.collect = parse_collect(ext, problems);

  if (doc.contains("numerics") && doc.at("numerics").is_object() && doc.at("numerics").contains("grid")) {
    const auto& g = doc.at("numerics").at("grid");
    if (g.is_object() && g.contains("h")) {
      if (!g.at("h").is_number() || !(g.at("h").get<double>() > 0)) problems.add("/numerics/grid/h", "must be a positive number");
      else job.grid_h = g.at("h").get<double>();
    }
    if (g.is_object() && g.contains("cells") && g.at("cells").is_number()) job.grid_cells = g.at("cells").get<double>();
  }
  problems.throw_if_any();
  return job;
}

}  // namespace gridfree
