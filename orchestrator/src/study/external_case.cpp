// SPDX-License-Identifier: GPL-3.0-or-later
// External cases: reading and checking /cases/NAME/external, the values on
// each grid, and the job document (study/external_case.h).
#include "study/external_case.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "core/json_fields.h"
#include "job/template_hash.h"
#include "study/expression.h"

namespace gridfree {
namespace {

using nlohmann::json;

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool valid_external_name(const std::string& n) {
  if (n.empty() || !is_name_start(n.front())) return false;
  for (char c : n)
    if (!is_name_char(c)) return false;
  return true;
}

std::string quote_for_shell(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The last non-empty lines of a command's stderr (at most 3, " | "
// between them, the end of at most 300 characters).
std::string stderr_tail_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos) lines.push_back(line.substr(first));
  }
  std::string out;
  for (std::size_t i = lines.size() > 3 ? lines.size() - 3 : 0; i < lines.size(); ++i)
    out += (out.empty() ? "" : " | ") + lines[i];
  if (out.size() > 300) out = "…" + out.substr(out.size() - 300);
  return out;
}

// The first line of `command`'s output run by /bin/sh in `dir`; the reason
// it failed otherwise, with the tail of its stderr.
std::pair<std::string, std::string> first_line_of_command(const std::string& command, const std::filesystem::path& dir) {
  std::error_code ec;
  std::string err_path = (std::filesystem::temp_directory_path(ec) / "gridfree-version-XXXXXX").string();
  char* err_name = err_path.data();
  const int err_fd = ::mkstemp(err_name);
  if (err_fd < 0) return {"", "could not create a file for its stderr"};
  ::close(err_fd);
  const std::string full =
      "cd " + quote_for_shell(dir.string()) + " && { " + command + "\n} 2>" + quote_for_shell(err_name);
  FILE* pipe = ::popen(full.c_str(), "r");
  if (pipe == nullptr) {
    ::unlink(err_name);
    return {"", "could not start /bin/sh"};
  }
  std::string out;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0)
    if (out.size() < 65536) out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  std::string err;
  {
    std::ifstream in(err_name, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    err = text.str().substr(0, 65536);
  }
  ::unlink(err_name);
  const std::string tail = stderr_tail_of(err);
  const std::string with_stderr = tail.empty() ? " (nothing on stderr)" : " (stderr: " + tail + ")";
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return {"", "the command failed (" +
                    (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status)) : std::string("killed")) +
                    ")" + with_stderr};
  std::string line = out.substr(0, out.find('\n'));
  while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
  if (line.empty()) return {"", "the command printed nothing on its first line" + with_stderr};
  return {line, ""};
}

std::string external_number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  // Shortest round trip: try fewer digits first.
  for (int digits = 1; digits <= 17; ++digits) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", digits, v);
    if (std::strtod(shorter, nullptr) == v) return shorter;
  }
  return buf;
}

void check_external_render_files(const ExternalCase& c, const std::set<std::string>& defined, const std::string& at,
                        ProblemList& problems) {
  for (std::size_t i = 0; i < c.render.size(); ++i) {
    const std::string where = at + "/render/" + std::to_string(i);
    const std::filesystem::path rel = c.render[i];
    if (rel.is_absolute() || rel.lexically_normal().string().rfind("..", 0) == 0) {
      problems.add(where, "'" + c.render[i] + "' must be a path inside the template folder");
      continue;
    }
    const auto file = c.template_dir / rel;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
      problems.add(where, "'" + c.render[i] + "' is not a file of the template folder");
      continue;
    }
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    for (const auto& [line, name] : placeholders_of(text.str()))
      if (defined.count(name) == 0)
        problems.add(where, c.render[i] + " line " + std::to_string(line) + ": placeholder @@" + name +
                                "@@ is not a defined variable (grid or derived)");
  }
}

