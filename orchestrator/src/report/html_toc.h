// SPDX-License-Identifier: GPL-3.0-or-later
// The report page's table of contents, built from the page's own sections
// so that it cannot drift from them: every <h2 id="…"> and <h3 id="…"> of
// the body, in order, each h3 nested under the h2 before it. A heading
// without an id is not a section and is not listed.
#pragma once

#include <string>
#include <vector>

namespace gridfree {

struct HtmlSection {
  int level = 2;           // 2 or 3
  std::string id;          // as written in the id attribute (already escaped)
  std::string title_html;  // the heading's content, tags removed (already escaped)
};

std::vector<HtmlSection> html_sections(const std::string& body);

// <ul> of links to the sections; h3 sections in a nested <ul>.
std::string toc_list_html(const std::vector<HtmlSection>& sections);

}  // namespace gridfree
