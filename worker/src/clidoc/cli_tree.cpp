// SPDX-License-Identifier: GPL-3.0-or-later
#include "clidoc/cli_tree.h"

#include <string>

#include <CLI/CLI.hpp>

namespace gridfree {

namespace {

// "TEXT:{local,slurm}" -> {"local", "slurm"}: the choices CLI11 writes into
// an option's type name for an IsMember check.
std::vector<std::string> choices_of(const std::string& type_name) {
  const auto open = type_name.find(":{");
  const auto close = type_name.rfind('}');
  if (open == std::string::npos || close == std::string::npos || close < open) return {};
  std::vector<std::string> out;
  std::string item;
  for (const char c : type_name.substr(open + 2, close - open - 2)) {
    if (c == ',') {
      out.push_back(item);
      item.clear();
    } else if (c != ' ') {
      item += c;
    }
  }
  if (!item.empty()) out.push_back(item);
  return out;
}

CliOption read_option(const CLI::Option& opt) {
  CliOption o;
  for (const auto& s : opt.get_snames()) o.names.push_back("-" + s);
  for (const auto& l : opt.get_lnames()) o.names.push_back("--" + l);
  if (opt.get_type_size() != 0) {
    o.value = opt.get_option_text().empty() ? opt.get_type_name() : opt.get_option_text();
    o.choices = choices_of(o.value);
    // How many values, as CLI11's own help says it: "FLOAT x 2", "TEXT ...".
    if (opt.get_option_text().empty()) {
      if (opt.get_expected_max() == CLI::detail::expected_max_vector_size)
        o.value += " ...";
      else if (opt.get_expected_min() > 1)
        o.value += " x " + std::to_string(opt.get_expected_min());
    }
    o.default_value = opt.get_default_str();
  }
  o.description = opt.get_description();
  o.required = opt.get_required();
  return o;
}

}  // namespace

CliCommand read_cli_tree(const CLI::App& app) {
  CliCommand c;
  c.name = app.get_parent() == nullptr ? "" : app.get_name();
  c.description = app.get_description();
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_group().empty()) continue;  // hidden
    if (opt->nonpositional()) {
      c.options.push_back(read_option(*opt));
    } else {
      c.positionals.push_back({opt->get_name(true, false), opt->get_description(), opt->get_required(),
                               opt->get_expected_max() > 1 || opt->get_items_expected_max() > 1});
    }
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App* s) { return !s->get_name().empty(); })) {
    if (sub->get_group().empty()) continue;  // hidden
    c.commands.push_back(read_cli_tree(*sub));
  }
  return c;
}

}  // namespace gridfree
