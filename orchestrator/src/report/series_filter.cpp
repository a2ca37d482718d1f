// SPDX-License-Identifier: GPL-3.0-or-later
// The series table's filter of exact tokens (see series_filter.h).
#include "report/series_filter.h"

#include <nlohmann/json.hpp>

namespace gridfree {
namespace {

// Long free text: not filtered (it would match words of sentences).
bool filtered(const Column& c) {
  return !c.prose && c.name != "verdict_reasons" && c.name != "note" && c.name != "extrapolation_notes";
}

// The matching, kept in one string so that a test can read it.
constexpr const char* kScript = R"js(
  var input = document.getElementById('series-filter'), shown = document.getElementById('series-shown');
  if (!input) return;
  var trs = document.querySelectorAll('#series-rows tbody tr');
  var split = function (t) { return t.toLowerCase().split(/[\s,;()]+/).filter(Boolean); };
  var words = data.map(function (r) { return r.reduce(function (a, v) { return a.concat(split(v)); }, []); });
  fields = fields.map(function (f) { return f.toLowerCase(); });
  var op = /^([a-z0-9_.\-]+)(:|>=|<=|>|<|=)(.+)$/;
  function holds(tok, i) {
    var m = op.exec(tok);
    if (!m) return words[i].indexOf(tok) !== -1;
    var v = (data[i][fields.indexOf(m[1])] || '').toLowerCase();
    if (m[2] === ':') return v === m[3] || split(v).indexOf(m[3]) !== -1;
    var x = parseFloat(v), y = parseFloat(m[3]);
    if (isNaN(x) || isNaN(y)) return false;
    return m[2] === '>' ? x > y : m[2] === '<' ? x < y : m[2] === '>=' ? x >= y : m[2] === '<=' ? x <= y : x === y;
  }
  function apply() {
    var toks = input.value.toLowerCase().split(/\s+/).filter(Boolean), n = 0;
    var unknown = toks.map(function (t) { var m = op.exec(t); return m && fields.indexOf(m[1]) < 0 ? m[1] : null; })
                      .filter(Boolean);
    trs.forEach(function (tr, i) {
      var show = !unknown.length && toks.every(function (t) { return holds(t, i); });
      tr.style.display = show ? '' : 'none'; n += show ? 1 : 0;
    });
    shown.textContent = unknown.length ? 'no field ' + unknown.join(', ') + '; the fields: ' + fields.join(', ')
                                       : toks.length ? n + ' of ' + trs.length + ' series' : '';
  }
  input.addEventListener('input', apply);
  document.querySelectorAll('a[data-filter]').forEach(function (a) {
    a.addEventListener('click', function () { input.value = a.getAttribute('data-filter'); apply(); });
  });
  if (input.value) apply();
)js";

}  // namespace

std::vector<std::string> series_filter_fields(const Table& t) {
  std::vector<std::string> out;
  for (const auto& c : t.columns)
    if (filtered(c)) out.push_back(c.name);
  return out;
}

std::string series_filter_help(const Table& t) {
  std::string fields;
  for (const auto& f : series_filter_fields(t)) fields += (fields.empty() ? "" : ", ") + f;
  return "Every word must match: a whole word of the row (hkl, not hkl2), field:value (verdict:pre-asymptotic, "
         "attention:yes), or field>number, <, >=, <=, = (failed>0). Fields: " + fields + ".";
}

std::string series_filter_script(const Table& t) {
  nlohmann::json fields = nlohmann::json::array(), data = nlohmann::json::array();
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < t.columns.size(); ++i)
    if (filtered(t.columns[i])) {
      kept.push_back(i);
      fields.push_back(t.columns[i].name);
    }
  for (const auto& row : t.rows) {
    nlohmann::json r = nlohmann::json::array();
    for (std::size_t i : kept) r.push_back(i < row.size() ? row[i].exact : std::string());
    data.push_back(std::move(r));
  }
  std::string args = fields.dump() + ", " + data.dump();
  // "</" would end the script element early.
  for (std::size_t at = args.find("</"); at != std::string::npos; at = args.find("</", at + 3)) args.insert(at + 1, "\\");
  return "<script>\n(function (fields, data) {" + std::string(kScript) + "})(" + args + ");\n</script>\n";
}

}  // namespace gridfree