void check_external_grids(const ExternalCase& c, const GridVariables& grids, const std::string& at, ProblemList& problems) {
  const std::size_t n = external_grid_count(grids);
  std::vector<double> hs;
  for (std::size_t level = 0; level < n; ++level) {
    ExternalGrid g;
    try {
      g = external_grid(c, grids, level);
    } catch (const std::exception& e) {
      problems.add_once(at, std::string(e.what()) + " (grid " + std::to_string(level) + ")");
      return;
    }
    for (const auto& [name, v] : g.variables)
      if (!std::isfinite(v) && c.variables.count(name) != 0) {
        problems.add_once(at + "/variables/" + name, "'" + c.variables.at(name) + "' is " + external_number_text(v) +
                                                         " on grid " + std::to_string(level) + ", not a finite number");
        return;
      }
    if (!std::isfinite(g.h) || !(g.h > 0)) {
      problems.add_once(at + "/h", "h = " + c.h_expression + " is " + external_number_text(g.h) + " on grid " +
                                       std::to_string(level) + "; it must be a positive finite number");
      return;
    }
    if (g.cells && (!std::isfinite(*g.cells) || !(*g.cells >= 1))) {
      problems.add_once(at + "/cells", "'" + c.cells_expression + "' is " + external_number_text(*g.cells) + " on grid " +
                                           std::to_string(level) + "; it must be a finite number of at least 1");
      return;
    }
    for (std::size_t j = 0; j < hs.size(); ++j)
      if (hs[j] == g.h) {
        problems.add_once(at + "/h", "h = " + c.h_expression + " is " + external_number_text(g.h) + " on grids " +
                                         std::to_string(j) + " and " + std::to_string(level) +
                                         "; every grid needs its own h");
        return;
      }
    hs.push_back(g.h);
  }
}

}  // namespace

std::size_t external_grid_count(const GridVariables& grids) {
  return grids.empty() ? 0 : grids.begin()->second.size();
}

std::vector<std::pair<std::size_t, std::string>> placeholders_of(const std::string& text) {
  std::vector<std::pair<std::size_t, std::string>> out;
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      continue;
    }
    if (text.compare(i, 2, "@@") != 0) continue;
    std::size_t j = i + 2;
    while (j < text.size() && is_name_char(text[j])) ++j;
    if (j > i + 2 && is_name_start(text[i + 2]) && text.compare(j, 2, "@@") == 0) {
      out.emplace_back(line, text.substr(i + 2, j - i - 2));
      i = j + 1;
    }
  }
  return out;
}

std::string external_h_expression(const json& h, std::string* meaning) {
  std::string expression, says;
  if (h.is_string()) {
    expression = h.get<std::string>();
    says = "h = " + expression;
  } else if (h.is_object()) {
    const std::string cells = h.value("cells", "1");
    const double volume = h.value("volume", 1.0);
    const int dim = h.value("dim", 3);
    expression = "(" + external_number_text(volume) + " / (" + cells + ")) ^ (1 / " + std::to_string(dim) + ")";
    says = "h = (V / cells)^(1/" + std::to_string(dim) + "), cells = " + cells + ", V = " + external_number_text(volume);
  }
  if (meaning != nullptr) *meaning = says;
  return expression;
}

ExternalGrid external_grid(const ExternalCase& c, const GridVariables& grids, std::size_t level) {
  ExternalGrid g;
  for (const auto& [name, values] : grids) g.variables[name] = values.at(level);
  // Derived variables in dependency order: each pass evaluates those whose
  // names are all known.
  std::map<std::string, std::string> pending = c.variables;
  while (!pending.empty()) {
    bool progressed = false;
    for (auto it = pending.begin(); it != pending.end();) {
      bool ready = true;
      for (const auto& n : expression_names(it->second))
        if (g.variables.count(n) == 0 && pending.count(n) != 0) ready = false;
      if (!ready) {
        ++it;
        continue;
      }
      g.variables[it->first] = evaluate_expression(it->second, g.variables);
      it = pending.erase(it);
      progressed = true;
    }
    if (!progressed) {
      std::string names;
      for (const auto& [n, e] : pending) names += (names.empty() ? "" : ", ") + n;
      throw std::runtime_error("the derived variables " + names + " depend on each other in a cycle");
    }
  }
  g.h = evaluate_expression(c.h_expression, g.variables);
  if (!c.cells_expression.empty()) g.cells = evaluate_expression(c.cells_expression, g.variables);
  return g;
}

