// SPDX-License-Identifier: GPL-3.0-or-later
// Sections of the report page and their table of contents (see html_toc.h).
#include "report/html_toc.h"

namespace gridfree {

namespace {

std::string without_tags(const std::string& html) {
  std::string out;
  bool in_tag = false;
  for (char ch : html) {
    if (ch == '<') in_tag = true;
    if (!in_tag) out += ch;
    if (ch == '>') in_tag = false;
  }
  return out;
}

}  // namespace

std::vector<HtmlSection> html_sections(const std::string& body) {
  std::vector<HtmlSection> out;
  for (std::size_t at = body.find("<h"); at != std::string::npos; at = body.find("<h", at + 1)) {
    if (at + 3 >= body.size() || (body[at + 2] != '2' && body[at + 2] != '3')) continue;
    const int level = body[at + 2] - '0';
    const std::size_t open_end = body.find('>', at);
    if (open_end == std::string::npos) break;
    const std::string open = body.substr(at, open_end - at);
    if (open.size() > 3 && open[3] != ' ') continue;  // <header>, <hr>…
    const std::size_t id_at = open.find(" id=\"");
    if (id_at == std::string::npos) continue;
    const std::size_t id_end = open.find('"', id_at + 5);
    if (id_end == std::string::npos) continue;
    const std::string close = "</h" + std::to_string(level) + ">";
    const std::size_t close_at = body.find(close, open_end);
    if (close_at == std::string::npos) break;
    out.push_back({level, open.substr(id_at + 5, id_end - id_at - 5),
                   without_tags(body.substr(open_end + 1, close_at - open_end - 1))});
  }
  return out;
}

std::string toc_list_html(const std::vector<HtmlSection>& sections) {
  std::string out = "<ul>\n";
  bool nested = false;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const HtmlSection& s = sections[i];
    if (s.level == 3 && !nested) {
      out += i == 0 ? "<li><ul>\n" : "<ul>\n";
      nested = true;
    } else if (s.level == 2 && nested) {
      out += "</li>\n</ul></li>\n";
      nested = false;
    } else if (i > 0) {
      out += "</li>\n";
    }
    out += "<li><a href=\"#" + s.id + "\">" + s.title_html + "</a>";
  }
  if (!sections.empty()) out += nested ? "</li>\n</ul></li>\n" : "</li>\n";
  out += "</ul>\n";
  return out;
}

}  // namespace gridfree