std::optional<ExternalCase> parse_external_case(const json& ext, const std::string& at,
                                                const std::filesystem::path& base_dir, const GridVariables& grids,
                                                ProblemList& problems, const std::set<std::string>& text_placeholders) {
  const std::size_t before = problems.problems().size();
  ExternalCase c;
  if (!ext.is_object()) return std::nullopt;  // the schema said so
  // Template folder and its identity.
  const std::string tmpl = ext.value("template", "");
  c.template_dir = std::filesystem::absolute(base_dir / tmpl).lexically_normal();
  std::error_code ec;
  if (!std::filesystem::is_directory(c.template_dir, ec)) {
    problems.add(at + "/template", "template folder '" + tmpl + "' not found (looked for " + c.template_dir.string() +
                                       ", relative to the study file's folder)");
  } else {
    try {
      c.template_sha256 = template_sha256(c.template_dir);
    } catch (const std::exception& e) {
      problems.add(at + "/template", e.what());
    }
  }
  if (auto r = ext.find("render"); r != ext.end() && r->is_array())
    for (const auto& f : *r) c.render.push_back(f.get<std::string>());
  for (const char* key : {"setup", "command"})
    if (auto a = ext.find(key); a != ext.end() && a->is_array())
      for (const auto& w : *a) (std::string(key) == "setup" ? c.setup : c.command).push_back(w.get<std::string>());
  if (c.command.empty() || c.command.front().empty())
    problems.add(at + "/command", "the command needs a program name as its first word");
  // Variables: grid variables are the study's; derived ones may not shadow them.
  std::set<std::string> defined;
  for (const auto& [n, v] : grids) defined.insert(n);
  // @@cores@@ is the job's cores (study/job_cores.h), given by the driver.
  if (grids.count(kExternalCoresPlaceholder) != 0)
    problems.add_once(child_pointer("/grids/variables", kExternalCoresPlaceholder),
                      "'cores' is the job's number of cores (@@cores@@, the study's cores rule); name the variable otherwise");
  if (auto v = ext.find("variables"); v != ext.end() && v->is_object())
    for (auto it = v->begin(); it != v->end(); ++it) {
      const std::string where = child_pointer(at + "/variables", it.key());
      if (!valid_external_name(it.key())) {
        problems.add(where, "a variable name is a letter or '_' followed by letters, digits or '_'");
        continue;
      }
      if (it.key() == kExternalCoresPlaceholder) {
        problems.add(where, "'cores' is the job's number of cores (@@cores@@, the study's cores rule); name the variable otherwise");
        continue;
      }
      if (grids.count(it.key()) != 0) {
        problems.add(where, "'" + it.key() + "' is already a grid variable (/grids/variables)");
        continue;
      }
      c.variables[it.key()] = it->get<std::string>();
      defined.insert(it.key());
    }
  // Constants: text placeholders of this case (an ensemble's instance changes one).
  if (auto k = ext.find("constants"); k != ext.end() && k->is_object())
    for (auto it = k->begin(); it != k->end(); ++it) {
      const std::string where = child_pointer(at + "/constants", it.key());
      if (!valid_external_name(it.key()))
        problems.add(where, "a constant's name is a letter or '_' followed by letters, digits or '_'");
      else if (it.key() == kExternalCoresPlaceholder)
        problems.add(where, "'cores' is the job's number of cores (@@cores@@, the study's cores rule); name the constant otherwise");
      else if (defined.count(it.key()) != 0)
        problems.add(where, "'" + it.key() + "' is already a grid or derived variable");
      else if (!it->is_string() && !(it->is_number() && !it->is_boolean()))
        problems.add(where, "a constant is a string or a number (written as text for @@" + it.key() + "@@)");
      else
        c.constants[it.key()] = it->is_string() ? it->get<std::string>() : it->dump();
    }
  // Every expression must parse and read only defined names.
  auto check_expression = [&](const std::string& text, const std::string& where) {
    try {
      for (const auto& n : expression_names(text))
        if (defined.count(n) == 0) {
          std::string known;
          for (const auto& d : defined) known += (known.empty() ? "" : ", ") + d;
          problems.add(where, "expression '" + text + "' reads '" + n + "', which is not a variable (defined: " +
                                  (known.empty() ? "none" : known) + ")");
        }
    } catch (const ExpressionError& e) {
      problems.add(where, e.what());
    }
  };
  for (const auto& [n, e] : c.variables) check_expression(e, child_pointer(at + "/variables", n));
  if (auto h = ext.find("h"); h != ext.end()) {
    c.h_expression = external_h_expression(*h, &c.h_meaning);
    if (h->is_string()) {
      check_expression(c.h_expression, at + "/h");
    } else if (h->is_object()) {
      const std::string cells = h->value("cells", "1");
      check_expression(cells, at + "/h/cells");
      if (!ext.contains("cells")) c.cells_expression = cells;
    }
  }
  if (auto n = ext.find("cells"); n != ext.end() && n->is_string()) {
    c.cells_expression = n->get<std::string>();
    check_expression(c.cells_expression, at + "/cells");
  }
  // Version: declared, or the first line of a command (run once, here).
  const bool has_version = ext.contains("version"), has_command = ext.contains("version_command");
  if (has_version == has_command) {
    problems.add(at, "give exactly one of version and version_command (the code's version is part of each job's identity)");
  } else if (has_version) {
    c.version = ext["version"].get<std::string>();
  } else {
    const std::string cmd = ext["version_command"].get<std::string>();
    const auto [line, why] = first_line_of_command(cmd, base_dir);
    if (!why.empty())
      problems.add(at + "/version_command", "'" + cmd + "': " + why);
    else
      c.version = line;
  }
  // Collect: quantities with units; each read from a file column or a log regex.
  c.collect = ext.value("collect", json::object());
  if (auto q = c.collect.find("quantities"); q != c.collect.end() && q->is_object())
    for (auto it = q->begin(); it != q->end(); ++it) {
      const std::string where = child_pointer(at + "/collect/quantities", it.key());
      if (!valid_external_name(it.key())) {
        problems.add(where, "a quantity name is a letter or '_' followed by letters, digits or '_'");
        continue;
      }
      const bool file = it->contains("file"), log = it->contains("log");
      if (file == log)
        problems.add(where, "give either file (with column) or log (with regex)");
      else if (file && !it->contains("column"))
        problems.add(where + "/file", "a file quantity needs its column (0-based)");
      else if (log && !it->contains("regex"))
        problems.add(where + "/log", "a log quantity needs its regex (the first group is the value)");
      if (it->value("units", "").empty()) problems.add(where + "/units", "units are required (\"1\" for none)");
      c.quantities.push_back({it.key(), it->value("units", ""), it->value("description", "")});
    }
  if (auto logs = c.collect.find("logs"); logs != c.collect.end() && logs->is_array())
    for (std::size_t i = 0; i < logs->size(); ++i) {
      const std::filesystem::path rel = (*logs)[i].get<std::string>();
      if (rel.is_absolute() || rel.lexically_normal().string().rfind("..", 0) == 0)
        problems.add(at + "/collect/logs/" + std::to_string(i),
                     "'" + rel.string() + "' must be a path (or glob) relative to the case folder");
    }
  if (auto cost = ext.find("cost"); cost != ext.end() && cost->is_object()) {
    if (cost->contains("cpu_s_per_cell")) c.cpu_s_per_cell = (*cost)["cpu_s_per_cell"].get<double>();
    if (cost->contains("mb_per_cell")) c.mb_per_cell = (*cost)["mb_per_cell"].get<double>();
    if ((c.cpu_s_per_cell || c.mb_per_cell) && c.cells_expression.empty())
      problems.add(at + "/cost", "per-cell costs need the cells expression (external/cells)");
  }
  if (problems.problems().size() != before) return std::nullopt;
  std::set<std::string> placeholders = defined;
  placeholders.insert(kExternalCoresPlaceholder);
  placeholders.insert(text_placeholders.begin(), text_placeholders.end());
  for (const auto& [name, text] : c.constants) placeholders.insert(name);
  check_external_render_files(c, placeholders, at, problems);
  if (external_grid_count(grids) > 0) check_external_grids(c, grids, at, problems);
  if (problems.problems().size() != before) return std::nullopt;
  return c;
}

std::set<std::string> rendered_placeholders(const ExternalCase& c) {
  std::set<std::string> out;
  for (const auto& r : c.render) {
    std::ifstream in(c.template_dir / r, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    for (const auto& [line, name] : placeholders_of(text.str())) out.insert(name);
  }
  return out;
}

json external_job_document(const ExternalCase& c, const std::string& case_name, const ExternalGrid& grid,
                           std::size_t level, const std::map<std::string, std::string>& levels) {
  json variables = json::object();
  for (const auto& [n, v] : grid.variables) variables[n] = v;
  json external = {{"template_dir", c.template_dir.string()},
                   {"template_sha256", c.template_sha256},
                   {"render", c.render},
                   {"variables", variables},
                   {"setup", c.setup},
                   {"command", c.command},
                   {"version", c.version},
                   {"collect", c.collect}};
  if (!c.constants.empty()) external["constants"] = c.constants;
  if (!levels.empty()) external["levels"] = levels;
  json g = {{"level", level}, {"h", grid.h}};
  if (grid.cells) g["cells"] = *grid.cells;
  return {{"schema", "gridfree/job/1"},
          {"case", {{"name", case_name}, {"external", external}}},
          {"numerics", {{"grid", g}}}};
}

}  // namespace gridfree
